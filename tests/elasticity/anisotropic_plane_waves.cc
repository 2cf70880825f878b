// Plane waves in anisotropic media, measured: a periodic box carries one
// standing plane wave u = p sin(k.x) (p an eigenvector of the Christoffel
// matrix of k), which the explicit central-difference scheme with the
// Gauss-Lobatto lumped mass and the matrix-free stiffness operator
// (Operators::ElasticOperator) advances in time. The wave's period is read
// from the zero crossings of its amplitude, and the speed omega/|k| is
// compared with the Christoffel equation's phase speed: qP, qS1 and qS2
// along several directions (axes, face and space diagonals), in a
// transversely isotropic medium with an oblique axis and in an orthotropic
// one with rotated axes, 3-D and 2-D (in-plane waves, axes chosen so that
// the model plane is a mirror plane), degree 2. Within 0.5 %.

#include <rupture/material/elastic_material.h>
#include <rupture/operators/elastic_operator.h>
#include <rupture/operators/element_frequency.h>

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace dealii;
using namespace rupture;

namespace
{
  using VectorType = LinearAlgebra::distributed::Vector<double>;

  template <int dim>
  class PlaneWave : public Function<dim>
  {
  public:
    PlaneWave(const Tensor<1, dim> &k, const Tensor<1, dim> &p)
      : Function<dim>(dim)
      , k(k)
      , p(p)
    {}

    double
    value(const Point<dim> &x, const unsigned int c) const override
    {
      return p[c] * std::sin(k * x);
    }

  private:
    const Tensor<1, dim> k, p;
  };



  template <int dim>
  void
  measure(const std::string &name, const std::string &entries)
  {
    ParameterHandler prm;
    Material::ElasticMaterials::declare_parameters(prm);
    prm.parse_input_from_string("subsection Material\n" + entries + "end\n");
    Material::ElasticMaterials materials;
    materials.parse_parameters(prm, dim);
    const Material::ElasticConstants &m = materials.get(0);

    const unsigned int degree = 2;
    const double       length = 1000;
    Triangulation<dim> tria;
    GridGenerator::hyper_cube(tria, 0, length, true);
    tria.refine_global(dim == 2 ? 4 : 3);
    hp::FECollection<dim> fe(FESystem<dim>(FE_Q<dim>(degree), dim));
    DoFHandler<dim>       dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    AffineConstraints<double> constraints;
    for (unsigned int d = 0; d < dim; ++d)
      DoFTools::make_periodicity_constraints(
        dof_handler, 2 * d, 2 * d + 1, d, constraints);
    constraints.close();

    Operators::ElasticOperator<dim> op;
    op.reinit(MappingQ1<dim>(), dof_handler, constraints, materials, degree);
    VectorType u, v, a, mass, mode;
    for (VectorType *x : {&u, &v, &a, &mass, &mode})
      op.initialize_dof_vector(*x);

    // The Gauss-Lobatto lumped mass, periodic DoFs summed on their
    // masters.
    {
      FEValues<dim>                        lumped(fe[0],
                           QGaussLobatto<dim>(degree + 1),
                           update_values | update_JxW_values);
      const unsigned int                   n = fe[0].n_dofs_per_cell();
      Vector<double>                       local(n);
      std::vector<types::global_dof_index> dofs(n);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          lumped.reinit(cell);
          local = 0;
          for (const unsigned int q : lumped.quadrature_point_indices())
            for (unsigned int i = 0; i < n; ++i)
              local(i) += m.density * std::pow(lumped.shape_value(i, q), 2) *
                          lumped.JxW(q);
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(local, dofs, mass);
        }
    }
    Operators::ElementFrequencies<dim> frequencies;
    const double                       dt =
      1. / frequencies.highest(dof_handler, materials, degree, MPI_COMM_WORLD);

