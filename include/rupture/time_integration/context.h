#ifndef rupture_time_integration_context_h
#define rupture_time_integration_context_h

#include <rupture/operators/elastic_system.h>
#include <rupture/solver/newton.h>
#include <rupture/solver/nonlinear_step.h>
#include <rupture/time_integration/energy_budget.h>
#include <rupture/time_integration/kinematics.h>
#include <rupture/time_integration/newmark.h>
#include <rupture/time_integration/time_state.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

namespace rupture
{
  namespace Fault
  {
    template <int dim>
    class Fault;
  }

  namespace TimeIntegration
  {
    /**
     * Everything a time integrator works with, by reference: the state it
     * advances and the energy budget it keeps, the elastic system, the
     * nonlinear solver, the discretization's constraints, the fault (null
     * without one), Newton's controls and status, and where to time and
     * print. The integrators hold a Context and nothing of the simulator
     * that owns these.
     */
    template <int dim>
    struct Context
    {
      TimeState                        &state;
      EnergyBudget                     &energy;
      const Parameters                 &time_parameters;
      Operators::ElasticSystem         &system;
      Solver::NonlinearStep            &nonlinear;
      const Kinematics                 &kinematics;
      Fault::Fault<dim>                *fault;
      Solver::NewtonStatus             &newton;
      const Solver::NewtonParameters   &newton_parameters;
      dealii::TimerOutput              &timer;
      const dealii::ConditionalOStream &pcout;
    };
  } // namespace TimeIntegration
} // namespace rupture

#endif
