// The fault's stiffness from a finite-element model of a plane-strain
// body with a dipping fault: one factorisation, one solve per node pair.

#include <rupture/boundary_integral/finite_element_grid.h>
#include <rupture/boundary_integral/plane_strain_finite_elements.h>
#include <rupture/boundary_integral/text.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace rupture
{
  namespace BoundaryIntegral
  {
    using namespace dealii;

    namespace
    {
      using Settings = PlaneStrainFiniteElements::Settings;

      /// Partial sums of @p sizes from @p start: the grid lines.
      std::vector<double>
      lines(const double start, const std::vector<double> &sizes)
      {
        std::vector<double> x(1, start);
        for (const double s : sizes)
          x.push_back(x.back() + s);
        return x;
      }

      /// A fault node of one side: its distance down the fault and its two
      /// unknowns (x and y components).
      struct SideNode
      {
        double                                 distance;
        std::array<types::global_dof_index, 2> dof;
      };

      /// The fault's nodes above W of each side (0 the footwall, 1 the
      /// hanging wall), by their distance down the fault.
      using Sides = std::array<std::vector<SideNode>, 2>;

      /// The settings' checks that need no mesh; the number of cells along
      /// the fault above W.
      double
      checked_fault_cells(const Settings &settings)
      {
        const double W = settings.fault_extent, p = settings.degree;
        const double fault_cells =
          FiniteElementGrid::check(W,
                                   settings.degree,
                                   settings.node_spacing,
                                   settings.domain_size,
                                   settings.growth);
        AssertThrow(settings.dip >= 10 && settings.dip <= 90,
                    ExcMessage("<Boundary integral/Dip> is " +
                               number(settings.dip) +
                               ", but it must lie between 10 and 90 (degrees "
                               "from the horizontal)."));
        const double mu = settings.shear_modulus, lambda = settings.lambda;
        AssertThrow(std::isfinite(mu) && mu > 0 && std::isfinite(lambda) &&
                      3 * lambda + 2 * mu > 0,
                    ExcMessage("The plane-strain body needs a shear modulus "
                               "> 0 and Poisson's ratio in (-1, 0.5) "
                               "(<Material>: density, S- and P-wave speeds)."));
        AssertThrow(fault_cells * p <= 10000,
                    ExcMessage("<Boundary integral/Element size> of " +
                               number(settings.node_spacing) + " m puts " +
                               number(fault_cells * p) +
                               " node pairs on the fault; the plane-strain "
                               "finite elements allow at most 10000. Give a "
                               "larger element size."));
        return fault_cells;
      }

      /**
       * The grid in (xi, z): xi the horizontal distance from the fault at
       * the depth z; x = xi + z cot(delta), y = -z.
       */
      struct Grid
      {
        Grid(const Settings &settings, const double fault_cells)
          : sine(std::sin(settings.dip * M_PI / 180))
          , cotangent(
              settings.dip == 90 ? 0. : 1 / std::tan(settings.dip * M_PI / 180))
          , h(settings.fault_extent / fault_cells)
          , tip(static_cast<unsigned int>(fault_cells))
        {
          const std::vector<double> across =
            FiniteElementGrid::graded(h, settings.growth, settings.domain_size);
          std::vector<double> down(static_cast<std::size_t>(fault_cells),
                                   h * sine);
          {
            const std::vector<double> below = FiniteElementGrid::graded(
              h * sine * settings.growth,
              settings.growth,
              std::max(settings.domain_size - settings.fault_extent * sine, h));
            down.insert(down.end(), below.begin(), below.end());
          }
          const double n_grid = 2. * across.size() * down.size();
          AssertThrow(n_grid <= 2e6,
                      ExcMessage("<Boundary integral/Cell growth factor> of " +
                                 number(settings.growth) + " makes " +
                                 number(n_grid) +
                                 " cells; at most 2e6 are allowed. Give a "
                                 "larger factor (or a larger <Element "
                                 "size>)."));
          xi = lines(0, across);
          {
            std::vector<double> left = xi;
            for (double &v : left)
              v = -v;
            std::reverse(left.begin(), left.end());
            left.pop_back(); // (0 once.)
            xi.insert(xi.begin(), left.begin(), left.end());
          }
          z     = lines(0, down);
          nx    = xi.size() - 1;
          nz    = z.size() - 1;
          fault = across.size();
        }

        /// xi of a point (x, y).
        double
        xi_of(const Point<2> &x) const
        {
          return x[0] + x[1] * cotangent;
        }

        double sine, cotangent;
        /// The cells' length along the dip above W (m).
        double              h;
        std::vector<double> xi, z;
        unsigned int        nx = 0, nz = 0;
        /// xi[fault] = 0; z[tip] = W sin(delta), the fault's lower end.
        unsigned int fault = 0, tip;
      };

      /// The mesh of @p grid, the fault's vertices above W doubled.
      void
      make_mesh(const Grid &grid, Triangulation<2> &mesh)
      {
        const unsigned int nx = grid.nx, nz = grid.nz, fault = grid.fault,
                           tip = grid.tip;
        const auto vertex = [&](const unsigned int i, const unsigned int k) {
          return k * (nx + 1) + i;
        };
        std::vector<Point<2>> vertices;
        for (unsigned int k = 0; k <= nz; ++k)
          for (unsigned int i = 0; i <= nx; ++i)
            vertices.emplace_back(grid.xi[i] + grid.z[k] * grid.cotangent,
                                  -grid.z[k]);
        // The hanging wall's copies of the fault's vertices above W.
        const unsigned int copies = vertices.size();
        for (unsigned int k = 0; k < tip; ++k)
          vertices.push_back(vertices[vertex(fault, k)]);
        std::vector<CellData<2>> cells;
        for (unsigned int k = 0; k < nz; ++k)
          for (unsigned int i = 0; i < nx; ++i)
            {
              CellData<2> c;
              // (deal.II's order: lower left, lower right, upper left, upper
              // right; the deeper line k + 1 is the lower one.)
              const auto v = [&](const unsigned int ii, const unsigned int kk) {
                return (ii == fault && i == fault && kk < tip) ? copies + kk :
                                                                 vertex(ii, kk);
              };
              c.vertices[0] = v(i, k + 1);
              c.vertices[1] = v(i + 1, k + 1);
              c.vertices[2] = v(i, k);
              c.vertices[3] = v(i + 1, k);
              cells.push_back(c);
            }
        mesh.create_triangulation(vertices, cells, SubCellData());
      }

      /// The fault's nodes above W on each side, from the faces on the
      /// fault (@p W: the fault's extent along the dip).
      Sides
      fault_nodes(const DoFHandler<2>         &dofs,
                  const std::vector<Point<2>> &support,
                  const Grid                  &grid,
                  const double                 W,
                  const double                 tolerance)
      {
        const FiniteElement<2>              &fe = dofs.get_fe();
        Sides                                side;
        const double                         z_tip = W * grid.sine;
        std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
        for (const auto &cell : dofs.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const Point<2> c = cell->face(f)->center();
                if (std::abs(grid.xi_of(c)) > tolerance || -c[1] > z_tip)
                  continue;
                const unsigned int s = grid.xi_of(cell->center()) > 0 ? 1 : 0;
                cell->face(f)->get_dof_indices(face_dofs);
                for (unsigned int a = 0; a < face_dofs.size(); ++a)
                  {
                    const unsigned int component =
                      fe.face_system_to_component_index(a).first;
                    if (component != 0)
                      continue;
                    const double depth = -support[face_dofs[a]][1];
                    if (depth > z_tip - tolerance)
                      continue; // (W: the tip, shared by both sides.)
                    // (The y component: the next unknown of the same
                    // support point on the face.)
                    types::global_dof_index other = numbers::invalid_dof_index;
                    for (unsigned int b = 0; b < face_dofs.size(); ++b)
                      if (fe.face_system_to_component_index(b).first == 1 &&
                          support[face_dofs[b]].distance(
                            support[face_dofs[a]]) < tolerance)
                        other = face_dofs[b];
                    AssertThrow(other != numbers::invalid_dof_index,
                                ExcInternalError());
                    side[s].push_back(
                      {depth / grid.sine, {{face_dofs[a], other}}});
                  }
              }
        for (auto &nodes : side)
          {
            std::sort(nodes.begin(),
                      nodes.end(),
                      [](const SideNode &a, const SideNode &b) {
                        return a.distance < b.distance;
                      });
            nodes.erase(std::unique(nodes.begin(),
                                    nodes.end(),
                                    [](const SideNode &a, const SideNode &b) {
                                      return a.dof == b.dof;
                                    }),
                        nodes.end());
          }
        AssertThrow(side[0].size() == side[1].size() && !side[0].empty(),
                    ExcInternalError());
        for (unsigned int i = 0; i < side[0].size(); ++i)
          AssertThrow(std::abs(side[0][i].distance - side[1][i].distance) <
                        tolerance,
                      ExcInternalError());
        return side;
      }

      /// The numbers of the reduced system's unknowns: every unknown that
      /// is not @p held, the hanging wall's fault unknowns tied to the
      /// footwall's (invalid for the held ones); and their count.
      std::pair<std::vector<types::global_dof_index>, types::global_dof_index>
      reduced_numbers(const std::vector<bool> &held, const Sides &side)
      {
        const types::global_dof_index        n_dofs = held.size();
        std::vector<types::global_dof_index> reduced(
          n_dofs, numbers::invalid_dof_index);
        std::vector<types::global_dof_index> partner(
          n_dofs, numbers::invalid_dof_index);
        for (unsigned int i = 0; i < side[0].size(); ++i)
          for (unsigned int c = 0; c < 2; ++c)
            partner[side[1][i].dof[c]] = side[0][i].dof[c];
        types::global_dof_index n_reduced = 0;
        for (types::global_dof_index i = 0; i < n_dofs; ++i)
          if (!held[i] && partner[i] == numbers::invalid_dof_index)
            reduced[i] = n_reduced++;
        for (types::global_dof_index i = 0; i < n_dofs; ++i)
          if (partner[i] != numbers::invalid_dof_index)
            reduced[i] = reduced[partner[i]];
        return {reduced, n_reduced};
      }

      /**
       * The stiffness matrix of the body @p A, the reduced one @p R (their
       * sparsity patterns made here), and the footwall's fault nodes'
       * tributary lengths.
       */
      std::vector<double>
      assemble(const Settings                             &settings,
               const DoFHandler<2>                        &dofs,
               const Grid                                 &grid,
               const Sides                                &side,
               const std::vector<types::global_dof_index> &reduced,
               const types::global_dof_index               n_reduced,
               const double                                tolerance,
               SparsityPattern                            &full_sparsity,
               SparsityPattern                            &reduced_sparsity,
               SparseMatrix<double>                       &A,
               SparseMatrix<double>                       &R)
      {
        const FiniteElement<2>       &fe     = dofs.get_fe();
        const types::global_dof_index n_dofs = dofs.n_dofs();
        const unsigned int            N      = side[0].size();
        const double mu = settings.shear_modulus, lambda = settings.lambda;
        std::vector<unsigned int> node_of(n_dofs,
                                          numbers::invalid_unsigned_int);
        for (unsigned int i = 0; i < N; ++i)
          node_of[side[0][i].dof[0]] = i;
        DynamicSparsityPattern full_pattern(n_dofs), reduced_pattern(n_reduced);
        DoFTools::make_sparsity_pattern(dofs, full_pattern);
        const unsigned int                   n = fe.n_dofs_per_cell();
        std::vector<types::global_dof_index> indices(n);
        for (const auto &cell : dofs.active_cell_iterators())
          {
            cell->get_dof_indices(indices);
            for (const auto a : indices)
              if (reduced[a] != numbers::invalid_dof_index)
                for (const auto b : indices)
                  if (reduced[b] != numbers::invalid_dof_index)
                    reduced_pattern.add(reduced[a], reduced[b]);
          }
        full_sparsity.copy_from(full_pattern);
        reduced_sparsity.copy_from(reduced_pattern);
        A.reinit(full_sparsity);
        R.reinit(reduced_sparsity);
        std::vector<double>                tributary(N, 0.);
        const QGauss<2>                    quadrature(settings.degree + 1);
        const QGauss<1>                    face_quadrature(settings.degree + 1);
        FEValues<2>                        values(fe,
                           quadrature,
                           update_gradients | update_JxW_values);
        FEFaceValues<2>                    face_values(fe,
                                    face_quadrature,
                                    update_values | update_JxW_values);
        const FEValuesExtractors::Vector   u(0);
        FullMatrix<double>                 local(n, n);
        std::vector<SymmetricTensor<2, 2>> strain(n);
        std::vector<double>                divergence(n);
        for (const auto &cell : dofs.active_cell_iterators())
          {
            values.reinit(cell);
            local = 0;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                for (unsigned int a = 0; a < n; ++a)
                  {
                    strain[a]     = values[u].symmetric_gradient(a, q);
                    divergence[a] = values[u].divergence(a, q);
                  }
                for (unsigned int a = 0; a < n; ++a)
                  for (unsigned int b = 0; b < n; ++b)
                    local(a, b) += (lambda * divergence[a] * divergence[b] +
                                    2 * mu * (strain[a] * strain[b])) *
                                   values.JxW(q);
              }
            cell->get_dof_indices(indices);
            A.add(indices, local);
            for (unsigned int a = 0; a < n; ++a)
              if (reduced[indices[a]] != numbers::invalid_dof_index)
                for (unsigned int b = 0; b < n; ++b)
                  if (reduced[indices[b]] != numbers::invalid_dof_index)
                    R.add(reduced[indices[a]],
                          reduced[indices[b]],
                          local(a, b));
            if (grid.xi_of(cell->center()) > 0)
              continue;
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  std::abs(grid.xi_of(cell->face(f)->center())) < tolerance)
                {
                  face_values.reinit(cell, f);
                  for (unsigned int a = 0; a < n; ++a)
                    if (node_of[indices[a]] != numbers::invalid_unsigned_int)
                      for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                        tributary[node_of[indices[a]]] +=
                          face_values.shape_value(a, q) * face_values.JxW(q);
                }
          }
        return tributary;
      }

      /// A surface point: the unknowns of the cell that holds it and their
      /// shape values there.
      struct Probe
      {
        std::vector<types::global_dof_index> dofs;
        std::vector<unsigned int>            components;
        std::vector<double>                  values;
      };

      /// The probes of the surface points of @p settings (the footwall's
      /// cell at the fault's trace x = 0), and in @p side_of_point +1 for a
      /// point on the hanging wall, -1 on the footwall.
      std::vector<Probe>
      surface_probes(const Settings      &settings,
                     const DoFHandler<2> &dofs,
                     const Grid          &grid,
                     const double         tolerance,
                     std::vector<double> &side_of_point)
      {
        const FiniteElement<2>              &fe = dofs.get_fe();
        const unsigned int                   n  = fe.n_dofs_per_cell();
        std::vector<types::global_dof_index> indices(n);
        std::vector<Probe>                   probes;
        const MappingQ1<2>                   mapping;
        const double reach_left = grid.xi.front(), reach_right = grid.xi.back();
        for (const double x : settings.surface_points)
          {
            AssertThrow(std::isfinite(x) && x > reach_left && x < reach_right,
                        ExcMessage("<Boundary integral/Surface stations>: x "
                                   "= " +
                                   number(x) +
                                   " m is not on the meshed surface, which "
                                   "reaches from " +
                                   number(reach_left) + " to " +
                                   number(reach_right) + " m."));
            const bool hanging = x > tolerance;
            side_of_point.push_back(hanging ? 1. : -1.);
            Probe probe;
            for (const auto &cell : dofs.active_cell_iterators())
              {
                // (The top row of cells: vertices 2 and 3 on the surface.)
                if (std::abs(cell->vertex(2)[1]) > tolerance ||
                    (grid.xi_of(cell->center()) > 0) != hanging ||
                    x < cell->vertex(2)[0] - tolerance ||
                    x > cell->vertex(3)[0] + tolerance)
                  continue;
                Point<2> unit =
                  mapping.transform_real_to_unit_cell(cell, Point<2>(x, 0.));
                for (unsigned int c = 0; c < 2; ++c)
                  unit[c] = std::clamp(unit[c], 0., 1.);
                FEValues<2> at_point(mapping,
                                     fe,
                                     Quadrature<2>(std::vector<Point<2>>{unit},
                                                   std::vector<double>{1.}),
                                     update_values);
                at_point.reinit(cell);
                cell->get_dof_indices(indices);
                for (unsigned int a = 0; a < n; ++a)
                  {
                    probe.dofs.push_back(indices[a]);
                    probe.components.push_back(
                      fe.system_to_component_index(a).first);
                    probe.values.push_back(at_point.shape_value(a, 0));
                  }
                break;
              }
            AssertThrow(!probe.dofs.empty(), ExcInternalError());
            probes.push_back(probe);
          }
        return probes;
      }
    } // namespace



    PlaneStrainFiniteElements::PlaneStrainFiniteElements(
      const Settings &settings,
      const MPI_Comm  communicator)
      : settings(settings)
    {
      const Grid       grid(settings, checked_fault_cells(settings));
      Triangulation<2> mesh;
      make_mesh(grid, mesh);

      const FESystem<2> fe(FE_Q<2>(static_cast<unsigned int>(settings.degree)),
                           2);
      DoFHandler<2>     dofs(mesh);
      dofs.distribute_dofs(fe);
      n_cells = mesh.n_active_cells();
      n_dofs  = dofs.n_dofs();
      std::vector<Point<2>> support(n_dofs);
      DoFTools::map_dofs_to_support_points(MappingQ1<2>(), dofs, support);

      // Where a point is, in (xi, z), to a tolerance.
      const double tolerance = 1e-6 * grid.h;
      const double left_end = grid.xi.front(), right_end = grid.xi.back(),
                   bottom = grid.z.back();

      // The held unknowns: the far sides and the bottom.
      std::vector<bool> held(n_dofs, false);
      for (types::global_dof_index i = 0; i < n_dofs; ++i)
        {
          const double g = grid.xi_of(support[i]);
          held[i] = g < left_end + tolerance || g > right_end - tolerance ||
                    -support[i][1] > bottom - tolerance;
        }

      const Sides side =
        fault_nodes(dofs, support, grid, settings.fault_extent, tolerance);
      const unsigned int N = side[0].size();
      for (unsigned int i = 0; i < N; ++i)
        node_distances.push_back(side[0][i].distance);
      const auto [reduced, n_reduced] = reduced_numbers(held, side);

      SparsityPattern      full_sparsity, reduced_sparsity;
      SparseMatrix<double> A, R;
      tributary = assemble(settings,
                           dofs,
                           grid,
                           side,
                           reduced,
                           n_reduced,
                           tolerance,
                           full_sparsity,
                           reduced_sparsity,
                           A,
                           R);
      SparseDirectUMFPACK solver;
      solver.factorize(R);

      // The slip direction d of the hanging wall relative to the footwall
      // and the normal n from the footwall into the hanging wall.
      const double delta  = settings.dip * M_PI / 180;
      const double cosine = settings.dip == 90 ? 0. : std::cos(delta);
      const std::array<double, 2> down_dip = {{cosine, -grid.sine}};
      const double                sense    = settings.thrust ? -1 : 1;
      const std::array<double, 2> d        = {
               {sense * down_dip[0], sense * down_dip[1]}};
      const std::array<double, 2> normal_direction = {{grid.sine, cosine}};
      direction                                    = d;

      const std::vector<Probe> probes =
        surface_probes(settings, dofs, grid, tolerance, side_of_point);
      const unsigned int M = probes.size();

      // This rank's columns.
      const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(
                           communicator),
                         ranks = dealii::Utilities::MPI::n_mpi_processes(
                           communicator);
      const unsigned int first = std::size_t(N) * rank / ranks,
                         last  = std::size_t(N) * (rank + 1) / ranks;
      std::vector<double> columns;
      columns.reserve(2 * std::size_t(last - first) * (N + M));
      Vector<double> field(n_dofs), right_hand_side(n_reduced);
      for (unsigned int j = first; j < last; ++j)
        {
          // u = u_s + w: u_s the jump d at the hanging wall's node j alone,
          // w continuous across the fault and held at the far sides. The
          // reduced right-hand side is -A u_s (A symmetric: the rows of
          // node j), the hanging wall's rows added to the footwall's.
          right_hand_side = 0;
          for (unsigned int c = 0; c < 2; ++c)
            {
              const types::global_dof_index dof = side[1][j].dof[c];
              for (auto entry = A.begin(dof); entry != A.end(dof); ++entry)
                if (reduced[entry->column()] != numbers::invalid_dof_index)
                  right_hand_side[reduced[entry->column()]] -=
                    d[c] * entry->value();
            }
          solver.solve(right_hand_side);
          for (types::global_dof_index i = 0; i < n_dofs; ++i)
            field[i] = reduced[i] != numbers::invalid_dof_index ?
                         right_hand_side[reduced[i]] :
                         0.;
          for (unsigned int c = 0; c < 2; ++c)
            field[side[1][j].dof[c]] += d[c];
          // The footwall's nodal forces, per tributary length.
          for (unsigned int i = 0; i < N; ++i)
            {
              std::array<double, 2> traction = {{0, 0}};
              for (unsigned int c = 0; c < 2; ++c)
                {
                  const types::global_dof_index dof = side[0][i].dof[c];
                  for (auto entry = A.begin(dof); entry != A.end(dof); ++entry)
                    traction[c] += entry->value() * field[entry->column()];
                  traction[c] /= tributary[i];
                }
              columns.push_back(traction[0] * d[0] + traction[1] * d[1]);
              columns.push_back(-(traction[0] * normal_direction[0] +
                                  traction[1] * normal_direction[1]));
            }
          // The surface points' displacements.
          for (const Probe &probe : probes)
            {
              std::array<double, 2> u = {{0, 0}};
              for (std::size_t a = 0; a < probe.dofs.size(); ++a)
                u[probe.components[a]] +=
                  probe.values[a] * field[probe.dofs[a]];
              columns.push_back(u[0]);
              columns.push_back(u[1]);
            }
        }

      // All columns on every rank, stored by rows.
      const std::vector<std::vector<double>> parts =
        dealii::Utilities::MPI::all_gather(communicator, columns);
      shear.assign(std::size_t(N) * N, 0.);
      normal.assign(std::size_t(N) * N, 0.);
      surface.assign(2 * std::size_t(M) * N, 0.);
      const std::size_t stride = 2 * std::size_t(N + M);
      unsigned int      j      = 0;
      for (const auto &part : parts)
        for (std::size_t c = 0; c < part.size() / stride; ++c, ++j)
          {
            const double *column = &part[c * stride];
            for (unsigned int i = 0; i < N; ++i)
              {
                shear[std::size_t(i) * N + j]  = column[2 * i];
                normal[std::size_t(i) * N + j] = column[2 * i + 1];
              }
            for (unsigned int k = 0; k < M; ++k)
              for (unsigned int l = 0; l < 2; ++l)
                surface[(2 * std::size_t(k) + l) * N + j] =
                  column[2 * N + 2 * k + l];
          }
    }



    std::vector<double>
    PlaneStrainFiniteElements::rows(const unsigned int begin,
                                    const unsigned int end) const
    {
      const std::size_t N = size();
      return std::vector<double>(shear.begin() + begin * N,
                                 shear.begin() + end * N);
    }



    std::vector<double>
    PlaneStrainFiniteElements::normal_rows(const unsigned int begin,
                                           const unsigned int end) const
    {
      const std::size_t N = size();
      return std::vector<double>(normal.begin() + begin * N,
                                 normal.begin() + end * N);
    }



    std::array<double, 2>
    PlaneStrainFiniteElements::surface_motion(
      const unsigned int         k,
      const std::vector<double> &fault_values,
      const double               plate_value) const
    {
      const std::size_t     N = size();
      std::array<double, 2> u;
      for (unsigned int c = 0; c < 2; ++c)
        {
          const double *row = &surface[(2 * std::size_t(k) + c) * N];
          double        sum = 0;
          for (std::size_t j = 0; j < N; ++j)
            sum += row[j] * fault_values[j];
          u[c] = side_of_point[k] * 0.5 * direction[c] * plate_value + sum;
        }
      return u;
    }



    std::string
    PlaneStrainFiniteElements::description() const
    {
      std::ostringstream s;
      s << std::setprecision(6) << "plane-strain finite elements (Q"
        << settings.degree << ", " << n_cells << " cells, " << n_dofs
        << " unknowns, the fault's far sides " << settings.domain_size / 1e3
        << " km away), a " << (settings.thrust ? "thrust" : "normal")
        << " fault dipping at " << settings.dip << " degrees, " << size()
        << " node pairs " << settings.fault_extent / size() << " m apart"
        << (settings.degree > 2 ? " on average" : "") << " down to "
        << settings.fault_extent / 1e3 << " km along the dip";
      return s.str();
    }
  } // namespace BoundaryIntegral
} // namespace rupture