    const std::vector<std::vector<int>> directions =
      (dim == 2) ?
        std::vector<std::vector<int>>{{1, 0}, {0, 1}, {1, 1}, {1, -1}} :
        std::vector<std::vector<int>>{
          {1, 0, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, -1}, {1, 1, 1}};
    const char *labels[3] = {"qP ", "qS1", "qS2"};
    double      worst     = 0;
    for (const auto &integers : directions)
      {
        Tensor<1, dim> k;
        Tensor<1, 3>   n;
        for (unsigned int d = 0; d < dim; ++d)
          k[d] = 2 * M_PI * integers[d] / length;
        for (unsigned int d = 0; d < dim; ++d)
          n[d] = k[d] / k.norm();
        // The polarisations: eigenvectors of Gamma (in 2-D of its in-plane
        // block), fastest first.
        const SymmetricTensor<2, 3> g3 =
          Material::christoffel_matrix(m.voigt, n);
        SymmetricTensor<2, dim> g;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            g[i][j] = g3[i][j];
        auto pairs = eigenvectors(g, SymmetricTensorEigenvectorMethod::jacobi);
        std::sort(pairs.begin(), pairs.end(), [](const auto &x, const auto &y) {
          return x.first > y.first;
        });
        for (unsigned int w = 0; w < dim; ++w)
          {
            const double expected = std::sqrt(pairs[w].first / m.density);
            VectorTools::interpolate(dof_handler,
                                     PlaneWave<dim>(k, pairs[w].second),
                                     mode);
            u = mode;
            v = 0;
            // A(t) = (u, M mode): cos(omega t) times A(0).
            const auto amplitude = [&]() {
              double sum = 0;
              for (unsigned int i = 0; i < u.size(); ++i)
                if (!constraints.is_constrained(i))
                  sum += u(i) * mass(i) * mode(i);
              return sum;
            };
            const auto acceleration = [&]() {
              op.vmult(a, u);
              for (unsigned int i = 0; i < a.size(); ++i)
                a(i) = constraints.is_constrained(i) ? 0. : -a(i) / mass(i);
            };
            acceleration();
            v.add(0.5 * dt, a); // v at dt/2
            double              previous = amplitude(), t = 0;
            std::vector<double> crossings;
            while (crossings.size() < 2)
              {
                u.add(dt, v);
                t += dt;
                acceleration();
                v.add(dt, a);
                const double now = amplitude();
                if ((previous > 0) != (now > 0))
                  crossings.push_back(t - dt * now / (now - previous));
                previous = now;
              }
            const double period   = 2 * (crossings[1] - crossings[0]);
            const double measured = 2 * M_PI / period / k.norm();
            const double error    = (measured - expected) / expected;
            worst                 = std::max(worst, std::abs(error));
            std::cout << "  " << name << " (";
            for (unsigned int d = 0; d < dim; ++d)
              std::cout << (d ? "," : "") << integers[d];
            std::cout << ") " << labels[w] << ": Christoffel " << std::fixed
                      << std::setprecision(1) << expected << " m/s, measured "
                      << measured << " m/s, " << std::setprecision(2)
                      << 100 * error << " %" << std::defaultfloat << std::endl;
          }
      }
    std::cout << dim << "-D " << name
              << ": every speed within 0.5 %: " << (worst < 5e-3 ? "yes" : "no")
              << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                ti =
    "  set Density = 2500\n"
    "  set Symmetry = transversely isotropic\n"
    "  set Stiffness = C11 = 6.0e10, C33 = 4.0e10, C13 = 1.5e10, C44 = "
    "1.2e10, C66 = 2.0e10\n";
  const std::string orthotropic =
    "  set Density = 2500\n"
    "  set Symmetry = orthotropic\n"
    "  set Stiffness = C11 = 7e10, C22 = 5e10, C33 = 4e10, C12 = 1.2e10, "
    "C13 = 1.1e10, C23 = 1.3e10, C44 = 1.4e10, C55 = 1.6e10, C66 = 1.9e10\n";
  measure<3>("TI, axis (1,2,3)", ti + "  set Material axes = 1, 2, 3\n");
  measure<3>("orthotropic, rotated",
             orthotropic + "  set Material axes = 2, 1, 2, -1, 2, 0\n");
  measure<2>("TI, axis (1,2,0)", ti + "  set Material axes = 1, 2, 0\n");
  measure<2>("orthotropic, rotated in the plane",
             orthotropic + "  set Material axes = 2, 1, 0, -1, 2, 0\n");
}
