#include <rupture/base/utilities.h>
#include <rupture/simulator/simulator.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace rupture
{



  template <int dim>
  void
  Simulator<dim>::check_finite(const VectorType  &v,
                               const std::string &what,
                               const bool         overflowed) const
  {
    const double norm = v.l2_norm();
    if (std::isfinite(norm) && !overflowed)
      return;

    std::ostringstream message;
    message << "At step " << state.step << " (t = " << state.clock.phase_time
            << " s) the " << what << " is no longer finite, "
            << discretization.locate_largest(v)
            << "; the run was stopped before writing it. ";
    if (current_scheme() ==
        TimeIntegration::Scheme::explicit_central_difference)
      message << "The explicit scheme blew up: its time step "
              << state.time_step << " s against the stable limit "
              << stable_time_step << " s. Reduce <Time integration/Time step>.";
    else if (fault)
      message << "Likely causes: fault penalties far above the stiffness "
                 "of the elements next to the fault, slip weakening steeper "
                 "than <Fault/Tangential penalty>, or extreme loads or "
                 "material constants. Lower the penalties or the time step.";
    else
      message << "Likely cause: extreme loads or material constants. Check "
                 "them.";
    AssertThrow(false, ExcMessage(message.str()));
  }



  template <int dim>
  void
  Simulator<dim>::compute_acceleration(const VectorType &load)
  {
    // M a_0 = f - K u_0 - C v_0 on the free DoFs.
    VectorType r(load), tmp(load);
    elastic_system.apply_stiffness(state.displacement, tmp);
    r -= tmp;
    elastic_system.damping_force(state.velocity, tmp);
    r -= tmp;
    r -= energy.contact_force;
    discretization.increment_constraints().set_zero(r);
    elastic_system.solve_mass(r, state.acceleration);
  }



  template <int dim>
  void
  Simulator<dim>::interpolate_initial_conditions()
  {
    // Interpolate the initial fields at the support points of the DoFs. A
    // fault's initial slip velocity moves each side rigidly at half of it
    // (the minus side has FE index 0, the plus side 1). A value that is not
    // finite is an input error, reported by every process.
    const Tensor<1, dim> half_slip_velocity =
      fault ? 0.5 * fault->initial_slip_velocity_of_sides() : Tensor<1, dim>();
    std::string error;
    discretization.for_each_support_point(
      [](const auto &cell) { return cell->is_locally_owned(); },
      [&](const auto                                 &cell,
          const std::vector<types::global_dof_index> &dofs,
          const std::vector<Point<dim>>              &points) {
        const auto  &fe   = cell->get_fe();
        const double side = (fault && cell->active_fe_index() == 1) ? 1. : -1.;
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (discretization.locally_owned_dofs().is_element(dofs[i]))
            {
              const unsigned int c =
                fe.system_to_component_index(i).first % dim;
              const double u =
                initial_conditions.displacement->value(points[i], c);
              const double v = initial_conditions.velocity->value(points[i], c);
              state.displacement(dofs[i]) = u;
              state.velocity(dofs[i])     = v + side * half_slip_velocity[c];
              if (error.empty() && !(std::isfinite(u) && std::isfinite(v)))
                {
                  std::ostringstream text;
                  text << "<Initial conditions/"
                       << (std::isfinite(u) ? "Velocity" : "Displacement")
                       << "> is not finite at (" << points[i] << "), component "
                       << c
                       << ". Allowed: expressions that are finite "
                          "throughout the body.";
                  error = text.str();
                }
            }
      });
    rupture::Utilities::throw_if_any(error, communicator);
    state.displacement.compress(VectorOperation::insert);
    state.velocity.compress(VectorOperation::insert);
    discretization.distribute_hanging(state.displacement);
    discretization.distribute_hanging(state.velocity);
  }



  template <int dim>
  void
  Simulator<dim>::set_applied_force(const VectorType &load,
                                    const VectorType &ku,
                                    const VectorType &ma)
  {
    energy.applied_force = load;
    for (const auto i : discretization.locally_owned_dofs())
      if (discretization.hanging_constraints().is_constrained(i))
        energy.applied_force(i) = 0;
      else if (discretization.increment_constraints().is_constrained(i) ||
               current_scheme() == TimeIntegration::Scheme::quasi_static)
        energy.applied_force(i) =
          ku(i) + ma(i) + energy.damping_force(i) + energy.contact_force(i);
    energy.applied_force.compress(VectorOperation::insert);
  }



  template <int dim>
  void
  Simulator<dim>::initialize_state()
  {
    TimerOutput::Scope t(timer, "Initial state");

    // The initial fields were interpolated in the constructor
    // (interpolate_initial_conditions()).
    VectorType load(discretization.locally_owned_dofs(), communicator);
    elastic_system.assemble_load(0, load);
    energy.contact_force = 0;
    if (fault && fault->uses_split_nodes())
      {
        // The fault traction that the initial state calls for: a prestress
        // above the strength makes the fault slip from the first step.
        VectorType r(load), tmp(load);
        elastic_system.apply_stiffness(state.displacement, tmp);
        r -= tmp;
        elastic_system.damping_force(state.velocity, tmp);
        r -= tmp;
        initial_split_node_force(r, energy.contact_force);
      }
    else if (fault)
      newton.add_contact_force(energy.contact_force);

    if (current_scheme() == TimeIntegration::Scheme::quasi_static)
      {
        state.velocity     = 0;
        state.acceleration = 0;
      }
    else
      {
        discretization.set_kinematic_velocity(state.velocity, state.time);
        compute_acceleration(load);
      }

    // Forces and energies of the initial state.
    VectorType ku(load);
    elastic_system.apply_stiffness(state.displacement, ku);
    elastic_system.damping_force(state.velocity, energy.damping_force);
    VectorType ma(load);
    ma = 0;
    if (current_scheme() != TimeIntegration::Scheme::quasi_static)
      elastic_system.apply_mass(state.acceleration, ma);
    // The force the body is in balance with at the start. A quasi-static
    // run follows an equilibrium path, on which the loads grow from the
    // internal force K u_0 to their full value within the first step.
    set_applied_force(load, ku, ma);

    discretization.hanging_constraints().set_zero(ku);
    energy.strain = 0.5 * (state.displacement * ku);
    VectorType mv(load);
    if (current_scheme() != TimeIntegration::Scheme::quasi_static)
      {
        elastic_system.apply_mass(state.velocity, mv);
        discretization.hanging_constraints().set_zero(mv);
        energy.kinetic = 0.5 * (state.velocity * mv);
      }
    energy.external_work       = 0;
    energy.damping_dissipation = 0;
    energy.absorbed            = 0;
    if (elastic_system.has_absorbing())
      {
        energy.absorbing_force.reinit(load);
        elastic_system.absorbing_force(state.velocity, energy.absorbing_force);
      }
    energy.initial = energy.kinetic + energy.strain;
  }



  template <int dim>
  void
  Simulator<dim>::initial_split_node_force(const VectorType &residual,
                                           VectorType       &force)
  {
    TimerOutput::Scope t(timer, "Fault split nodes");
    // The initial acceleration uses the lumped mass alone (see
    // compute_acceleration()).
    VectorType inverse(residual);
    for (const auto i : discretization.locally_owned_dofs())
      inverse(i) = (elastic_system.lumped_mass()(i) > 0 &&
                    !discretization.increment_constraints().is_constrained(i)) ?
                     1. / elastic_system.lumped_mass()(i) :
                     0.;
    inverse.compress(VectorOperation::insert);
    fault->assemble_split_node(state.displacement,
                               state.velocity,
                               residual,
                               inverse,
                               state.time_step,
                               time_parameters.gamma,
                               force);
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
