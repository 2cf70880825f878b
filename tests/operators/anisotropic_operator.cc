// Anisotropic materials in the stiffness operators. (1) The matrix-free
// operator (Operators::ElasticOperator, its per-batch stiffness tensors)
// against the element matrices of Operators::local_elasticity_matrices
// assembled as C^T K C: 2-D (Q1 to Q3) and 3-D (Q1, Q2), a rotated transversely
// isotropic material beside an isotropic one, general hexahedra, hanging
// nodes and the fault's hp split. (2) The isotropic limit: isotropic
// constants given as a general tensor give the isotropic operator to
// round-off; the same comparison where the TI material's constants are
// functions of position (the operator's tensor per quadrature point,
// against element matrices with the tensor at each quadrature point).
// (3) The stable step's element eigenvalue of axis-aligned boxes
// (Operators::BoxElementFrequency) for an anisotropic material against the
// element matrices assembled with FEValues.

#include <rupture/material/elastic_material.h>
#include <rupture/operators/elastic_operator.h>
#include <rupture/operators/element_frequency.h>
#include <rupture/operators/local_elasticity.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>

using namespace dealii;

namespace
{
  const std::string ti_constants =
    "C11 = 6.0e10, C33 = 4.0e10, C13 = 1.5e10, C44 = 1.2e10, C66 = 2.0e10";

  rupture::Material::ElasticMaterials
  materials(const std::string &entries, const unsigned int dim)
  {
    ParameterHandler prm;
    rupture::Material::ElasticMaterials::declare_parameters(prm);
    prm.parse_input_from_string("subsection Material\n" + entries + "end\n");
    rupture::Material::ElasticMaterials m;
    m.parse_parameters(prm, dim);
    return m;
  }

  /// A TI material (axis in the model plane in 2-D, oblique in 3-D) and an
  /// isotropic one.
  rupture::Material::ElasticMaterials
  anisotropic(const unsigned int dim)
  {
    return materials("  set Names = shale, granite\n"
                     "  set Density = 2500, 2700\n"
                     "  set P-wave speed = 6000\n"
                     "  set S-wave speed = 3464\n"
                     "  set Symmetry = transversely isotropic, isotropic\n"
                     "  set Stiffness = " +
                       ti_constants +
                       ";\n"
                       "  set Material axes = " +
                       (dim == 2 ? "1, 2, 0" : "1, 2, 3") + ";\n",
                     dim);
  }

  template <int dim>
  struct Mesh
  {
    Triangulation<dim>        tria;
    hp::FECollection<dim>     fe;
    DoFHandler<dim>           dof_handler;
    AffineConstraints<double> constraints;

    Mesh(const unsigned int degree)
      : dof_handler(tria)
    {
      GridGenerator::hyper_cube(tria, 0, 1);
      tria.refine_global(2);
      for (auto &cell : tria.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          {
            Point<dim> &p        = cell->vertex(v);
            bool        interior = true;
            for (unsigned int d = 0; d < dim; ++d)
              interior = interior && p[d] > 1e-12 && p[d] < 1 - 1e-12;
            if (interior && std::abs(p[0] - 0.5) > 1e-12)
              p[1] += 0.03 * std::sin(7 * p[0] + 3 * p[dim - 1]);
          }
      for (auto &cell : tria.active_cell_iterators())
        if (cell->center()[0] < 0.25 && cell->center()[1] < 0.25)
          cell->set_refine_flag();
      tria.execute_coarsening_and_refinement();
      for (auto &cell : tria.active_cell_iterators())
        cell->set_material_id(cell->center()[1] > 0.5 ? 1 : 0);
      fe.push_back(
        FESystem<dim>(FE_Q<dim>(degree), dim, FE_Nothing<dim>(), dim));
      fe.push_back(
        FESystem<dim>(FE_Nothing<dim>(), dim, FE_Q<dim>(degree), dim));
      for (auto &cell : dof_handler.active_cell_iterators())
        cell->set_active_fe_index(cell->center()[0] > 0.5 ? 1 : 0);
      dof_handler.distribute_dofs(fe);
      DoFTools::make_hanging_node_constraints(dof_handler, constraints);
      constraints.close();
    }
  };

