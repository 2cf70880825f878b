// The split-pair topology of the fault: which side a cell is on, the
// pairing of the nodes of the two sides on the interface (and the welding of
// the pairs outside the fault region), and what the solvers need of the
// pairs (sparsity, DoF pairs, the level interfaces of multigrid).

#include <rupture/base/lobatto_points.h>
#include <rupture/fault/face_nodes.h>
#include <rupture/fault/fault.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace rupture
{
  namespace Fault
  {
    template <int dim>
    unsigned int
    Fault<dim>::side(
      const typename Triangulation<dim>::cell_iterator &cell) const
    {
      if (side_by_plane)
        return ((cell->center() - plane_point) * plane_normal > 0) ? 1 : 0;
      return std::find(plus_materials.begin(),
                       plus_materials.end(),
                       cell->material_id()) != plus_materials.end() ?
               1 :
               0;
    }



    template <int dim>
    bool
    Fault<dim>::interface_face(
      const typename Triangulation<dim>::cell_iterator &cell,
      const unsigned int                                f) const
    {
      return !cell->at_boundary(f) && side(cell->neighbor(f)) != side(cell);
    }



    template <int dim>
    bool
    Fault<dim>::on_fault(
      const typename Triangulation<dim>::cell_iterator &cell) const
    {
      for (const auto f : cell->face_indices())
        if (interface_face(cell, f) &&
            region->value(cell->face(f)->center()) != 0)
          return true;
      return false;
    }



    template <int dim>
    Point<3>
    Fault<dim>::to_3d(const Point<dim> &p) const
    {
      Point<3> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = p[d];
      return x;
    }



    template <int dim>
    void
    Fault<dim>::find_interface(const DoFHandler<dim>     &dof_handler,
                               AffineConstraints<double> &constraints,
                               Interface                 &result) const
    {
      const FiniteElement<dim> &fe0               = dof_handler.get_fe(0);
      const FiniteElement<dim> &fe1               = dof_handler.get_fe(1);
      auto                     &fault_nodes       = result.fault_nodes;
      auto                     &welded_nodes      = result.welded_nodes;
      unsigned int             &n_interface_faces = result.n_interface_faces;
      std::vector<types::global_dof_index> dm(fe0.n_dofs_per_face()),
        dp(fe1.n_dofs_per_face());
      const unsigned int n_nodes = fe0.n_dofs_per_face() / dim;
      // Where each face node sits: the support point of its DoF in the
      // minus cell (the FE_Q's unit support points, mapped d-linearly from
      // the cell's vertices). Taken through the cell's own DoF order, which
      // needs no care for the orientation of the face's lines at degree 3
      // and above. Only fault nodes are located, instead of a map of the
      // support points of every DoF (some 80 B per DoF of the whole mesh).
      const std::vector<Point<dim>> &unit_points =
        fe0.base_element(0).get_unit_support_points();
      AssertThrow(fe0.base_element(0).n_dofs_per_face() == n_nodes,
                  ExcInternalError());
      std::vector<types::global_dof_index> cell_dofs(fe0.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial() && cell->active_fe_index() == 0)
          for (const auto f : cell->face_indices())
            {
              if (cell->at_boundary(f))
                continue;
              // Hanging nodes may lie anywhere but on the fault itself.
              const auto neighbor = cell->neighbor(f);
              bool       across   = false;
              if (neighbor->has_children())
                {
                  for (unsigned int c = 0; c < cell->face(f)->n_children(); ++c)
                    {
                      const auto child = cell->neighbor_child_on_subface(f, c);
                      across           = across || (!child->is_artificial() &&
                                          child->active_fe_index() == 1);
                    }
                }
              else
                across = (neighbor->level() != cell->level()) &&
                         !neighbor->is_artificial() &&
                         neighbor->active_fe_index() == 1;
              if (across)
                {
                  std::ostringstream where;
                  where << cell->face(f)->center();
                  AssertThrow(false,
                              ExcMessage(
                                "The fault interface must be refined alike "
                                "on both sides (no hanging nodes on it), but "
                                "the cells at (" +
                                where.str() +
                                ") differ in size. Keep "
                                "<Discretization/Refinement region> off the "
                                "fault, or let it cover both sides."));
                }
              if (neighbor->has_children() || neighbor->is_artificial() ||
                  neighbor->active_fe_index() != 1)
                continue;
              const auto       face   = cell->face(f);
              const Point<dim> center = face->center();
              if (cell->is_locally_owned())
                ++n_interface_faces;
              if (side_by_plane)
                {
                  const double distance = (center - plane_point) * plane_normal;
                  std::ostringstream where;
                  where << center;
                  AssertThrow(std::abs(distance) <= 1e-6 * cell->diameter(),
                              ExcMessage(
                                "The fault plane of <Fault/Plane point> and "
                                "<Fault/Plane normal> does not coincide with "
                                "faces of the mesh: the interface face at (" +
                                where.str() + ") is " +
                                std::to_string(distance) +
                                " m off the plane. Choose a plane through "
                                "mesh faces, or a mesh that has faces on "
                                "the plane."));
                }
              const double region_value = region->value(center);
              if (!std::isfinite(region_value))
                {
                  std::ostringstream where;
                  where << center;
                  AssertThrow(false,
                              ExcMessage("<Fault/Fault region> is not a "
                                         "finite number at the interface "
                                         "face (" +
                                         where.str() +
                                         "). Allowed is an expression that "
                                         "is finite everywhere on the "
                                         "interface: nonzero on the fault, "
                                         "0 where the sides stay welded."));
                }
              const bool is_fault = (region_value != 0);
              if (is_fault && cell->is_locally_owned())
                result.fault_faces.insert({cell, f});

              face->get_dof_indices(dm, 0);
              face->get_dof_indices(dp, 1);
              std::vector<std::array<types::global_dof_index, dim>> minus(
                n_nodes),
                plus(n_nodes);
              for (unsigned int i = 0; i < dm.size(); ++i)
                {
                  const auto ci = fe0.face_system_to_component_index(i, f);
                  minus[ci.second][ci.first] = dm[i];
                  const auto cp = fe1.face_system_to_component_index(i, f);
                  plus[cp.second][cp.first - dim] = dp[i];
                }
              cell->get_dof_indices(cell_dofs);
              std::map<types::global_dof_index, Point<dim>> located;
              for (unsigned int i = 0; i < cell_dofs.size(); ++i)
                {
                  const auto ci = fe0.system_to_component_index(i);
                  if (ci.first == 0 && fe0.has_support_on_face(i, f))
                    {
                      Point<dim> x;
                      for (const unsigned int v : cell->vertex_indices())
                        x += GeometryInfo<dim>::d_linear_shape_function(
                               unit_points[ci.second], v) *
                             cell->vertex(v);
                      located[cell_dofs[i]] = x;
                    }
                }
              if (is_fault && cell->is_locally_owned())
                {
                  // The face's nodes in lexicographic order (FaceNodes),
                  // found from where they sit between its corners.
                  const unsigned int      degree = fe0.base_element(0).degree;
                  std::vector<Point<dim>> corners;
                  for (unsigned int v = 0;
                       v < GeometryInfo<dim>::vertices_per_face;
                       ++v)
                    corners.push_back(located.at(minus[v][0]));
                  std::vector<types::global_dof_index> keys(
                    n_nodes, numbers::invalid_dof_index);
                  for (unsigned int k = 0; k < n_nodes; ++k)
                    {
                      const auto xi =
                        FaceNodes::coordinates<dim>(corners,
                                                    located.at(minus[k][0]));
                      unsigned int index = 0;
                      for (unsigned int d = dim - 1; d-- > 0;)
                        index = index * (degree + 1) +
                                LobattoPoints::nearest(degree, xi[d]);
                      AssertThrow(keys[index] == numbers::invalid_dof_index,
                                  ExcInternalError());
                      keys[index] = minus[k][0];
                    }
                  result.owned_faces.push_back(keys);
                }
              for (unsigned int k = 0; k < n_nodes; ++k)
                {
                  NodePair pair;
                  pair.minus    = minus[k];
                  pair.plus     = plus[k];
                  const auto at = located.find(minus[k][0]);
                  AssertThrow(at != located.end(), ExcInternalError());
                  pair.location = at->second;
                  pair.material = cell->material_id();
                  (is_fault ? fault_nodes : welded_nodes)
                    .emplace(pair.minus[0], pair);
                }
            }

      // Nodes on the border of the fault region are welded.
      for (const auto &w : welded_nodes)
        fault_nodes.erase(w.first);

      for (const auto &[key, pair] : welded_nodes)
        for (unsigned int c = 0; c < dim; ++c)
          if (!constraints.is_constrained(pair.plus[c]))
            {
              constraints.add_line(pair.plus[c]);
              constraints.add_entry(pair.plus[c], pair.minus[c], 1.);
            }
    }



    template <int dim>
    std::vector<std::pair<std::array<types::global_dof_index, dim>,
                          std::array<types::global_dof_index, dim>>>
    Fault<dim>::level_interface(const DoFHandler<dim>     &dof_handler,
                                AffineConstraints<double> &constraints) const
    {
      Interface interface;
      find_interface(dof_handler, constraints, interface);
      const IndexSet &owned = dof_handler.locally_owned_dofs();
      std::vector<std::pair<std::array<types::global_dof_index, dim>,
                            std::array<types::global_dof_index, dim>>>
        result;
      for (const auto &[key, pair] : interface.fault_nodes)
        if (owned.is_element(pair.minus[0]))
          result.emplace_back(pair.minus, pair.plus);
      return result;
    }



    template <int dim>
    std::vector<
      std::pair<std::array<types::global_dof_index, dim>, Tensor<2, dim>>>
    Fault<dim>::pair_tangents() const
    {
      std::vector<
        std::pair<std::array<types::global_dof_index, dim>, Tensor<2, dim>>>
        result;
      result.reserve(pairs.size());
      for (const auto &pair : pairs)
        result.emplace_back(pair.minus, pair.area * pair.trial.tangent);
      return result;
    }



    template <int dim>
    void
    Fault<dim>::add_sparsity(DynamicSparsityPattern          &dsp,
                             const AffineConstraints<double> &constraints) const
    {
      std::vector<types::global_dof_index> dofs(2 * dim);
      for (const auto &pair : pairs)
        if (pair.hanging)
          {
            // The pair's coupling, condensed onto the nodes that its
            // hanging nodes follow.
            for (unsigned int c = 0; c < dim; ++c)
              {
                dofs[c]       = pair.minus[c];
                dofs[dim + c] = pair.plus[c];
              }
            constraints.add_entries_local_to_global(dofs, dsp, true);
          }
        else
          for (unsigned int a = 0; a < dim; ++a)
            for (unsigned int b = 0; b < dim; ++b)
              {
                dsp.add(pair.minus[a], pair.plus[b]);
                dsp.add(pair.plus[a], pair.minus[b]);
                dsp.add(pair.minus[a], pair.minus[b]);
                dsp.add(pair.plus[a], pair.plus[b]);
              }
    }



    template <int dim>
    std::vector<std::pair<types::global_dof_index, types::global_dof_index>>
    Fault<dim>::dof_pairs() const
    {
      std::vector<std::pair<types::global_dof_index, types::global_dof_index>>
        result;
      for (const auto &pair : pairs)
        for (unsigned int c = 0; c < dim; ++c)
          result.emplace_back(pair.minus[c], pair.plus[c]);
      return result;
    }



    template <int dim>
    bool
    Fault<dim>::touches_fault_region(
      const std::vector<types::global_dof_index> &cell_dofs) const
    {
      for (const auto dof : cell_dofs)
        if (region_node_dofs.count(dof) != 0)
          return true;
      return false;
    }



    template class Fault<2>;
    template class Fault<3>;
  } // namespace Fault
} // namespace rupture
