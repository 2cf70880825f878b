// The meshed antiplane body beside the fault: grid, matrix, held unknowns,
// the fault's nodes and one factorisation.

#include <rupture/boundary_integral/antiplane_body.h>
#include <rupture/boundary_integral/finite_element_grid.h>
#include <rupture/boundary_integral/text.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace rupture
{
  namespace BoundaryIntegral
  {
    using namespace dealii;

    AntiplaneBody::AntiplaneBody(
      const AntiplaneFiniteElements::Settings &settings)
      : settings(settings)
      , fe(static_cast<unsigned int>(std::clamp(settings.degree, 1, 4)))
    {
      const double W           = settings.fault_depth;
      const double fault_cells = FiniteElementGrid::check(W,
                                                          settings.degree,
                                                          settings.node_spacing,
                                                          settings.domain_size,
                                                          settings.growth);
      AssertThrow(std::isfinite(settings.shear_modulus) &&
                    settings.shear_modulus > 0 &&
                    std::isfinite(settings.vertical_shear_modulus) &&
                    settings.vertical_shear_modulus >= 0,
                  ExcMessage("The shear modulus (density times the S-wave "
                             "speed squared, <Material>) must be > 0."));
      C55 = settings.shear_modulus;
      C44 = (settings.vertical_shear_modulus > 0) ?
              settings.vertical_shear_modulus :
              settings.shear_modulus;
      AssertThrow(fault_cells * settings.degree <= 20000,
                  ExcMessage("<Boundary integral/Element size> of " +
                             number(settings.node_spacing) + " m puts " +
                             number(fault_cells * settings.degree) +
                             " nodes on the fault; the dense stiffness "
                             "allows at most 20000 (3.2 GB). Give a larger "
                             "element size."));

      // The mesh: the fault's cells down to W, then growing; across, growing
      // from the fault.
      h = W / fault_cells;
      std::vector<double> across =
        FiniteElementGrid::graded(h, settings.growth, settings.domain_size);
      std::vector<double>       down(static_cast<std::size_t>(fault_cells), h);
      const std::vector<double> below =
        FiniteElementGrid::graded(h * settings.growth,
                                  settings.growth,
                                  std::max(settings.domain_size - W, h));
      down.insert(down.end(), below.begin(), below.end());
      AssertThrow(double(across.size()) * down.size() <= 4e6,
                  ExcMessage("<Boundary integral/Cell growth factor> of " +
                             number(settings.growth) + " makes " +
                             number(double(across.size()) * down.size()) +
                             " cells; at most 4e6 are allowed. Give a "
                             "larger factor (or a larger <Element size>)."));
      for (const double a : across)
        width += a;
      for (const double d : down)
        height += d;
      std::reverse(down.begin(), down.end()); // (From the bottom up.)
      GridGenerator::subdivided_hyper_rectangle(
        mesh, {across, down}, Point<2>(0, -height), Point<2>(width, 0), true);
      // Boundary ids: 0 the fault (x = 0), 1 the far side, 2 the bottom,
      // 3 the free surface.

      dofs.reinit(mesh);
      dofs.distribute_dofs(fe);
      const types::global_dof_index n_dofs = dofs.n_dofs();
      support.resize(n_dofs);
      DoFTools::map_dofs_to_support_points(MappingQ1<2>(), dofs, support);

      // The held unknowns, and the fault's nodes above W by depth.
      held.assign(n_dofs, false);
      const double                              tolerance = 1e-9 * h;
      std::map<double, types::global_dof_index> fault_nodes;
      for (types::global_dof_index i = 0; i < n_dofs; ++i)
        {
          const Point<2> &x = support[i];
          if (x[0] < tolerance)
            {
              held[i] = true;
              if (-x[1] < W - tolerance)
                fault_nodes[-x[1]] = i;
            }
          else if (x[0] > width - tolerance || x[1] < -height + tolerance)
            held[i] = true;
        }
      std::vector<unsigned int> index_of(n_dofs, numbers::invalid_unsigned_int);
      for (const auto &[depth, dof] : fault_nodes)
        {
          index_of[dof] = fault_dof.size();
          fault_dof.push_back(dof);
          node_depths.push_back(depth);
        }
      const unsigned int N = fault_dof.size();

      // The stiffness matrix of the body, and the tributary lengths.
      DynamicSparsityPattern pattern(n_dofs);
      DoFTools::make_sparsity_pattern(dofs, pattern);
      sparsity.copy_from(pattern);
      A.reinit(sparsity);
      tributary.assign(N, 0.);
      {
        const QGauss<2>    quadrature(settings.degree + 1);
        const QGauss<1>    face_quadrature(settings.degree + 1);
        FEValues<2>        values(fe,
                           quadrature,
                           update_gradients | update_JxW_values);
        FEFaceValues<2>    face_values(fe,
                                    face_quadrature,
                                    update_values | update_JxW_values);
        const unsigned int n = fe.n_dofs_per_cell();
        FullMatrix<double> local(n, n);
        std::vector<types::global_dof_index> indices(n);
        for (const auto &cell : dofs.active_cell_iterators())
          {
            values.reinit(cell);
            local = 0;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              for (unsigned int a = 0; a < n; ++a)
                for (unsigned int b = 0; b < n; ++b)
                  local(a, b) += (C55 * values.shape_grad(a, q)[0] *
                                    values.shape_grad(b, q)[0] +
                                  C44 * values.shape_grad(a, q)[1] *
                                    values.shape_grad(b, q)[1]) *
                                 values.JxW(q);
            cell->get_dof_indices(indices);
            A.add(indices, local);
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  cell->face(f)->boundary_id() == 0)
                {
                  face_values.reinit(cell, f);
                  for (unsigned int a = 0; a < n; ++a)
                    if (index_of[indices[a]] != numbers::invalid_unsigned_int)
                      for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                        tributary[index_of[indices[a]]] +=
                          face_values.shape_value(a, q) * face_values.JxW(q);
                }
          }
      }

      // The matrix with the held unknowns' rows and columns cut to the
      // diagonal, factorised once.
      reduced.reinit(sparsity);
      reduced.copy_from(A);
      for (types::global_dof_index i = 0; i < n_dofs; ++i)
        for (auto entry = reduced.begin(i); entry != reduced.end(i); ++entry)
          if ((held[i] || held[entry->column()]) && entry->column() != i)
            entry->value() = 0;
      solver.factorize(reduced);
    }



    void
    AntiplaneBody::solve_static(Vector<double> &u) const
    {
      // The right-hand side -A u_held at the free unknowns; the held rows
      // of the reduced matrix are their diagonal entries alone.
      Vector<double> rhs(u.size());
      for (types::global_dof_index i = 0; i < u.size(); ++i)
        if (!held[i])
          for (auto entry = A.begin(i); entry != A.end(i); ++entry)
            if (held[entry->column()])
              rhs[i] -= entry->value() * u[entry->column()];
      for (types::global_dof_index i = 0; i < u.size(); ++i)
        if (held[i])
          rhs[i] = reduced.diag_element(i) * u[i];
      solver.solve(rhs);
      u = rhs;
    }
  } // namespace BoundaryIntegral
} // namespace rupture
