#ifndef rupture_time_integration_interface_h
#define rupture_time_integration_interface_h

#include <rupture/time_integration/newmark.h>

#include <memory>
#include <vector>

namespace rupture
{
  template <int dim>
  class Simulator;

  namespace TimeIntegration
  {
    /**
     * A time integrator: it steps the simulator's state (displacement,
     * velocity, acceleration, fault state, energy budget) over one time
     * step with the operators the simulator owns (elastic operator,
     * preconditioners, the fault's coupling, Newton's method). Each scheme
     * is a class of its own that keeps its own work vectors and step
     * control; the simulator creates one per phase of the run (create())
     * and calls step() from its time loop.
     *
     * As ASPECT's SimulatorAccess, the integrators are friends of the
     * simulator: they read and update its state in place rather than
     * copying it through an interface at every step.
     */
    template <int dim>
    class Interface
    {
    public:
      explicit Interface(Simulator<dim> &simulator)
        : simulator(simulator)
      {}
      virtual ~Interface() = default;

      virtual Scheme
      scheme() const = 0;

      /**
       * Build what the steps of a phase need, for the simulator's current
       * time step: the effective stiffness and its preconditioner
       * (implicit, quasi-static) or the diagonal and work vectors
       * (explicit).
       */
      virtual void
      prepare() = 0;

      /**
       * One step of the simulator's time step, ending at its current time.
       */
      virtual void
      step() = 0;

      /**
       * What a checkpoint keeps of the integrator between steps (the
       * implicit scheme's sub-stepping after step cuts), and its restore
       * after prepare(). Nothing by default.
       */
      virtual std::vector<double>
      saved_state() const
      {
        return {};
      }
      virtual void
      restore_state(const std::vector<double> &)
      {}

    protected:
      Simulator<dim> &simulator;
    };

    /**
     * The integrator of @p scheme for @p simulator.
     */
    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(const Scheme scheme, Simulator<dim> &simulator);
  } // namespace TimeIntegration
} // namespace rupture

#endif
