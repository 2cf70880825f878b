#ifndef rupture_time_integration_step_controller_h
#define rupture_time_integration_step_controller_h

#include <rupture/base/binary_io.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>

namespace rupture
{
  namespace TimeIntegration
  {
    /**
     * The entries of <Time integration/Step controller>: which controller
     * chooses the time steps of a phase, and its bounds.
     */
    struct StepControllerParameters
    {
      /// Declare the subsection; call inside <Time integration>.
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /// Parse and check it; call inside <Time integration>.
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /// "fixed" or "rate and state".
      std::string name = "fixed";
      /// The fraction xi of the state evolution time L / V per step.
      double state_fraction = 0.1;
      double minimum_step   = 1e-3;
      double maximum_step   = 3.15576e7;
      /// A step is at most this factor longer than the one before.
      double growth_factor = 2;
    };

    /**
     * What a controller may base the next step on, gathered by the
     * integrator from the fault after the last accepted step.
     */
    struct StepInputs
    {
      /// The shortest time over which a fault point's friction state
      /// evolves (smallest L / V over the fault,
      /// Fault::state_evolution_time()), infinite where nothing slips or
      /// without a fault.
      double state_evolution_time;
    };

    /**
     * Chooses the time step of each step of a phase. The integrator owns
     * one and asks it for the next step before each step (next()), tells
     * it which step was taken (accept()) or failed (reject()), and keeps
     * its state in checkpoints (save(), load()).
     *
     * "fixed" keeps the phase's step (the loop counts steps as before);
     * "rate and state" is the rule of Lapusta et al. (2000) for slow and
     * fast slip alike: dt = xi min(L / V), between a minimum and a maximum
     * step, growing by at most a factor per step.
     */
    class StepController
    {
    public:
      virtual ~StepController() = default;

      /// The controller's name in the .prm.
      virtual std::string
      name() const = 0;

      /// Whether steps change from step to step (the loop then goes by
      /// time, not by a number of steps).
      virtual bool
      adaptive() const = 0;

      /// The next step from @p inputs and the steps before.
      virtual double
      next(const StepInputs &inputs) const = 0;

      /// A step of @p dt was taken.
      virtual void
      accept(const double dt) = 0;

      /// A step of @p dt failed and is taken again with a smaller one.
      virtual void
      reject(const double dt) = 0;

      /// The controller's state as records "integrator/step controller/...".
      virtual void
      save(BinaryIO::Records &records) const = 0;
      virtual void
      load(const BinaryIO::Records &records) = 0;
    };

    /**
     * The controller @p parameters name, starting from the phase's step
     * @p initial_step.
     */
    std::unique_ptr<StepController>
    create_step_controller(const StepControllerParameters &parameters,
                           const double                    initial_step);
  } // namespace TimeIntegration
} // namespace rupture

#endif
