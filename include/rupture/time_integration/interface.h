#ifndef rupture_time_integration_interface_h
#define rupture_time_integration_interface_h

#include <rupture/time_integration/context.h>
#include <rupture/time_integration/newmark.h>

#include <memory>
#include <vector>

namespace rupture
{
  namespace TimeIntegration
  {
    /**
     * A time integrator: it steps a TimeState (displacement, velocity,
     * acceleration, time) and the fault's state over one time step and
     * keeps the energy budget, with what its Context offers: the elastic
     * system, the nonlinear solver, the discretization's constraints and
     * the fault. Each scheme is a class of its own that keeps its own work
     * vectors and step control; the simulator creates one per phase of the
     * run (create()) and calls step() from its time loop. An integrator
     * knows nothing of the simulator.
     */
    template <int dim>
    class Interface
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      /**
       * An integrator working with @p context, its steps chosen by the
       * controller <Time integration/Step controller> names, starting from
       * the state's current time step (the phase's).
       */
      explicit Interface(const Context<dim> &context)
        : context(context)
        , controller(
            create_step_controller(context.time_parameters.step_controller,
                                   context.state.time_step))
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
       * After the mesh changed under the phase (the state interpolated to
       * the new mesh, prepare() called again): move the displacement into
       * balance with the carried velocity and acceleration, where the
       * scheme can. A loaded body's interpolated displacement is not in
       * balance on a finer mesh (its stresses were the coarse mesh's), and
       * the imbalance would otherwise act on the new nodes as a sudden
       * force. Returns the number of Newton iterations, 0 where the scheme
       * does nothing (default); if the solve fails (Solver::NewtonFailure,
       * or the linear solver's error where no boundary holds a part of
       * the body) it throws with the state as it was. Collective.
       */
      virtual unsigned int
      balance_displacement()
      {
        return 0;
      }

      /**
       * Whether the steps change from step to step (a controller other than
       * "fixed"): the time loop then asks next_time_step() before each step
       * and goes by time, not by a number of steps.
       */
      bool
      adaptive_steps() const
      {
        return controller->adaptive();
      }

      /**
       * The step the controller asks for next, from the fault's state
       * after the last accepted step. Collective.
       */
      double
      next_time_step() const;

      /**
       * What a checkpoint keeps of the integrator between steps (its step
       * controller's state, the implicit scheme's sub-stepping after step
       * cuts), as records named "integrator/...", and its restore after
       * prepare().
       */
      void
      save(BinaryIO::Records &records) const
      {
        controller->save(records);
        save_scheme(records);
      }
      void
      load(const BinaryIO::Records &records)
      {
        controller->load(records);
        load_scheme(records);
      }

    protected:
      Context<dim>                    context;
      std::unique_ptr<StepController> controller;

      /// The scheme's own part of save() and load(): nothing by default.
      virtual void
      save_scheme(BinaryIO::Records &) const
      {}
      virtual void
      load_scheme(const BinaryIO::Records &)
      {}

      /**
       * After the solve of a step from @p old_displacement: accept the
       * fault state (and add the work of its contact forces) and update
       * the energy budget by the trapezoidal rule, with the step's
       * @p load, the @p residual of its solve and the damping force
       * @p new_damping_force at its end.
       */
      /**
       * The static residual of the state's displacement: @p residual =
       * @p forces - K u - F_contact(u) (the contact forces from the fault's
       * return mapping at u); @p work is scratch.
       */
      void
      static_residual(const VectorType &forces,
                      VectorType       &residual,
                      VectorType       &work)
      {
        Context<dim> &s = context;
        residual        = forces;
        s.system.apply_stiffness(s.state.displacement, work);
        residual -= work;
        if (s.fault)
          {
            work = 0;
            s.nonlinear.add_contact_force(work);
            residual -= work;
          }
      }

      void
      accept_step(const VectorType &old_displacement,
                  const VectorType &load,
                  const VectorType &residual,
                  const VectorType &new_damping_force);
    };

    /**
     * The integrator of @p scheme working with @p context.
     */
    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(const Scheme scheme, const Context<dim> &context);
  } // namespace TimeIntegration
} // namespace rupture

#endif
