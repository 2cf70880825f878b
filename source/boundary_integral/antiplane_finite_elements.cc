// The fault's stiffness from a finite-element model of the antiplane body:
// one factorisation, one solve per fault node.

#include <rupture/boundary_integral/antiplane_finite_elements.h>
#include <rupture/boundary_integral/finite_element_grid.h>
#include <rupture/boundary_integral/text.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace rupture
{
  namespace BoundaryIntegral
  {
    using namespace dealii;

    AntiplaneFiniteElements::AntiplaneFiniteElements(
      const Settings &settings,
      const MPI_Comm  communicator)
      : settings(settings)
    {
      const double W = settings.fault_depth, p = settings.degree;
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
      const double C55 = settings.shear_modulus,
                   C44 = (settings.vertical_shear_modulus > 0) ?
                           settings.vertical_shear_modulus :
                           settings.shear_modulus;
      AssertThrow(fault_cells * p <= 20000,
                  ExcMessage("<Boundary integral/Element size> of " +
                             number(settings.node_spacing) + " m puts " +
                             number(fault_cells * p) +
                             " nodes on the fault; the dense stiffness "
                             "allows at most 20000 (3.2 GB). Give a larger "
                             "element size."));

      // The mesh: the fault's cells down to W, then growing; across, growing
      // from the fault.
      const double        h = W / fault_cells;
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
      double width = 0, height = 0;
      for (const double a : across)
        width += a;
      for (const double d : down)
        height += d;
      std::reverse(down.begin(), down.end()); // (From the bottom up.)
      Triangulation<2> mesh;
      GridGenerator::subdivided_hyper_rectangle(
        mesh, {across, down}, Point<2>(0, -height), Point<2>(width, 0), true);
      // Boundary ids: 0 the fault (x = 0), 1 the far side, 2 the bottom,
      // 3 the free surface.

      const FE_Q<2> fe(static_cast<unsigned int>(settings.degree));
      DoFHandler<2> dofs(mesh);
      dofs.distribute_dofs(fe);
      n_cells = mesh.n_active_cells();
      n_dofs  = dofs.n_dofs();
      std::vector<Point<2>> support(n_dofs);
      DoFTools::map_dofs_to_support_points(MappingQ1<2>(), dofs, support);

      // The held unknowns, and the fault's nodes above W by depth.
      std::vector<bool>                         held(n_dofs, false);
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
      std::vector<types::global_dof_index> fault_dof;
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
      SparsityPattern sparsity;
      sparsity.copy_from(pattern);
      SparseMatrix<double> A(sparsity);
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
      SparseMatrix<double> reduced(sparsity);
      reduced.copy_from(A);
      for (types::global_dof_index i = 0; i < n_dofs; ++i)
        for (auto entry = reduced.begin(i); entry != reduced.end(i); ++entry)
          if ((held[i] || held[entry->column()]) && entry->column() != i)
            entry->value() = 0;
      SparseDirectUMFPACK solver;
      solver.factorize(reduced);

      // This rank's columns.
      const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(
                           communicator),
                         ranks = dealii::Utilities::MPI::n_mpi_processes(
                           communicator);
      const unsigned int first = std::size_t(N) * rank / ranks,
                         last  = std::size_t(N) * (rank + 1) / ranks;
      std::vector<double> columns;
      columns.reserve(std::size_t(last - first) * N);
      // The right-hand side -A u_j of u_j = 1/2 at node j is nonzero only
      // in column j of A (its row, A being symmetric), and only the
      // fault's rows of A u are needed: no product with the whole matrix.
      Vector<double> u(n_dofs);
      for (unsigned int j = first; j < last; ++j)
        {
          const types::global_dof_index dof = fault_dof[j];
          u                                 = 0;
          for (auto entry = A.begin(dof); entry != A.end(dof); ++entry)
            if (!held[entry->column()])
              u[entry->column()] = -0.5 * entry->value();
          solver.solve(u);
          u[dof] = 0.5;
          for (unsigned int i = 0; i < N; ++i)
            {
              double reaction = 0;
              for (auto entry = A.begin(fault_dof[i]);
                   entry != A.end(fault_dof[i]);
                   ++entry)
                reaction += entry->value() * u[entry->column()];
              columns.push_back(-reaction / tributary[i]);
            }
        }

      // All columns on every rank, stored by rows.
      const std::vector<std::vector<double>> parts =
        dealii::Utilities::MPI::all_gather(communicator, columns);
      matrix.assign(std::size_t(N) * N, 0.);
      unsigned int j = 0;
      for (const auto &part : parts)
        for (std::size_t c = 0; c < part.size() / N; ++c, ++j)
          for (unsigned int i = 0; i < N; ++i)
            matrix[std::size_t(i) * N + j] = part[c * N + i];
    }



    std::vector<double>
    AntiplaneFiniteElements::rows(const unsigned int begin,
                                  const unsigned int end) const
    {
      const std::size_t N = size();
      return std::vector<double>(matrix.begin() + begin * N,
                                 matrix.begin() + end * N);
    }



    std::string
    AntiplaneFiniteElements::description() const
    {
      std::ostringstream s;
      s << std::setprecision(6) << "antiplane finite elements (Q"
        << settings.degree << ", " << n_cells << " cells, " << n_dofs
        << " unknowns on a " << settings.domain_size / 1e3 << " km box), "
        << size() << " fault nodes " << settings.fault_depth / size()
        << " m apart" << (settings.degree > 2 ? " on average" : "")
        << " down to " << settings.fault_depth / 1e3 << " km";
      return s.str();
    }
  } // namespace BoundaryIntegral
} // namespace rupture
