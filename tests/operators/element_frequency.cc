// The element eigenvalue problem of axis-aligned boxes assembled without
// quadrature (Operators::BoxElementFrequency), which sets the explicit
// scheme's stable step on box meshes: its largest eigenvalue must equal
// that of the element matrices assembled with FEValues on the same cell
// (consistent stiffness, Gauss-Lobatto lumped mass) for degrees 1 to 4,
// cubes and stretched boxes, 2-D and 3-D; Gershgorin's bound must lie above
// it; the eigenvalue must scale as 1/h^2; and only boxes are recognised.

#include <rupture/material/elastic_material.h>
#include <rupture/operators/element_frequency.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace rupture;

namespace
{
  Material::ElasticConstants
  material()
  {
    Material::ElasticConstants m;
    m.density = 2.7;
    m.lambda  = 2.0;
    m.mu      = 1.3;
    return m;
  }

  // The largest eigenvalue of K x = omega^2 M x on one box cell, assembled
  // the usual way: FEValues, Gauss rule of degree + 1 points, Gauss-Lobatto
  // lumped mass.
  template <int dim>
  double
  with_quadrature(const unsigned int degree, const Point<dim> &h)
  {
    Triangulation<dim> tria;
    GridGenerator::hyper_rectangle(tria, Point<dim>(), h);
    const FESystem<dim> fe(FE_Q<dim>(degree), dim);
    DoFHandler<dim>     dofs(tria);
    dofs.distribute_dofs(fe);
    const auto                       m = material();
    FEValues<dim>                    values(fe,
                         QGauss<dim>(degree + 1),
                         update_gradients | update_JxW_values);
    FEValues<dim>                    lumped(fe,
                         QGaussLobatto<dim>(degree + 1),
                         update_values | update_JxW_values);
    const auto                       cell = dofs.begin_active();
    const unsigned                   n    = fe.n_dofs_per_cell();
    const FEValuesExtractors::Vector u(0);
    values.reinit(cell);
    lumped.reinit(cell);
    FullMatrix<double>  k(n, n);
    std::vector<double> mass(n, 0.);
    for (const unsigned int q : values.quadrature_point_indices())
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          k(i, j) += (m.lambda * values[u].divergence(i, q) *
                        values[u].divergence(j, q) +
                      2 * m.mu *
                        (values[u].symmetric_gradient(i, q) *
                         values[u].symmetric_gradient(j, q))) *
                     values.JxW(q);
    for (const unsigned int q : lumped.quadrature_point_indices())
      for (unsigned int i = 0; i < n; ++i)
        mass[i] +=
          m.density * lumped[u].value(i, q).norm_square() * lumped.JxW(q);
    LAPACKFullMatrix<double> a(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        a(i, j) = k(i, j) / std::sqrt(mass[i] * mass[j]);
    return Operators::largest_eigenvalue_above(a, 0.);
  }

  template <int dim>
  void
  check(const unsigned int degree, const Point<dim> &h)
  {
    const Operators::BoxElementFrequency<dim> boxes(degree);
    LAPACKFullMatrix<double>                  a;
    boxes.scaled_matrix(h, material(), a);
    const double bound      = Operators::gershgorin_bound(a);
    const double largest    = Operators::largest_eigenvalue_above(a, 0.);
    const double quadrature = with_quadrature(degree, h);
    // Half the size: four times the eigenvalue.
    boxes.scaled_matrix(0.5 * h, material(), a);
    const double half = Operators::largest_eigenvalue_above(a, 0.);
    // A floor above the largest eigenvalue is returned as it is.
    boxes.scaled_matrix(h, material(), a);
    const double floor = Operators::largest_eigenvalue_above(a, 2 * largest);
    std::cout << dim << "-D degree " << degree << " box " << h
              << ": omega^2 = " << std::setprecision(8) << largest
              << ", same with quadrature: "
              << (std::abs(largest - quadrature) <= 1e-12 * quadrature ? "yes" :
                                                                         "NO")
              << ", Gershgorin / omega^2 = " << std::setprecision(4)
              << bound / largest << ", half size x " << std::setprecision(10)
              << half / largest
              << ", floor kept: " << (floor == 2 * largest ? "yes" : "NO")
              << std::endl;
  }

  template <int dim>
  std::string
  recognised(const std::array<Point<dim>, (1u << dim)> &vertices)
  {
    const auto         h = Operators::box_edges<dim>(vertices);
    std::ostringstream out;
    if (h)
      out << "box " << *h;
    else
      out << "not a box";
    return out.str();
  }

  template <int dim>
  void
  check_recognition()
  {
    std::array<Point<dim>, (1u << dim)> box;
    for (unsigned int v = 0; v < box.size(); ++v)
      for (unsigned int d = 0; d < dim; ++d)
        box[v][d] = 10. + d + ((v >> d) & 1u) * (1. + d);
    auto sheared = box;
    sheared[box.size() - 1][0] += 1e-6;
    auto mirrored = box;
    for (auto &p : mirrored)
      p[0] = -p[0];
    std::cout << dim << "-D: box: " << recognised<dim>(box)
              << "; sheared by 1e-6: " << recognised<dim>(sheared)
              << "; numbered against the axis: " << recognised<dim>(mirrored)
              << std::endl;
  }
} // namespace

int
main()
{
  check_recognition<2>();
  check_recognition<3>();
  for (unsigned int degree = 1; degree <= 4; ++degree)
    {
      check<2>(degree, Point<2>(1., 1.));
      check<2>(degree, Point<2>(0.3, 1.7));
    }
  check<3>(1, Point<3>(1., 1., 1.));
  for (unsigned int degree = 1; degree <= 3; ++degree)
    check<3>(degree, Point<3>(1., 2.5, 0.4));
  check<3>(4, Point<3>(0.5, 1., 2.));
}