  /// The TI material of anisotropic() with constants that are functions
  /// of position (the tensor's shape varies), beside the isotropic one.
  rupture::Material::ElasticMaterials
  tensor_functions(const unsigned int dim)
  {
    return materials("  set Names = shale, granite\n"
                     "  set Density = 2500, 2700\n"
                     "  set P-wave speed = 6000\n"
                     "  set S-wave speed = 3464\n"
                     "  set Symmetry = transversely isotropic, isotropic\n"
                     "  set Stiffness = C11 = 6.0e10*(1 + 0.5*x*y), C33 = "
                     "4.0e10, C13 = 1.5e10 - 0.5e10*y, C44 = 1.2e10*(1 + "
                     "x), C66 = 2.0e10 + 1e10*y*y;\n"
                     "  set Material axes = " +
                       std::string(dim == 2 ? "1, 2, 0" : "1, 2, 3") + ";\n",
                     dim);
  }

  template <int dim>
  void
  check_operator(const unsigned int degree, const bool functions = false)
  {
    Mesh<dim>  mesh(degree);
    const auto m = functions ? tensor_functions(dim) : anisotropic(dim);

    DynamicSparsityPattern dsp(mesh.dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(mesh.dof_handler,
                                    dsp,
                                    mesh.constraints,
                                    false);
    SparsityPattern sparsity;
    const std::function<rupture::Material::ElasticConstants(const Point<dim> &)>
                      *local = nullptr;
    types::material_id id    = 0;
    const std::function<rupture::Material::ElasticConstants(const Point<dim> &)>
      at = [&](const Point<dim> &p) { return m.at(id, p); };
    if (functions)
      local = &at;
    sparsity.copy_from(dsp);
    SparseMatrix<double>                 k(sparsity);
    hp::FEValues<dim>                    hp_values(mesh.fe,
                                hp::QCollection<dim>(QGauss<dim>(degree + 1)),
                                update_values | update_gradients |
                                  update_JxW_values | update_quadrature_points);
    std::vector<types::global_dof_index> dofs;
    FullMatrix<double>                   ke;
    for (const auto &cell : mesh.dof_handler.active_cell_iterators())
      {
        hp_values.reinit(cell);
        const auto &fv = hp_values.get_present_fe_values();
        ke.reinit(fv.dofs_per_cell, fv.dofs_per_cell);
        id = cell->material_id();
        rupture::Operators::local_elasticity_matrices(
          fv,
          FEValuesExtractors::Vector(cell->active_fe_index() * dim),
          m.get(cell->material_id()),
          ke,
          nullptr,
          local);
        dofs.resize(fv.dofs_per_cell);
        cell->get_dof_indices(dofs);
        mesh.constraints.distribute_local_to_global(ke, dofs, k);
      }

    rupture::Operators::ElasticOperator<dim> op;
    op.reinit(MappingQ1<dim>(), mesh.dof_handler, mesh.constraints, m, degree);
    LinearAlgebra::distributed::Vector<double> x, y;
    op.initialize_dof_vector(x);
    op.initialize_dof_vector(y);
    Vector<double> xs(mesh.dof_handler.n_dofs()), ys(xs.size());
    for (unsigned int i = 0; i < xs.size(); ++i)
      xs(i) = std::sin(0.37 * i + 1.) * 1e-3;
    mesh.constraints.distribute(xs);
    for (unsigned int i = 0; i < xs.size(); ++i)
      x(i) = xs(i);
    k.vmult(ys, xs);
    op.vmult(y, x);
    double difference = 0, norm = 0;
    for (unsigned int i = 0; i < xs.size(); ++i)
      if (!mesh.constraints.is_constrained(i))
        {
          difference += std::pow(y(i) - ys(i), 2);
          norm += std::pow(ys(i), 2);
        }
    std::cout << dim << "-D Q" << degree << ": " << mesh.dof_handler.n_dofs()
              << " DoFs, matrix-free K x against the assembled element "
                 "matrices within 1e-12"
              << (functions ? " (constants as functions of position)" : "")
              << ": "
              << (norm > 0 && std::sqrt(difference / norm) < 1e-12 ? "yes" :
                                                                     "no")
              << std::endl;
    if (functions)
      return;

    // The isotropic limit: the isotropic material's constants as a
    // general tensor, in both materials.
    const double lambda = 2700. * (6000. * 6000 - 2 * 3464. * 3464),
                 mu     = 2700. * 3464. * 3464;
    std::ostringstream general;
    general << std::setprecision(17);
    for (unsigned int I = 0; I < 6; ++I)
      for (unsigned int J = I; J < 6; ++J)
        general << (I + J > 0 ? ", " : "") << "C" << I + 1 << J + 1 << " = "
                << ((I < 3 && J < 3) ? lambda + (I == J ? 2 * mu : 0.) :
                                       (I == J ? mu : 0.));
    const auto iso = materials("  set Names = a, b\n"
                               "  set Density = 2700\n"
                               "  set P-wave speed = 6000\n"
                               "  set S-wave speed = 3464\n",
                               dim);
    const auto gen = materials("  set Names = a, b\n"
                               "  set Density = 2700\n"
                               "  set Symmetry = general\n"
                               "  set Stiffness = " +
                                 general.str() + "\n",
                               dim);
    rupture::Operators::ElasticOperator<dim> op_iso, op_gen;
    op_iso.reinit(
      MappingQ1<dim>(), mesh.dof_handler, mesh.constraints, iso, degree);
    op_gen.reinit(
      MappingQ1<dim>(), mesh.dof_handler, mesh.constraints, gen, degree);
    LinearAlgebra::distributed::Vector<double> y_gen(y);
    op_iso.vmult(y, x);
    op_gen.vmult(y_gen, x);
    const double scale = y.l2_norm();
    y_gen -= y;
    std::cout << "   isotropic constants as a general tensor: relative "
                 "difference below 1e-13: "
              << (y_gen.l2_norm() < 1e-13 * scale ? "yes" : "no") << std::endl;
  }



  template <int dim>
  void
  check_frequency(const unsigned int degree)
  {
    const auto         m = anisotropic(dim);
    const auto        &c = m.get(0);
    Triangulation<dim> tria;
    Point<dim>         h;
    Tensor<1, dim>     edges;
    for (unsigned int d = 0; d < dim; ++d)
      edges[d] = h[d] = 1. + 0.7 * d;
    GridGenerator::hyper_rectangle(tria, Point<dim>(), h);
    const FESystem<dim> fe(FE_Q<dim>(degree), dim);
    DoFHandler<dim>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    FEValues<dim> values(fe,
                         QGauss<dim>(degree + 1),
                         update_values | update_gradients | update_JxW_values);
    FEValues<dim> lumped(fe,
                         QGaussLobatto<dim>(degree + 1),
                         update_values | update_JxW_values);
    values.reinit(dof_handler.begin_active());
    lumped.reinit(dof_handler.begin_active());
    const unsigned int               n = fe.n_dofs_per_cell();
    FullMatrix<double>               k(n, n);
    const FEValuesExtractors::Vector u(0);
    rupture::Operators::local_elasticity_matrices(values, u, c, k, nullptr);
    std::vector<double> mass(n, 0.);
    for (const unsigned int q : lumped.quadrature_point_indices())
      for (unsigned int i = 0; i < n; ++i)
        mass[i] +=
          c.density * lumped[u].value(i, q).norm_square() * lumped.JxW(q);
    LAPACKFullMatrix<double> a(n, n), b;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        a(i, j) = k(i, j) / std::sqrt(mass[i] * mass[j]);
    const double assembled =
      rupture::Operators::largest_eigenvalue_above(a, 0.);
    rupture::Operators::BoxElementFrequency<dim>(degree).scaled_matrix(edges,
                                                                       c,
                                                                       b);
    const double box = rupture::Operators::largest_eigenvalue_above(b, 0.);
    std::cout << dim << "-D Q" << degree
              << ": largest element eigenvalue of the box "
              << std::setprecision(8) << box << " (assembled " << assembled
              << "), equal to 1e-10: "
              << (std::abs(box - assembled) < 1e-10 * assembled ? "yes" : "no")
              << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // (Degree 3 in 2-D only: the 3-D assembly at degree 3 takes 40 s in a
  // Debug build.)
  for (const unsigned int degree : {1u, 2u, 3u})
    {
      check_operator<2>(degree);
      if (degree < 3)
        check_operator<3>(degree);
      check_operator<2>(degree, true);
      if (degree < 2)
        check_operator<3>(degree, true);
    }
  for (const unsigned int degree : {1u, 2u, 3u})
    {
      check_frequency<2>(degree);
      check_frequency<3>(degree);
    }
}
