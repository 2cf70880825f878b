// The matrix-free stiffness operator (Operators::ElasticOperator) against
// the assembled matrix C^T K C of the same constraints: 2-D and 3-D, Q1 and
// Q2, two materials, hanging nodes, on an affine mesh with one field and on
// a distorted mesh (general hexahedra) with the fault's hp split (one
// FESystem per side, FE_Nothing for the other) whose node pairs are welded
// on half of the interface. The products must agree to round-off, and the
// rows of constrained DoFs must be zero.

#include <rupture/material/elastic_material.h>
#include <rupture/operators/elastic_operator.h>

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
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <iostream>
#include <map>

using namespace dealii;

namespace
{
  template <int dim>
  void
  check(const unsigned int degree, const bool split)
  {
    Triangulation<dim> tria;
    GridGenerator::hyper_cube(tria, 0, 1);
    tria.refine_global(2);
    if (split)
      // General hexahedra: move the interior vertices off the grid, but
      // keep the interface x = 1/2 plane.
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
    // Hanging nodes away from the interface.
    for (auto &cell : tria.active_cell_iterators())
      if (cell->center()[0] < 0.25 && cell->center()[1] < 0.25)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();
    for (auto &cell : tria.active_cell_iterators())
      cell->set_material_id(cell->center()[1] > 0.5 ? 1 : 0);

    hp::FECollection<dim> fe;
    if (!split)
      fe.push_back(FESystem<dim>(FE_Q<dim>(degree), dim));
    else
      {
        fe.push_back(
          FESystem<dim>(FE_Q<dim>(degree), dim, FE_Nothing<dim>(), dim));
        fe.push_back(
          FESystem<dim>(FE_Nothing<dim>(), dim, FE_Q<dim>(degree), dim));
      }
    DoFHandler<dim> dof_handler(tria);
    if (split)
      for (auto &cell : dof_handler.active_cell_iterators())
        cell->set_active_fe_index(cell->center()[0] > 0.5 ? 1 : 0);
    dof_handler.distribute_dofs(fe);

    AffineConstraints<double> constraints;
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    if (split)
      {
        // Weld side 1 to side 0 on the interface above y = 1/2.
        std::map<types::global_dof_index, Point<dim>> points;
        DoFTools::map_dofs_to_support_points(
          hp::MappingCollection<dim>(MappingQ1<dim>()), dof_handler, points);
        std::vector<unsigned int>            component(dof_handler.n_dofs());
        std::vector<types::global_dof_index> dofs;
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            dofs.resize(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              component[dofs[i]] =
                cell->get_fe().system_to_component_index(i).first;
          }
        for (const auto &[i, p] : points)
          if (component[i] >= dim && std::abs(p[0] - 0.5) < 1e-12 &&
              p[1] > 0.5 - 1e-12)
            for (const auto &[j, q] : points)
              if (component[j] == component[i] - dim && p.distance(q) < 1e-12 &&
                  !constraints.is_constrained(i))
                {
                  constraints.add_line(i);
                  constraints.add_entry(i, j, 1.);
                }
      }
    constraints.close();

    ParameterHandler prm;
    rupture::Material::ElasticMaterials::declare_parameters(prm);
    prm.parse_input_from_string("subsection Material\n"
                                "  set Names = crust, mantle\n"
                                "  set Density = 2700, 3300\n"
                                "  set P-wave speed = 6000, 8000\n"
                                "  set S-wave speed = 3464, 4500\n"
                                "end\n");
    rupture::Material::ElasticMaterials materials;
    materials.parse_parameters(prm);

    // The assembled C^T K C.
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityPattern sparsity;
    sparsity.copy_from(dsp);
    SparseMatrix<double>                 k(sparsity);
    hp::FEValues<dim>                    hp_values(fe,
                                hp::QCollection<dim>(QGauss<dim>(degree + 1)),
                                update_gradients | update_JxW_values);
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        hp_values.reinit(cell);
        const auto                      &fv = hp_values.get_present_fe_values();
        const auto                      &m = materials.get(cell->material_id());
        const FEValuesExtractors::Vector u(cell->active_fe_index() * dim);
        const unsigned int               n = fv.dofs_per_cell;
        FullMatrix<double>               ke(n, n);
        for (const unsigned int q : fv.quadrature_point_indices())
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              ke(i, j) +=
                (m.lambda * fv[u].divergence(i, q) * fv[u].divergence(j, q) +
                 2 * m.mu *
                   (fv[u].symmetric_gradient(i, q) *
                    fv[u].symmetric_gradient(j, q))) *
                fv.JxW(q);
        dofs.resize(n);
        cell->get_dof_indices(dofs);
        constraints.distribute_local_to_global(ke, dofs, k);
      }

    rupture::Operators::ElasticOperator<dim> op;
    op.reinit(MappingQ1<dim>(), dof_handler, constraints, materials, degree);
    LinearAlgebra::distributed::Vector<double> x, y;
    op.initialize_dof_vector(x);
    op.initialize_dof_vector(y);
    Vector<double> xs(dof_handler.n_dofs()), ys(dof_handler.n_dofs());
    for (unsigned int i = 0; i < xs.size(); ++i)
      xs(i) = std::sin(0.37 * i + 1.) * 1e-3;
    constraints.distribute(xs);
    for (unsigned int i = 0; i < xs.size(); ++i)
      x(i) = xs(i);
    k.vmult(ys, xs);
    op.vmult(y, x);

    double difference = 0, norm = 0, constrained_rows = 0;
    for (unsigned int i = 0; i < xs.size(); ++i)
      if (constraints.is_constrained(i))
        constrained_rows = std::max(constrained_rows, std::abs(y(i)));
      else
        {
          difference += std::pow(y(i) - ys(i), 2);
          norm += std::pow(ys(i), 2);
        }
    std::cout << dim << "-D Q" << degree << (split ? " split" : " plain")
              << ": " << dof_handler.n_dofs() << " DoFs, "
              << constraints.n_constraints()
              << " constraints, |K x| > 0: " << (norm > 0 ? "yes" : "no")
              << ", relative difference < 1e-12: "
              << (std::sqrt(difference / norm) < 1e-12 ? "yes" : "no")
              << ", constrained rows zero: "
              << (constrained_rows == 0 ? "yes" : "no") << std::endl;
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const bool split : {false, true})
    for (const unsigned int degree : {1u, 2u})
      {
        check<2>(degree, split);
        check<3>(degree, split);
      }
}
