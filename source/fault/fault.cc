#include <rupture/base/utilities.h>
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
#include <deal.II/lac/vector.h>

#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace rupture
{
  namespace Fault
  {
    template <int dim>
    void
    Fault<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Fault");
      {
        prm.declare_entry("Model",
                          "none",
                          Patterns::Selection(
                            "none|penalty contact|traction at split nodes"),
                          "'none' for a body without a fault. 'penalty "
                          "contact': the fault of the GeoFEM paper, a split "
                          "interface whose node pairs are coupled by normal "
                          "and tangential penalties with Coulomb friction; "
                          "for the implicit Newmark and quasi-static "
                          "schemes. 'traction at split nodes': the same "
                          "split interface with the exact constraint of "
                          "Day et al. (2005) and no penalty: each step the "
                          "traction that keeps a node pair together is "
                          "computed and limited by the friction strength; "
                          "for the explicit central-difference scheme. The "
                          "penalties are then not used.");
        prm.declare_entry("Plus side",
                          "plane",
                          Patterns::Selection("plane|material ids"),
                          "How the cells on either side of the fault are "
                          "told apart: by the plane through <Plane point> "
                          "with normal <Plane normal> (cells on the side the "
                          "normal points to are the plus side), or by the "
                          "material ids listed in <Plus side material ids>. "
                          "The faces between the sides form the interface; "
                          "they must be faces of the mesh.");
        prm.declare_entry("Plane point",
                          "0",
                          Patterns::Anything(),
                          "A point of the fault plane (m): one number per "
                          "dimension, or one for all.");
        prm.declare_entry("Plane normal",
                          "0, 1, 0",
                          Patterns::Anything(),
                          "A normal vector of the fault plane, pointing to "
                          "the plus side; one number per dimension. Used "
                          "when <Plus side> = plane.");
        prm.declare_entry("Plus side material ids",
                          "",
                          Patterns::Anything(),
                          "Material ids of the plus side, when <Plus side> "
                          "= material ids (e.g. '2' for the plate of the "
                          "Northeast-Japan scene).");
        prm.declare_entry(
          "Fault region",
          "1",
          Patterns::Anything(),
          "Where the interface is a fault: a function of x, y (, z) that is "
          "nonzero on the fault and zero where the two sides stay welded, "
          "e.g. '(abs(x) <= 15000 && z >= -15000) ? 1 : 0'. Nodes on the "
          "border of the region are welded.");
        prm.declare_entry("Normal penalty",
                          "5e11",
                          Patterns::Anything(),
                          "p_n (Pa/m): stiffness resisting interpenetration, "
                          "a function of x, y (, z). > 0. The paper uses "
                          "5e11.");
        prm.declare_entry("Tangential penalty",
                          "5e11",
                          Patterns::Anything(),
                          "p_t (Pa/m): stiffness of the stuck fault in "
                          "shear, a function of x, y (, z). > 0.");
        prm.declare_entry(
          "Initial traction",
          "",
          Patterns::Anything(),
          "Traction (Pa) of an initial stress that the displacement does "
          "not carry, exerted on the minus side (T = sigma n, n from minus "
          "to plus; compression has T.n < 0), as a vector function of x, y "
          "(, z), components separated by ';'. Empty for zero, as when the "
          "stress comes from a loading step. Used by the benchmarks, e.g. "
          "TPV3: '70e6; -120e6; 0' for a plane with normal (0, 1, 0).");
        prm.enter_subsection("Forced slip");
        {
          prm.declare_entry(
            "Region",
            "0",
            Patterns::Anything(),
            "Where slip is imposed instead of computed from friction (the "
            "paper's forced-slip trigger): a function of x, y (, z), "
            "nonzero inside. '0' for no forced slip. Forced slip acts in "
            "the dynamic phase only.");
          prm.declare_entry(
            "Slip",
            "0",
            Patterns::Anything(),
            "The imposed slip (m, >= 0) as a function of x, y (, z) and t, "
            "with t the time since the start of the dynamic phase, e.g. "
            "'4 * min(t / 0.1, 1)' for the paper's 4 m over 0.1 s. After "
            "the ramp the patch stays at its final slip.");
          prm.declare_entry(
            "Direction",
            "",
            Patterns::Anything(),
            "Direction of the imposed slip (motion of the plus side "
            "relative to the minus side), one number per dimension, e.g. "
            "'1, 0, 0'; it is projected onto the fault plane. Needed when "
            "<Region> is set.");
        }
        prm.leave_subsection();
        Friction::declare_parameters(prm);
      }
      prm.leave_subsection();
    }



    template <int dim>
    std::unique_ptr<Fault<dim>>
    Fault<dim>::create(ParameterHandler &prm)
    {
      prm.enter_subsection("Fault");
      if (prm.get("Model") == "none")
        {
          prm.leave_subsection();
          return nullptr;
        }
      auto fault = std::make_unique<Fault<dim>>();
      fault->split_node_method =
        (prm.get("Model") == "traction at split nodes");
      const std::string variables = (dim == 2 ? "x,y" : "x,y,z");
      fault->side_by_plane        = (prm.get("Plus side") == "plane");
      fault->plane_point          = Point<dim>(Utilities::parse_vector<dim>(
        prm.get("Plane point"), "Fault/Plane point", true));
      // The plane normal matters only for a fault given by a plane.
      fault->plane_normal[dim - 1] = 1;
      if (fault->side_by_plane)
        {
          fault->plane_normal =
            Utilities::parse_vector<dim>(prm.get("Plane normal"),
                                         "Fault/Plane normal");
          AssertThrow(fault->plane_normal.norm() > 0,
                      ExcMessage("<Fault/Plane normal> must not be the zero "
                                 "vector."));
          fault->plane_normal /= fault->plane_normal.norm();
        }
      for (const double id :
           Utilities::parse_doubles(prm.get("Plus side material ids"),
                                    "Fault/Plus side material ids"))
        {
          AssertThrow(id >= 0 && id < 255 && id == std::floor(id),
                      ExcMessage("<Fault/Plus side material ids> must be "
                                 "integers in 0..254."));
          fault->plus_materials.push_back(static_cast<types::material_id>(id));
        }
      AssertThrow(fault->side_by_plane || !fault->plus_materials.empty(),
                  ExcMessage("<Fault/Plus side> = material ids, but <Fault/"
                             "Plus side material ids> is empty."));
      fault->region = Utilities::parse_function<dim>(prm.get("Fault region"),
                                                     1,
                                                     "Fault/Fault region",
                                                     variables);
      fault->normal_penalty = Utilities::parse_function<dim>(
        prm.get("Normal penalty"), 1, "Fault/Normal penalty", variables);
      fault->tangential_penalty =
        Utilities::parse_function<dim>(prm.get("Tangential penalty"),
                                       1,
                                       "Fault/Tangential penalty",
                                       variables);
      fault->initial_traction = Utilities::parse_function<dim>(
        prm.get("Initial traction"), dim, "Fault/Initial traction", variables);
      prm.enter_subsection("Forced slip");
      fault->forced_region = Utilities::parse_function<dim>(
        prm.get("Region"), 1, "Fault/Forced slip/Region", variables);
      fault->forced_slip =
        Utilities::parse_function<dim>(prm.get("Slip"),
                                       1,
                                       "Fault/Forced slip/Slip");
      if (dealii::Utilities::trim(prm.get("Region")) != "0")
        fault->forced_direction =
          Utilities::parse_vector<dim>(prm.get("Direction"),
                                       "Fault/Forced slip/Direction");
      prm.leave_subsection();
      fault->friction_law = Friction::create(prm);
      prm.leave_subsection();
      return fault;
    }



    template <int dim>
    unsigned int
    Fault<dim>::side(
      const typename DoFHandler<dim>::active_cell_iterator &cell) const
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
    Fault<dim>::setup(const DoFHandler<dim> &dof_handler,
                      const IndexSet        &locally_owned_dofs,
                      const IndexSet &,
                      AffineConstraints<double> &constraints,
                      const std::vector<double> &shear_modulus,
                      const MPI_Comm             comm)
    {
      communicator = comm;
      AssertThrow(dof_handler.get_fe_collection().size() == 2,
                  ExcInternalError());
      const FiniteElement<dim> &fe0 = dof_handler.get_fe(0);
      const FiniteElement<dim> &fe1 = dof_handler.get_fe(1);

      std::map<types::global_dof_index, NodePair> fault_nodes;
      std::map<types::global_dof_index, NodePair> welded_nodes;
      std::set<
        std::pair<typename DoFHandler<dim>::active_cell_iterator, unsigned int>>
        fault_faces;

      owned_faces.clear();
      std::vector<types::global_dof_index> dm(fe0.n_dofs_per_face()),
        dp(fe1.n_dofs_per_face());
      const unsigned int n_nodes           = fe0.n_dofs_per_face() / dim;
      unsigned int       n_interface_faces = 0;
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
              const bool is_fault = (region->value(center) != 0);
              if (is_fault && cell->is_locally_owned())
                fault_faces.insert({cell, f});

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
              if (is_fault && cell->is_locally_owned())
                {
                  std::vector<types::global_dof_index> keys;
                  for (unsigned int v = 0;
                       v < GeometryInfo<dim>::vertices_per_face;
                       ++v)
                    keys.push_back(minus[v][0]);
                  owned_faces.push_back(keys);
                }
              for (unsigned int k = 0; k < n_nodes; ++k)
                {
                  NodePair pair;
                  pair.minus         = minus[k];
                  pair.plus          = plus[k];
                  pair.shear_modulus = shear_modulus[cell->material_id()];
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

      // Tributary area and normal of each node: the integral of its shape
      // function times the normal over the fault faces, with the vertex
      // (Gauss-Lobatto) quadrature that lumps it to the nodes.
      VectorType area_normal(locally_owned_dofs, communicator);
      {
        const unsigned int       degree = fe0.degree;
        hp::QCollection<dim - 1> q(QGaussLobatto<dim - 1>(degree + 1));
        hp::FEFaceValues<dim>    hp_face(dof_handler.get_fe_collection(),
                                      q,
                                      update_values | update_normal_vectors |
                                        update_JxW_values);
        std::vector<types::global_dof_index> dofs(fe0.n_dofs_per_cell());
        Vector<double>                       local(fe0.n_dofs_per_cell());
        for (const auto &[cell, f] : fault_faces)
          {
            hp_face.reinit(cell, f);
            const FEFaceValues<dim> &fv = hp_face.get_present_fe_values();
            cell->get_dof_indices(dofs);
            local = 0;
            for (const unsigned int q : fv.quadrature_point_indices())
              for (unsigned int i = 0; i < dofs.size(); ++i)
                {
                  const unsigned int c = fe0.system_to_component_index(i).first;
                  local(i) +=
                    fv.shape_value(i, q) * fv.normal_vector(q)[c] * fv.JxW(q);
                }
            area_normal.add(dofs, local);
          }
        area_normal.compress(VectorOperation::add);
      }

      std::map<types::global_dof_index, Point<dim>> support_points;
      DoFTools::map_dofs_to_support_points(hp::MappingCollection<dim>(
                                             MappingQ1<dim>()),
                                           dof_handler,
                                           support_points);

      pairs.clear();
      for (auto &[key, pair] : fault_nodes)
        if (locally_owned_dofs.is_element(pair.minus[0]))
          {
            for (unsigned int c = 0; c < dim; ++c)
              pair.normal[c] = area_normal(pair.minus[c]);
            pair.area = pair.normal.norm();
            AssertThrow(pair.area > 0, ExcInternalError());
            pair.normal /= pair.area;
            pair.location    = support_points[pair.minus[0]];
            const Point<3> x = to_3d(pair.location);
            for (unsigned int c = 0; c < dim; ++c)
              pair.initial_traction[c] =
                initial_traction->value(pair.location, c);
            pair.normal_penalty     = normal_penalty->value(pair.location);
            pair.tangential_penalty = tangential_penalty->value(pair.location);
            std::ostringstream where, values;
            where << pair.location;
            values << pair.normal_penalty << " and " << pair.tangential_penalty;
            AssertThrow(split_node_method || (pair.normal_penalty > 0 &&
                                              pair.tangential_penalty > 0),
                        ExcMessage("<Fault/Normal penalty> and <Fault/"
                                   "Tangential penalty> must be > 0 (Pa/m), "
                                   "but are " +
                                   values.str() + " at (" + where.str() +
                                   ")."));
            friction_law->initialize_state(x, pair.state);
            if (forced_region->value(pair.location) != 0)
              {
                pair.forced = true;
                pair.forced_direction =
                  forced_direction -
                  (forced_direction * pair.normal) * pair.normal;
                AssertThrow(
                  pair.forced_direction.norm() > 1e-6 * forced_direction.norm(),
                  ExcMessage("<Fault/Forced slip/Direction> is normal to "
                             "the fault at (" +
                             where.str() +
                             "): it has no component along the fault to "
                             "slip in."));
                pair.forced_direction /= pair.forced_direction.norm();
              }
            pairs.push_back(pair);
          }

      {
        // The split-node method and the matrix-free contact tangent read
        // and write the pairs' DoFs alone (minus side then plus side, dim
        // entries each, pair by pair). The split-node forces go straight
        // to the DoFs, so none may be constrained there (hanging nodes on
        // the fault are not supported).
        std::vector<types::global_dof_index> indices;
        bool                                 constrained = false;
        for (const auto &pair : pairs)
          for (const auto *side : {&pair.minus, &pair.plus})
            for (const auto dof : *side)
              {
                indices.push_back(dof);
                constrained = constrained || constraints.is_constrained(dof);
              }
        pair_dofs.reinit(locally_owned_dofs, indices, communicator);
        if (split_node_method)
          AssertThrow(dealii::Utilities::MPI::max(constrained ? 1 : 0,
                                                  communicator) == 0,
                      ExcMessage("The fault's split nodes lie on hanging "
                                 "nodes: the traction-at-split-node method "
                                 "needs the same refinement on both sides "
                                 "of the fault and along it. Refine the "
                                 "mesh globally."));
      }

      unsigned int n_welded_owned = 0;
      for (const auto &[key, pair] : welded_nodes)
        if (locally_owned_dofs.is_element(pair.minus[0]))
          ++n_welded_owned;
      n_global_split =
        dealii::Utilities::MPI::sum(static_cast<unsigned int>(pairs.size()),
                                    communicator);
      n_global_welded =
        dealii::Utilities::MPI::sum(n_welded_owned, communicator);
      const unsigned int n_faces =
        dealii::Utilities::MPI::sum(n_interface_faces, communicator);
      AssertThrow(n_faces > 0,
                  ExcMessage("The fault interface is empty: no cell of the "
                             "plus side touches a cell of the minus side. "
                             "Check <Fault/Plus side> and its plane or "
                             "material ids."));
    }



    template <int dim>
    void
    Fault<dim>::add_sparsity(DynamicSparsityPattern &dsp) const
    {
      for (const auto &pair : pairs)
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
    void
    Fault<dim>::assemble(const VectorType                &u,
                         const double                     dt,
                         const AffineConstraints<double> &force_constraints,
                         VectorType                      &force,
                         const AffineConstraints<double> &tangent_constraints,
                         TrilinosWrappers::SparseMatrix  *tangent,
                         const double                     sign)
    {
      std::vector<types::global_dof_index> dofs(2 * dim);
      FullMatrix<double>                   local_tangent(2 * dim, 2 * dim);
      for (auto &pair : pairs)
        {
          Tensor<1, dim> delta;
          for (unsigned int c = 0; c < dim; ++c)
            {
              delta[c]      = u(pair.plus[c]) - u(pair.minus[c]);
              dofs[c]       = pair.minus[c];
              dofs[dim + c] = pair.plus[c];
            }
          if (pair.forced && forced_slip_active)
            pair.trial = forced_slip_response<dim>(delta,
                                                   pair.normal,
                                                   pair.initial_traction,
                                                   pair.normal_penalty,
                                                   pair.tangential_penalty,
                                                   pair.plastic_slip,
                                                   imposed_slip(pair, 0));
          else
            pair.trial = return_map<dim>(delta,
                                         pair.normal,
                                         pair.initial_traction,
                                         pair.normal_penalty,
                                         pair.tangential_penalty,
                                         pair.plastic_slip,
                                         pair.state,
                                         *friction_law,
                                         to_3d(pair.location),
                                         dt);
          pair.trial_slip = delta - (delta * pair.normal) * pair.normal;

          add_internal_force(pair, force_constraints, force);

          if (tangent)
            {
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  {
                    const double d =
                      sign * pair.area * pair.trial.tangent[i][j];
                    local_tangent(i, j)             = d;
                    local_tangent(i, dim + j)       = -d;
                    local_tangent(dim + i, j)       = -d;
                    local_tangent(dim + i, dim + j) = d;
                  }
              tangent_constraints.distribute_local_to_global(local_tangent,
                                                             dofs,
                                                             *tangent);
            }
        }
      force.compress(VectorOperation::add);
      if (tangent)
        tangent->compress(VectorOperation::add);
    }



    template <int dim>
    unsigned int
    Fault<dim>::limit_stick_crossings(
      const VectorType                &increment,
      const AffineConstraints<double> &constraints,
      VectorType                      &correction) const
    {
      unsigned int                         n_limited = 0;
      std::vector<types::global_dof_index> dofs(2 * dim);
      Vector<double>                       local(2 * dim);
      for (const auto &pair : pairs)
        {
          if (pair.trial.status != ContactStatus::slip ||
              (pair.forced && forced_slip_active))
            continue;
          // Tangential trial traction now and along the update,
          // T(s) = T + s D, and the strength now (the traction that slip
          // returned the trial to).
          const Tensor<1, dim> &n = pair.normal;
          Tensor<1, dim>        step;
          for (unsigned int c = 0; c < dim; ++c)
            step[c] = increment(pair.plus[c]) - increment(pair.minus[c]);
          const Tensor<1, dim>  step_t = step - (step * n) * n;
          const Tensor<1, dim> &T      = pair.trial.trial_traction;
          const Tensor<1, dim>  D      = pair.tangential_penalty * step_t;
          const double          D2     = D * D;
          if (D2 == 0)
            continue;
          const Tensor<1, dim> &traction = pair.trial.traction;
          const double strength = (traction - (traction * n) * n).norm();
          // The update's closest approach to zero traction, and whether it
          // lies in the stick region while the full update ends in slip.
          const double s_min   = std::min(std::max(-(T * D) / D2, 0.), 1.);
          const double closest = (T + s_min * D).norm();
          if (s_min >= 1 || (T + D).norm() <= strength || closest >= strength)
            continue;
          // Stop 5 % of the chord into the stick region (a tenth of the way
          // from where the update enters it to its middle): the node's
          // traction changes little, and the next iteration starts from
          // stick, whose penalty tangent is exact there.
          const double s = std::max(s_min - 0.9 *
                                              std::sqrt(strength * strength -
                                                        closest * closest) /
                                              std::sqrt(D2),
                                    0.);
          // Keep the mean of the pair, scale its tangential jump by s.
          const Tensor<1, dim> change = 0.5 * (1 - s) * step_t;
          for (unsigned int c = 0; c < dim; ++c)
            {
              dofs[c]        = pair.minus[c];
              dofs[dim + c]  = pair.plus[c];
              local[c]       = change[c];
              local[dim + c] = -change[c];
            }
          constraints.distribute_local_to_global(local, dofs, correction);
          ++n_limited;
        }
      correction.compress(VectorOperation::add);
      return dealii::Utilities::MPI::sum(n_limited, communicator);
    }



    template <int dim>
    void
    Fault<dim>::assemble_split_node(const VectorType &u,
                                    const VectorType &v,
                                    const VectorType &residual,
                                    const VectorType &inverse_mass,
                                    const double      dt,
                                    const double      gamma,
                                    VectorType       &force)
    {
      // With the fault traction T = T_0 + dT acting on the minus node (and
      // -T on the plus node), the accelerations of the step are
      //   a- = (R- + A dT) / M-,   a+ = (R+ - A dT) / M+,
      // and the displacement of the next step is u + dt (v + c dt a) with
      // c = gamma + 1/2. The traction that keeps the pair together (no
      // tangential slip over the next step, normal gap closed) is thus
      //   dT = [dv / (c dt) + R+/M+ - R-/M- + (du.n) n / (c dt^2)]
      //        / (A (1/M+ + 1/M-)),
      // with dv = v+ - v- and du = u+ - u-.
      const double            c         = gamma + 0.5;
      const VectorType *const fields[4] = {&u, &v, &residual, &inverse_mass};
      for (unsigned int f = 0; f < 4; ++f)
        pair_dofs.gather(fields[f]->trilinos_vector()[0], pair_values[f]);
      const std::vector<double> &us = pair_values[0], &vs = pair_values[1],
                                &rs = pair_values[2], &ms = pair_values[3];
      std::vector<double> &forces = pair_values[0];
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          NodePair          &pair = pairs[k];
          const unsigned int m0 = 2 * dim * k, p0 = m0 + dim;
          Tensor<1, dim>     du, rate, acceleration, inverse_sum;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const unsigned int m = m0 + d, p = p0 + d;
              du[d]           = us[p] - us[m];
              rate[d]         = vs[p] - vs[m];
              acceleration[d] = rs[p] * ms[p] - rs[m] * ms[m];
              inverse_sum[d]  = ms[p] + ms[m];
            }
          const Tensor<1, dim> &n         = pair.normal;
          const double          gap       = du * n;
          const Tensor<1, dim>  slip      = du - gap * n;
          const double          increment = (slip - pair.slip).norm();

          ContactResponse<dim> r;
          r.slip_increment = increment;
          r.plastic_slip   = slip;
          // Components whose nodes are both held kinematically get no
          // traction change.
          Tensor<1, dim> T = pair.initial_traction;
          // A forced pair follows the imposed slip instead: its slip over
          // the next step is the imposed one's.
          const bool     forced = pair.forced && forced_slip_active;
          Tensor<1, dim> target;
          if (forced)
            target = imposed_slip(pair, dt) - slip;
          const Tensor<1, dim> stick =
            rate / (c * dt) + acceleration + (gap * n - target) / (c * dt * dt);
          for (unsigned int d = 0; d < dim; ++d)
            if (inverse_sum[d] > 0)
              T[d] += stick[d] / (pair.area * inverse_sum[d]);
          const Point<3> x  = to_3d(pair.location);
          double         dm = 0;
          r.friction =
            friction_law->coefficient(x, pair.state, increment, dt, dm);
          r.friction_derivative = dm;
          const double tn       = T * n;
          if (tn > 0)
            {
              r.status = ContactStatus::open;
              T        = 0;
            }
          else if (forced)
            r.status =
              (increment > 0) ? ContactStatus::slip : ContactStatus::stick;
          else
            {
              const Tensor<1, dim> shear    = T - tn * n;
              const double         strength = std::max(
                r.friction * (-tn) + friction_law->cohesion(x, pair.state), 0.);
              if (shear.norm() > strength)
                {
                  r.status = ContactStatus::slip;
                  T        = tn * n + (strength / shear.norm()) * shear;
                }
              else
                r.status = ContactStatus::stick;
            }
          r.traction      = T;
          pair.trial      = r;
          pair.trial_slip = slip;

          // Internal force of the fault: -A dT on the minus node, +A dT on
          // the plus node (as add_internal_force()).
          const Tensor<1, dim> dT = T - pair.initial_traction;
          for (unsigned int d = 0; d < dim; ++d)
            {
              forces[m0 + d] = -pair.area * dT[d];
              forces[p0 + d] = pair.area * dT[d];
            }
        }
      pair_dofs.scatter_add(forces, force.trilinos_vector()[0]);
    }



    template <int dim>
    void
    Fault<dim>::add_internal_force(const NodePair                  &pair,
                                   const AffineConstraints<double> &constraints,
                                   VectorType                      &force) const
    {
      // Internal force of the fault: -A dT on the minus node, +A dT on the
      // plus node, with dT the traction change carried by the displacement.
      std::vector<types::global_dof_index> dofs(2 * dim);
      Vector<double>                       local_force(2 * dim);
      const Tensor<1, dim> dT = pair.trial.traction - pair.initial_traction;
      for (unsigned int d = 0; d < dim; ++d)
        {
          dofs[d]              = pair.minus[d];
          dofs[dim + d]        = pair.plus[d];
          local_force(d)       = -pair.area * dT[d];
          local_force(dim + d) = pair.area * dT[d];
        }
      constraints.distribute_local_to_global(local_force, dofs, force);
    }



    template <int dim>
    void
    Fault<dim>::commit(const double dt, const double time)
    {
      for (auto &pair : pairs)
        {
          Friction::State updated;
          friction_law->update_state(to_3d(pair.location),
                                     pair.state,
                                     pair.trial.slip_increment,
                                     dt,
                                     updated);
          pair.slip_velocity = (pair.trial_slip - pair.slip) / dt;
          updated.slip_rate  = pair.slip_velocity.norm();
          // Rupture time: the first time the slip rate exceeds 1 mm/s,
          // linearly interpolated within the step (SCEC convention). With
          // penalty contact the jump also holds the springs' elastic part
          // traction / p_t, which moves whenever a passing wave changes the
          // traction (at TPV3's penalties faster than 1 mm/s, well ahead of
          // the rupture), so there it is the rate of the frictional
          // (plastic) slip; the split nodes have no elastic part.
          const double rate = split_node_method ?
                                updated.slip_rate :
                                pair.trial.slip_increment / dt;
          if (pair.rupture_time < 0 && rate > 1e-3)
            {
              const double w = (1e-3 - pair.rupture_rate) /
                               std::max(rate - pair.rupture_rate, 1e-300);
              pair.rupture_time =
                time - dynamic_start - dt + std::clamp(w, 0., 1.) * dt;
            }
          pair.rupture_rate = rate;
          const Tensor<1, dim> t =
            pair.trial.traction -
            (pair.trial.traction * pair.normal) * pair.normal;
          frictional_energy += pair.area * t.norm() * pair.trial.slip_increment;
          pair.state        = updated;
          pair.plastic_slip = pair.trial.plastic_slip;
          pair.slip         = pair.trial_slip;
        }
    }



    template <int dim>
    std::vector<typename Fault<dim>::NodeRecord>
    Fault<dim>::gather(const std::set<types::global_dof_index> *keys) const
    {
      std::vector<NodeRecord> mine;
      for (const auto &pair : pairs)
        if (!keys || keys->count(pair.minus[0]))
          {
            NodeRecord r;
            r.key           = pair.minus[0];
            r.location      = pair.location;
            r.normal        = pair.normal;
            r.slip          = pair.slip - pair.slip_at_start;
            r.slip_velocity = pair.slip_velocity;
            r.traction      = pair.trial.traction;
            r.slip_path     = pair.state.slip_path;
            r.friction      = pair.trial.friction;
            r.rupture_time  = pair.rupture_time;
            r.status        = static_cast<int>(pair.trial.status);
            mine.push_back(r);
          }
      const auto all = dealii::Utilities::MPI::gather(communicator, mine, 0);
      std::vector<NodeRecord> result;
      for (const auto &part : all)
        result.insert(result.end(), part.begin(), part.end());
      return result;
    }



    template <int dim>
    std::vector<std::vector<types::global_dof_index>>
    Fault<dim>::gather_faces() const
    {
      const auto all =
        dealii::Utilities::MPI::gather(communicator, owned_faces, 0);
      std::vector<std::vector<types::global_dof_index>> result;
      for (const auto &part : all)
        result.insert(result.end(), part.begin(), part.end());
      return result;
    }



    template <int dim>
    unsigned long
    Fault<dim>::status_signature() const
    {
      unsigned long signature = 0;
      for (const auto &pair : pairs)
        signature += (static_cast<unsigned long>(pair.trial.status) + 1) *
                     (pair.minus[0] % 1000003 + 1);
      return dealii::Utilities::MPI::sum(signature, communicator);
    }



    template <int dim>
    void
    Fault<dim>::set_time(const double time)
    {
      friction_law->set_time(time);
      current_time = time;
    }



    template <int dim>
    Tensor<1, dim>
    Fault<dim>::imposed_slip(const NodePair &pair, const double delay) const
    {
      const double t = current_time + delay - dynamic_start;
      forced_slip->set_time(t);
      const double       s = forced_slip->value(pair.location);
      std::ostringstream message;
      message << "<Fault/Forced slip/Slip> must be finite and >= 0 (m), but "
              << "is " << s << " at " << pair.location << " and t = " << t
              << " s.";
      AssertThrow(std::isfinite(s) && s >= 0, ExcMessage(message.str()));
      return s * pair.forced_direction;
    }



    template <int dim>
    void
    Fault<dim>::start_dynamic_phase(const double time)
    {
      friction_law->start_dynamic_phase(time);
      friction_law->enable_weakening(true);
      dynamic_start      = time;
      forced_slip_active = true;
      for (auto &pair : pairs)
        pair.slip_at_start = pair.slip;
      // Weakening counts the slip of the dynamic phase: a bonded zone
      // breaks when the dynamic phase starts.
      for (auto &pair : pairs)
        pair.state.slip_path = 0;
    }



    template <int dim>
    void
    Fault<dim>::start_loading_phase()
    {
      friction_law->enable_weakening(false);
      forced_slip_active = false;
    }



    template <int dim>
    unsigned int
    Fault<dim>::n_weakening() const
    {
      unsigned int n = 0;
      for (const auto &pair : pairs)
        if (pair.trial.status == ContactStatus::slip &&
            friction_law->can_weaken(to_3d(pair.location), pair.state))
          ++n;
      return dealii::Utilities::MPI::sum(n, communicator);
    }



    template <int dim>
    bool
    Fault<dim>::all_stuck() const
    {
      unsigned int n = 0;
      for (const auto &pair : pairs)
        if (pair.trial.status != ContactStatus::stick)
          ++n;
      return dealii::Utilities::MPI::sum(n, communicator) == 0;
    }



    template <int dim>
    unsigned int
    Fault<dim>::n_steeper_than_body(const VectorType &effective_diagonal) const
    {
      std::vector<double> &diagonal = pair_values[0];
      pair_dofs.gather(effective_diagonal.trilinos_vector()[0], diagonal);
      unsigned int n = 0;
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          const NodePair             &pair = pairs[k];
          const ContactResponse<dim> &r    = pair.trial;
          if (pair.forced || r.status != ContactStatus::slip ||
              r.friction_derivative >= 0)
            continue;
          const double   tn  = r.traction * pair.normal;
          const double   k_w = -r.friction_derivative * std::max(-tn, 0.);
          const double   p_t = pair.tangential_penalty;
          Tensor<1, dim> e   = r.traction - tn * pair.normal;
          if (e.norm() == 0 || k_w == 0)
            continue;
          e /= e.norm();
          // Where the weakening is steeper than the penalty the node's
          // traction snaps to its residual strength instead (counted by
          // Statistics::unstable_softening).
          if (k_w >= p_t)
            continue;
          const double softening = k_w * p_t / (p_t - k_w) * pair.area;
          // The stiffness of each side along e.
          const auto side = [&](const unsigned int first) {
            double d = 0;
            for (unsigned int c = 0; c < dim; ++c)
              d += e[c] * e[c] * diagonal[first + c];
            return d;
          };
          const double minus = side(2 * dim * k),
                       plus  = side(2 * dim * k + dim);
          if (minus > 0 && plus > 0 &&
              softening > minus * plus / (minus + plus))
            ++n;
        }
      return dealii::Utilities::MPI::sum(n, communicator);
    }



    template <int dim>
    void
    Fault<dim>::apply_tangent(const VectorType &x, VectorType &y) const
    {
      std::vector<double> &values = pair_values[0];
      pair_dofs.gather(x.trilinos_vector()[0], values);
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          const NodePair    &pair = pairs[k];
          const unsigned int m0 = 2 * dim * k, p0 = m0 + dim;
          // The block [D, -D; -D, D] times (x-, x+): -D j and D j, with the
          // jump j = x+ - x-.
          Tensor<1, dim> jump;
          for (unsigned int d = 0; d < dim; ++d)
            jump[d] = values[p0 + d] - values[m0 + d];
          const Tensor<1, dim> f = pair.area * (pair.trial.tangent * jump);
          for (unsigned int d = 0; d < dim; ++d)
            {
              values[m0 + d] = -f[d];
              values[p0 + d] = f[d];
            }
        }
      pair_dofs.scatter_add(values, y.trilinos_vector()[0]);
    }



    template <int dim>
    void
    Fault<dim>::prepare_pair_preconditioner(const VectorType &diagonal,
                                            const VectorType &free) const
    {
      pair_dofs.gather(diagonal.trilinos_vector()[0], pair_values[0]);
      pair_dofs.gather(free.trilinos_vector()[0], pair_values[1]);
      const std::vector<double> &ds = pair_values[0], &fs = pair_values[1];
      constexpr unsigned int     n = 2 * dim;
      pair_block_inverses.resize(pairs.size() * n * n);
      pair_point_inverses.resize(pairs.size() * n);
      FullMatrix<double> block(n, n), inverse(n, n);
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          const NodePair    &pair  = pairs[k];
          const unsigned int first = n * k;
          block                    = 0;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              {
                const double d = pair.area * pair.trial.tangent[i][j];
                block(i, j) += d;
                block(i, dim + j) -= d;
                block(dim + i, j) -= d;
                block(dim + i, dim + j) += d;
              }
          // Constrained DoFs: identity rows and columns.
          for (unsigned int i = 0; i < n; ++i)
            if (fs[first + i] == 0)
              for (unsigned int j = 0; j < n; ++j)
                block(i, j) = block(j, i) = 0;
          for (unsigned int i = 0; i < n; ++i)
            {
              const bool   is_free = (fs[first + i] != 0);
              const double d       = ds[first + i];
              block(i, i) += (is_free ? d : 1);
              // What the point-Jacobi part put into z at this entry.
              pair_point_inverses[first + i] = (is_free && d > 0) ? 1 / d : 1;
            }
          inverse.invert(block);
          std::copy(&inverse(0, 0),
                    &inverse(0, 0) + n * n,
                    pair_block_inverses.begin() + n * first);
        }
    }



    template <int dim>
    void
    Fault<dim>::precondition_pairs(const VectorType &r, VectorType &z) const
    {
      constexpr unsigned int n = 2 * dim;
      Assert(pair_block_inverses.size() == pairs.size() * n * n,
             ExcMessage("prepare_pair_preconditioner() must come first."));
      std::vector<double> &rs = pair_values[0];
      std::vector<double> &zs = pair_values[1];
      pair_dofs.gather(r.trilinos_vector()[0], rs);
      zs.resize(rs.size());
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          const unsigned int first   = n * k;
          const double      *inverse = pair_block_inverses.data() + n * first;
          for (unsigned int i = 0; i < n; ++i)
            {
              double solution = 0;
              for (unsigned int j = 0; j < n; ++j)
                solution += inverse[i * n + j] * rs[first + j];
              // z holds the point-Jacobi value here: add the difference.
              zs[first + i] =
                solution - pair_point_inverses[first + i] * rs[first + i];
            }
        }
      pair_dofs.scatter_add(zs, z.trilinos_vector()[0]);
    }



    template <int dim>
    Statistics
    Fault<dim>::statistics() const
    {
      Statistics s;
      double     area = 0, moment = 0, normal = 0, shear = 0, total_area = 0;
      unsigned   n_slip = 0, n_open = 0, unstable = 0;
      double     max_slip = 0, max_rate = 0;
      for (const auto &pair : pairs)
        {
          if (pair.trial.status == ContactStatus::slip)
            {
              ++n_slip;
              area += pair.area;
            }
          if (pair.trial.status == ContactStatus::open)
            ++n_open;
          if (pair.trial.unstable_softening)
            ++unstable;
          const double slip = (pair.slip - pair.slip_at_start).norm();
          max_slip          = std::max(max_slip, slip);
          max_rate          = std::max(max_rate, pair.state.slip_rate);
          moment += pair.shear_modulus * pair.area * slip;
          const double tn = pair.trial.traction * pair.normal;
          normal += pair.area * tn;
          shear += pair.area * (pair.trial.traction - tn * pair.normal).norm();
          total_area += pair.area;
        }
      total_area = dealii::Utilities::MPI::sum(total_area, communicator);
      if (total_area > 0)
        {
          s.mean_normal_traction =
            dealii::Utilities::MPI::sum(normal, communicator) / total_area;
          s.mean_shear_traction =
            dealii::Utilities::MPI::sum(shear, communicator) / total_area;
        }
      s.n_nodes        = n_global_split;
      s.n_slipping     = dealii::Utilities::MPI::sum(n_slip, communicator);
      s.n_open         = dealii::Utilities::MPI::sum(n_open, communicator);
      s.slipping_area  = dealii::Utilities::MPI::sum(area, communicator);
      s.seismic_moment = dealii::Utilities::MPI::sum(moment, communicator);
      s.max_slip       = dealii::Utilities::MPI::max(max_slip, communicator);
      s.max_slip_rate  = dealii::Utilities::MPI::max(max_rate, communicator);
      s.frictional_energy =
        dealii::Utilities::MPI::sum(frictional_energy, communicator);
      s.unstable_softening =
        dealii::Utilities::MPI::sum(unstable, communicator) > 0;
      return s;
    }



    template <int dim>
    unsigned int
    Fault<dim>::n_split_nodes() const
    {
      return n_global_split;
    }



    template <int dim>
    unsigned int
    Fault<dim>::n_welded_nodes() const
    {
      return n_global_welded;
    }



    template class Fault<2>;
    template class Fault<3>;
  } // namespace Fault
} // namespace rupture
