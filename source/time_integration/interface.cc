#include <rupture/fault/fault.h>
#include <rupture/time_integration/central_difference.h>
#include <rupture/time_integration/implicit_newmark.h>
#include <rupture/time_integration/quasi_static.h>

#include <limits>

namespace rupture
{
  namespace TimeIntegration
  {
    template <int dim>
    double
    Interface<dim>::next_time_step() const
    {
      StepInputs inputs;
      inputs.state_evolution_time = context.fault ?
                                      context.fault->state_evolution_time() :
                                      std::numeric_limits<double>::infinity();
      return controller->next(inputs);
    }



    template <int dim>
    void
    Interface<dim>::accept_step(const VectorType &old_displacement,
                                const VectorType &load,
                                const VectorType &residual,
                                const VectorType &new_damping_force)
    {
      Context<dim> &s = context;
      if (s.fault)
        {
          // The contact forces of the converged state, for the work done on
          // the fault, and the accepted fault state.
          VectorType force(s.state.displacement);
          force = 0;
          s.nonlinear.add_contact_force(force);
          VectorType increment(s.state.displacement);
          increment -= old_displacement;
          s.energy.fault_work +=
            0.5 * ((force * increment) + (s.energy.contact_force * increment));
          s.energy.contact_force = force;
          s.fault->commit(s.state.time_step, s.state.time);
        }
      controller->accept(s.state.time_step);

      // Work of the applied forces by the trapezoidal rule: loads on free
      // DoFs, reactions (load minus residual) on kinematically held ones.
      // On free DoFs the residual is the error of the solve, which thus
      // shows up in the energy balance instead of being hidden.
      // DoFs tied to others (hanging nodes, welded fault nodes) carry no
      // force of their own: their rows of K and M hold only a placeholder
      // diagonal, so they are left out of every energy.
      const dealii::AffineConstraints<double> &hanging =
        s.kinematics.hanging_constraints();
      const dealii::AffineConstraints<double> &increment_constraints =
        s.kinematics.increment_constraints();
      VectorType force(load);
      for (const auto i : s.kinematics.owned_dofs())
        if (increment_constraints.is_constrained(i) &&
            !hanging.is_constrained(i))
          force(i) = load(i) - residual(i);
      force.compress(dealii::VectorOperation::insert);

      VectorType increment(s.state.displacement);
      increment -= old_displacement;
      s.energy.external_work +=
        0.5 * ((force * increment) + (s.energy.applied_force * increment));
      s.energy.damping_dissipation +=
        0.5 * ((new_damping_force * increment) +
               (s.energy.damping_force * increment));
      s.energy.applied_force = force;
      s.energy.damping_force = new_damping_force;
      const bool dynamic     = (scheme() != Scheme::quasi_static);
      if (s.system.absorbing_damping() && dynamic)
        {
          // The dashpots' share, from the velocities at the ends of the
          // step (the schemes' damping force may use a predicted velocity
          // instead, so this split is exact only to O(dt)).
          VectorType f(load);
          s.system.absorbing_force(s.state.velocity, f);
          s.energy.absorbed +=
            0.5 * ((f * increment) + (s.energy.absorbing_force * increment));
          s.energy.absorbing_force = f;
        }

      VectorType tmp(load);
      s.system.apply_stiffness(s.state.displacement, tmp);
      hanging.set_zero(tmp);
      s.energy.strain = 0.5 * (s.state.displacement * tmp);
      if (dynamic)
        {
          s.system.apply_mass(s.state.velocity, tmp);
          hanging.set_zero(tmp);
          s.energy.kinetic = 0.5 * (s.state.velocity * tmp);
        }
    }



    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(const Scheme scheme, const Context<dim> &context)
    {
      switch (scheme)
        {
          case Scheme::implicit_newmark:
            return std::make_unique<ImplicitNewmark<dim>>(context);
          case Scheme::explicit_central_difference:
            return std::make_unique<CentralDifference<dim>>(context);
          case Scheme::quasi_static:
            return std::make_unique<QuasiStatic<dim>>(context);
        }
      return nullptr;
    }



    template class Interface<2>;
    template class Interface<3>;
    template std::unique_ptr<Interface<2>>
    create(const Scheme, const Context<2> &);
    template std::unique_ptr<Interface<3>>
    create(const Scheme, const Context<3> &);
  } // namespace TimeIntegration
} // namespace rupture
