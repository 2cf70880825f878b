#include <rupture/base/utilities.h>
#include <rupture/fault/fault.h>
#include <rupture/fault/location_index.h>
#include <rupture/fault/radiation_damping.h>

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
#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace rupture
{
  namespace Fault
  {
    double
    read_radiation_damping(const std::string &entry)
    {
      const std::string text = dealii::Utilities::trim(entry);
      if (text == "auto")
        return -1;
      std::istringstream in(text);
      double             value = 0;
      in >> value;
      AssertThrow(!in.fail() && in.eof() && std::isfinite(value) && value >= 0,
                  ExcMessage("<Fault/Radiation damping> = '" + text +
                             "' is neither a number >= 0 (Pa s/m) nor "
                             "'auto'. Allowed: a number >= 0 or 'auto' (half "
                             "the shear impedance across the fault, from the "
                             "material)."));
      return value;
    }



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
        prm.declare_entry(
          "Split-node friction time",
          "centred",
          Patterns::Selection("centred|end of step"),
          "With 'traction at split nodes' and a friction law of the slip "
          "rate: when the friction is evaluated. 'centred' (second order "
          "in time): the traction of a step meets the strength at the slip "
          "rate of that instant (the mean of the slip rates of the steps "
          "before and after it) with the state evolved up to it over the "
          "slip of the step before, as the central-difference scheme holds "
          "velocities. 'end of step': the former update, the strength at "
          "the slip rate of the next step with the state evolved over it "
          "(first order in time; kept for comparison). Laws of the slip "
          "path (slip weakening) are the same with both.");
        prm.declare_entry(
          "Penalty friction time",
          "end of step",
          Patterns::Selection("end of step|centred"),
          "With 'penalty contact' and a friction law of the slip rate: "
          "when the friction is met. 'end of step' (first order in time): "
          "the traction at the step's end meets the strength at the step's "
          "mean slip rate with the state evolved over the whole step. "
          "'centred' (second order, the implicit midpoint rule): the mean "
          "of the tractions at the step's start and end meets the strength "
          "at the mean slip rate with the state evolved over half the "
          "step; the right choice for earthquake cycles with the 'rate and "
          "state' step controller (doc/verification.md, spring-slider). "
          "Laws of the slip path (slip weakening) are the same with both.");
        prm.declare_entry(
          "Radiation damping",
          "0",
          Patterns::Anything(),
          "eta (Pa s/m): the quasi-dynamic approximation of the waves a "
          "slipping fault radiates (Rice 1993): the shear strength gains "
          "eta V at slip rate V, as the SCEC SEAS benchmarks' quasi-dynamic "
          "problems ask with eta = mu / (2 c_s) (half the shear impedance; "
          "4.62e6 for their rho = 2670 kg/m^3, c_s = 3464 m/s). A number "
          ">= 0, or 'auto': at each fault node half the shear impedance "
          "across the fault, sqrt(rho mu_n) / 2, with mu_n the material's "
          "shear stiffness across the fault plane (for an anisotropic "
          "material from its tensor: the mean of the Christoffel matrix's "
          "eigenvalues in the fault plane; mu / (2 c_s) for an isotropic "
          "one) and rho its density there. With 'penalty contact' in "
          "quasi-static phases, where no wave carries the energy away; 0 "
          "(the default) for none. Not with 'traction at split nodes' "
          "(explicit dynamics radiates the waves itself).");
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
        prm.declare_entry(
          "Initial slip velocity",
          "",
          Patterns::Anything(),
          "Velocity (m/s) of the plus side relative to the minus side at "
          "t = 0, one number per dimension, e.g. '1e-12, 0, 0': each side "
          "starts moving rigidly at plus or minus half of it (added to "
          "<Initial conditions/Initial velocity>), as the SCEC rate-and-state "
          "benchmarks start (particle velocity +-V/2 on the two sides). Set "
          "the friction law's <Initial slip rate> to its magnitude. Empty "
          "for none.");
        prm.enter_subsection("Traction perturbation");
        {
          prm.declare_entry(
            "Traction",
            "",
            Patterns::Anything(),
            "A traction (Pa) added to <Fault/Initial traction> in the "
            "dynamic phase to nucleate a rupture, as a vector function of x, "
            "y (, z), components separated by ';' (the same convention). It "
            "is multiplied by <Time function>. Empty for none. E.g. the "
            "smooth pulse of SCEC TPV101, Delta tau_0 F(r) with "
            "F = exp(r^2 / (r^2 - R^2)) for r < R = 3 km: '(x^2 + (z + "
            "7500)^2 < 9e6) ? 25e6 * exp((x^2 + (z + 7500)^2) / (x^2 + (z + "
            "7500)^2 - 9e6)) : 0; 0; 0'.");
          prm.declare_entry(
            "Time function",
            "1",
            Patterns::Anything(),
            "G(t), the factor of <Traction> as a function of t, the time "
            "(s) since the start of the dynamic phase, e.g. SCEC's smooth "
            "ramp over T = 1 s: '(t <= 0) ? 0 : ((t < 1) ? exp((t - 1)^2 / "
            "(t * (t - 2))) : 1)'. Must be finite.");
        }
        prm.leave_subsection();
        prm.enter_subsection("Anisotropic friction");
        {
          prm.declare_entry(
            "Strength ratio",
            "1",
            Patterns::Double(0.01, 100),
            "Anisotropic friction (the review paper's section 5): the set "
            "of admissible shear tractions is the ellipse |A^-1 tau| <= "
            "strength with A = diag(1, r) in the directions <First "
            "direction> (e_1, projected onto the fault) and e_2 = n x e_1: "
            "the strength along e_2 is r times that along e_1. Slip follows "
            "the subdifferential sliding rule (along the normal of the "
            "ellipse at the traction, not along the traction), and the "
            "friction law sees the slip measured as |A slip|. 1 (the "
            "default) is isotropic friction. In 2-D (plane strain) the fault's "
            "one shear direction must be an axis: <First direction> in the "
            "model plane and not normal to the fault (the in-plane slip "
            "sees the strength S, as isotropic friction) or normal to the "
            "plane (0, 0, 1: strength r S, slip measured r |slip|). Every fault model and friction "
            "law; a law of the slip rate sees the slip rate |A V|, and "
            "radiation damping acts on the slip rate as a vector.");
          prm.declare_entry("First direction",
                            "1, 0, 0",
                            Patterns::Anything(),
                            "The principal direction e_1 of the friction "
                            "ellipse (model coordinates; its projection "
                            "onto the fault plane is used and must not "
                            "vanish), e.g. the strike.");
        }
        prm.leave_subsection();
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
      fault->centred_split_node =
        (prm.get("Split-node friction time") == "centred");
      fault->centred_penalty = (prm.get("Penalty friction time") == "centred");
      // (-1: 'auto', half the shear impedance across the fault per pair.)
      fault->radiation_damping =
        read_radiation_damping(prm.get("Radiation damping"));
      AssertThrow(!fault->split_node_method || fault->radiation_damping == 0,
                  ExcMessage("<Fault/Radiation damping> = " +
                             prm.get("Radiation damping") +
                             " is for <Fault/Model> = penalty contact (its "
                             "quasi-static phases): with traction at split "
                             "nodes the explicit scheme radiates the waves "
                             "itself. Allowed: 0 with split nodes."));
      const std::string variables = (dim == 2 ? "x,y" : "x,y,z");
      fault->side_by_plane        = (prm.get("Plus side") == "plane");
      AssertThrow(
        !fault->side_by_plane ||
          dealii::Utilities::trim(prm.get("Plus side material ids")).empty(),
        ExcMessage("<Fault/Plus side material ids> is given, but <Fault/Plus "
                   "side> is 'plane' (its default), which tells the sides "
                   "apart by <Plane point> and <Plane normal> and ignores "
                   "the ids. Set <Fault/Plus side> = material ids to use "
                   "them, or leave <Plus side material ids> empty."));
      fault->plane_point = Point<dim>(Utilities::parse_vector<dim>(
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
      if (!dealii::Utilities::trim(prm.get("Initial slip velocity")).empty())
        fault->initial_slip_velocity =
          Utilities::parse_vector<dim>(prm.get("Initial slip velocity"),
                                       "Fault/Initial slip velocity");
      prm.enter_subsection("Traction perturbation");
      if (!dealii::Utilities::trim(prm.get("Traction")).empty())
        {
          fault->traction_perturbation =
            Utilities::parse_function<dim>(prm.get("Traction"),
                                           dim,
                                           "Fault/Traction perturbation/"
                                           "Traction",
                                           variables);
          fault->perturbation_time_function = Utilities::parse_function<1>(
            prm.get("Time function"),
            1,
            "Fault/Traction perturbation/Time function",
            "t");
        }
      prm.leave_subsection();
      prm.enter_subsection("Anisotropic friction");
      const double      r              = prm.get_double("Strength ratio");
      const std::string direction_text = prm.get("First direction");
      // (A 3-D vector also in 2-D.)
      const Tensor<1, 3> d =
        Utilities::parse_vector<3>(direction_text,
                                   "Fault/Anisotropic friction/First "
                                   "direction");
      prm.leave_subsection();
      AssertThrow(r == 1 || d.norm() > 0,
                  ExcMessage("<Fault/Anisotropic friction/First direction> "
                             "must not be the zero vector."));
      fault->friction_ellipse.a2 = r;
      for (unsigned int c = 0; c < dim; ++c)
        fault->friction_ellipse.direction[c] = d[c];
      if (dim == 2 && r != 1)
        {
          // In 2-D the fault's one shear direction is the in-plane
          // tangent, and plane strain keeps the slip in the plane: the
          // ellipse's axes must be the tangent and the normal z of the
          // model plane, and the set K is the interval |tau| <= a S with
          // a the ellipse's factor along the tangent (its slip rate a |V|).
          const double in_plane = std::hypot(d[0], d[1]);
          if (std::abs(d[2]) <= 1e-12 * d.norm())
            fault->friction_ellipse.a1 = 1; // tangent = first axis
          else if (in_plane <= 1e-12 * d.norm())
            {
              // The tangent is the second axis (strength r S).
              fault->friction_ellipse.a1        = r;
              fault->friction_ellipse.a2        = 1;
              fault->friction_ellipse.direction = 0;
            }
          else
            AssertThrow(false,
                        ExcMessage(
                          "<Fault/Anisotropic friction/First direction> = " +
                          direction_text +
                          " is oblique to the 2-D model plane: the friction "
                          "ellipse's axes would not be the fault's in-plane "
                          "direction and the normal to the plane, and its "
                          "sliding rule would move the slip out of the "
                          "plane, which plane strain forbids. Allowed in "
                          "2-D: a direction in the model plane (third "
                          "component 0: the in-plane slip has the strength "
                          "S along the first axis) or normal to it (0, 0, "
                          "1: the in-plane slip lies along the second axis, "
                          "strength <Strength ratio> times S)."));
        }
      // (In 2-D a first axis along the tangent leaves the in-plane
      // friction isotropic.)
      fault->anisotropic_friction =
        (fault->friction_ellipse.a1 != 1 ||
         (dim == 3 && fault->friction_ellipse.a2 != 1));
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
    void
    Fault<dim>::setup(
      const DoFHandler<dim> &dof_handler,
      const IndexSet        &locally_owned_dofs,
      const IndexSet &,
      AffineConstraints<double> &constraints,
      const std::function<std::array<double, 2>(types::material_id,
                                                const Tensor<1, dim> &,
                                                const Point<dim> &)>
                    &shear_across,
      const MPI_Comm comm)
    {
      communicator = comm;
      AssertThrow(dof_handler.get_fe_collection().size() == 2,
                  ExcInternalError());
      const FiniteElement<dim> &fe0 = dof_handler.get_fe(0);

      Interface interface;
      find_interface(dof_handler, constraints, interface);
      auto &fault_nodes                    = interface.fault_nodes;
      auto &welded_nodes                   = interface.welded_nodes;
      auto &fault_faces                    = interface.fault_faces;
      owned_faces                          = std::move(interface.owned_faces);
      const unsigned int n_interface_faces = interface.n_interface_faces;
      region_node_dofs.clear();
      for (const auto &[key, pair] : fault_nodes)
        {
          region_node_dofs.insert(pair.minus[0]);
          region_node_dofs.insert(pair.plus[0]);
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
      // Pairs on hanging nodes (a fault face finer than its neighbour on
      // both sides). Their displacements follow the pairs they hang from.
      // With penalty contact each keeps its own contact and area, and the
      // constraints carry its force to those pairs. The split-node method
      // keeps the tractions at free pairs only: a hanging pair passes its
      // area to the pairs it hangs from (the area of their constrained
      // shape functions) and its traction is theirs interpolated.
      AffineConstraints<double> hanging;
      hanging.copy_from(constraints);
      hanging.close();
      {
        unsigned int n_hanging = 0;
        for (const auto &[key, pair] : fault_nodes)
          if (locally_owned_dofs.is_element(pair.minus[0]) &&
              hanging.is_constrained(pair.minus[0]))
            ++n_hanging;
        any_hanging = dealii::Utilities::MPI::sum(n_hanging, communicator) > 0;
      }
      if (split_node_method && any_hanging)
        {
          VectorType passed(locally_owned_dofs, communicator);
          for (const auto &[key, pair] : fault_nodes)
            if (locally_owned_dofs.is_element(pair.minus[0]) &&
                hanging.is_constrained(pair.minus[0]))
              for (unsigned int c = 0; c < dim; ++c)
                for (const auto &[master, weight] :
                     *hanging.get_constraint_entries(pair.minus[c]))
                  passed.add(std::vector<types::global_dof_index>{master},
                             std::vector<double>{weight *
                                                 area_normal(pair.minus[c])});
          passed.compress(VectorOperation::add);
          area_normal += passed;
        }

      // A set-up after the first keeps the committed state of every pair
      // whose location is unchanged (on this process).
      std::vector<NodePair>               previous;
      std::unique_ptr<LocationIndex<dim>> previous_index;
      if (set_up)
        {
          previous = std::move(pairs);
          std::vector<Point<dim>> locations;
          for (const auto &pair : previous)
            locations.push_back(pair.location);
          previous_index =
            std::make_unique<LocationIndex<dim>>(locations,
                                                 location_tolerance(previous));
        }
      new_pair_indices.clear();
      pairs.clear();
      // A check that fails at one pair is reported by every process
      // (Utilities::throw_if_any()), not only by the one that owns it.
      std::string error;
      for (auto &[key, pair] : fault_nodes)
        if (locally_owned_dofs.is_element(pair.minus[0]) && error.empty())
          try
            {
              for (unsigned int c = 0; c < dim; ++c)
                pair.normal[c] = area_normal(pair.minus[c]);
              pair.area = pair.normal.norm();
              AssertThrow(pair.area > 0, ExcInternalError());
              pair.normal /= pair.area;
              const auto [shear_modulus, density] =
                shear_across(pair.material, pair.normal, pair.location);
              pair.shear_modulus = shear_modulus;
              pair.radiation_damping =
                radiation_damping >= 0 ?
                  radiation_damping :
                  0.5 * std::sqrt(density * shear_modulus);
              if (friction_ellipse.a2 != 1 &&
                  friction_ellipse.direction.norm() > 0)
                {
                  const Tensor<1, dim> &d = friction_ellipse.direction;
                  std::ostringstream    where;
                  where << pair.location;
                  AssertThrow((d - (d * pair.normal) * pair.normal).norm() >
                                1e-6 * d.norm(),
                              ExcMessage(
                                "<Fault/Anisotropic friction/First direction> "
                                "is normal to the fault at (" +
                                where.str() +
                                "): its projection onto the fault plane, "
                                "the friction ellipse's first axis, "
                                "vanishes. Allowed: a direction that lies "
                                "in the fault plane or across it at an "
                                "angle (e.g. the strike)."));
                }
              pair.hanging = hanging.is_constrained(pair.minus[0]);
              {
                std::ostringstream where;
                where << pair.location;
                AssertThrow(pair.hanging ==
                              hanging.is_constrained(pair.plus[0]),
                            ExcMessage("The fault node at (" + where.str() +
                                       ") hangs on one side of the fault "
                                       "only: the cells on both sides of a "
                                       "fault face must be refined alike."));
              }
              if (split_node_method && pair.hanging)
                pair.area = 0;
              const Point<3> x = to_3d(pair.location);
              for (unsigned int c = 0; c < dim; ++c)
                pair.initial_traction[c] =
                  initial_traction->value(pair.location, c);
              {
                std::ostringstream text;
                text << "<Fault/Initial traction> is not finite at the fault "
                        "point ("
                     << pair.location << "): it is (" << pair.initial_traction
                     << ") Pa. Allowed: expressions that are finite on the "
                        "whole fault.";
                bool finite = true;
                for (unsigned int c = 0; c < dim; ++c)
                  finite = finite && std::isfinite(pair.initial_traction[c]);
                AssertThrow(finite, ExcMessage(text.str()));
              }
              pair.background_traction = pair.initial_traction;
              // The fault slips from the start at its initial slip velocity
              // (along the fault).
              pair.slip_velocity =
                initial_slip_velocity -
                (initial_slip_velocity * pair.normal) * pair.normal;
              if (traction_perturbation)
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    pair.perturbation[c] =
                      traction_perturbation->value(pair.location, c);
                    std::ostringstream text;
                    text << "<Fault/Traction perturbation/Traction> is not "
                            "finite at the fault point ("
                         << pair.location << "): its component " << c << " is "
                         << pair.perturbation[c]
                         << " Pa. Allowed: expressions that are finite on the "
                            "whole fault.";
                    AssertThrow(std::isfinite(pair.perturbation[c]),
                                ExcMessage(text.str()));
                  }
              pair.normal_penalty = normal_penalty->value(pair.location);
              pair.tangential_penalty =
                tangential_penalty->value(pair.location);
              std::ostringstream where, values;
              where << pair.location;
              values << pair.normal_penalty << " and "
                     << pair.tangential_penalty;
              AssertThrow(split_node_method ||
                            (pair.normal_penalty > 0 &&
                             pair.tangential_penalty > 0 &&
                             std::isfinite(pair.normal_penalty) &&
                             std::isfinite(pair.tangential_penalty)),
                          ExcMessage("<Fault/Normal penalty> and <Fault/"
                                     "Tangential penalty> must be finite and "
                                     "> 0 (Pa/m), but are " +
                                     values.str() + " at (" + where.str() +
                                     ")."));
              // A penalty many orders of magnitude above the stiffness of
              // the elements next to the fault (about mu / h per area)
              // leaves their equations in the round-off of the contact's,
              // and overflows the system matrix long before it is infinite.
              if (!split_node_method && pair.shear_modulus > 0)
                {
                  const double h =
                    std::pow(pair.area, 1. / std::max(dim - 1, 1));
                  const double element_stiffness = pair.shear_modulus / h;
                  const double largest =
                    std::max(pair.normal_penalty, pair.tangential_penalty);
                  std::ostringstream limit;
                  limit << 1e10 * element_stiffness;
                  AssertThrow(largest <= 1e10 * element_stiffness,
                              ExcMessage(
                                "<Fault/Normal penalty> and <Fault/"
                                "Tangential penalty> are " +
                                values.str() + " Pa/m at (" + where.str() +
                                "), more than 1e10 times the stiffness of "
                                "the elements next to the fault there "
                                "(shear modulus / element size): the elastic "
                                "equations would be lost in the round-off of "
                                "the contact's. Allowed: up to " +
                                limit.str() +
                                " Pa/m here (the paper's 5e11 Pa/m is about "
                                "1e4 times the elements' stiffness at 2.5 "
                                "km)."));
                }
              {
                const double tn = pair.initial_traction * pair.normal;
                // (With anisotropic friction the ratio's shear is measured
                // against the ellipse, |A^-1 tau_0|.)
                const double ts =
                  traction_measure(pair,
                                   pair.initial_traction - tn * pair.normal);
                friction_law->initialize_state(
                  x,
                  (tn < 0) ? ts / (-tn) :
                             std::numeric_limits<double>::quiet_NaN(),
                  pair.state);
                pair.state.slip_rate = slip_measure(pair, pair.slip_velocity);
                pair.rupture_rate    = pair.slip_velocity.norm();
              }
              if (forced_region->value(pair.location) != 0)
                {
                  pair.forced = true;
                  pair.forced_direction =
                    forced_direction -
                    (forced_direction * pair.normal) * pair.normal;
                  AssertThrow(pair.forced_direction.norm() >
                                1e-6 * forced_direction.norm(),
                              ExcMessage(
                                "<Fault/Forced slip/Direction> is normal to "
                                "the fault at (" +
                                where.str() +
                                "): it has no component along the fault to "
                                "slip in."));
                  pair.forced_direction /= pair.forced_direction.norm();
                }
              if (previous_index)
                {
                  const unsigned int j = previous_index->find(pair.location);
                  if (j != LocationIndex<dim>::invalid)
                    carry_state(previous[j], pair);
                  else
                    new_pair_indices.push_back(pairs.size());
                }
              pairs.push_back(pair);
            }
          catch (const ExceptionBase &e)
            {
              error = Utilities::message_of(e);
            }
      Utilities::throw_if_any(error, communicator);

      {
        // The split-node method and the matrix-free contact tangent read
        // and write the pairs' DoFs alone (minus side then plus side, dim
        // entries each, pair by pair).
        std::vector<types::global_dof_index> indices;
        for (const auto &pair : pairs)
          for (const auto *side : {&pair.minus, &pair.plus})
            for (const auto dof : *side)
              indices.push_back(dof);
        pair_dofs.reinit(locally_owned_dofs, indices, communicator);
        std::vector<typename Operators::PairBlocks<dim>::PairDofs> pair_list;
        for (const auto &pair : pairs)
          pair_list.emplace_back(pair.minus, pair.plus);
        contact_blocks.reinit(pair_list, locally_owned_dofs, communicator);
        if (!split_node_method && any_hanging)
          {
            // The matrix-free contact tangent of the pairs on hanging
            // nodes acts through the nodes they follow.
            std::vector<
              std::tuple<unsigned int, types::global_dof_index, double>>
              entries;
            for (unsigned int k = 0; k < pairs.size(); ++k)
              if (pairs[k].hanging)
                for (unsigned int s = 0; s < 2; ++s)
                  for (unsigned int c = 0; c < dim; ++c)
                    for (const auto &[master, weight] :
                         *hanging.get_constraint_entries(
                           s == 0 ? pairs[k].minus[c] : pairs[k].plus[c]))
                      entries.emplace_back(2 * dim * k + s * dim + c,
                                           master,
                                           weight);
            contact_blocks.set_hanging(entries,
                                       locally_owned_dofs,
                                       communicator);
          }
        // The nodal forces A T_0 on both sides of every pair.
        double force_square = 0;
        for (const auto &pair : pairs)
          force_square +=
            2 * pair.area * pair.area * pair.initial_traction.norm_square();
        initial_force_scale =
          std::sqrt(dealii::Utilities::MPI::sum(force_square, communicator));
        // The split-node method interpolates the traction of a hanging
        // pair from the minus DoFs it follows.
        hanging_sources.clear();
        if (split_node_method && any_hanging)
          {
            std::vector<types::global_dof_index> masters;
            for (unsigned int k = 0; k < pairs.size(); ++k)
              if (pairs[k].hanging)
                for (unsigned int c = 0; c < dim; ++c)
                  for (const auto &[master, weight] :
                       *hanging.get_constraint_entries(pairs[k].minus[c]))
                    {
                      hanging_sources.push_back({k, c, weight});
                      masters.push_back(master);
                    }
            hanging_gather.reinit(locally_owned_dofs, masters, communicator);
            traction_change.reinit(locally_owned_dofs, communicator);
          }
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
      n_global_new = dealii::Utilities::MPI::sum(
        static_cast<unsigned int>(new_pair_indices.size()), communicator);
      const unsigned int n_faces =
        dealii::Utilities::MPI::sum(n_interface_faces, communicator);
      AssertThrow(n_faces > 0,
                  ExcMessage("The fault interface is empty: no cell of the "
                             "plus side touches a cell of the minus side. "
                             "Check <Fault/Plus side> and its plane or "
                             "material ids."));
      // The traction of a perturbation at the present time.
      if (set_up)
        set_time(current_time);
      set_up = true;
    }



    template <int dim>
    double
    Fault<dim>::location_tolerance(const std::vector<NodePair> &of) const
    {
      // A millionth of the smallest node spacing (the tributary length,
      // or the root of the tributary area, of a pair).
      double spacing = std::numeric_limits<double>::max();
      for (const auto &pair : of)
        if (pair.area > 0)
          spacing =
            std::min(spacing, std::pow(pair.area, 1. / std::max(dim - 1, 1)));
      spacing = dealii::Utilities::MPI::min(spacing, communicator);
      return 1e-6 * spacing;
    }



    template <int dim>
    void
    Fault<dim>::carry_state(const NodePair &from, NodePair &to)
    {
      static_cast<NodeState<dim> &>(to) =
        static_cast<const NodeState<dim> &>(from);
      to.trial               = from.trial;
      to.trial_slip          = from.trial_slip;
      to.trial_state         = from.trial_state;
      to.trial_slip_velocity = from.trial_slip_velocity;
    }



    template class Fault<2>;
    template class Fault<3>;
  } // namespace Fault
} // namespace rupture
