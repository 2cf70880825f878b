#ifndef rupture_time_integration_time_state_h
#define rupture_time_integration_time_state_h

#include <rupture/time_integration/phase_clock.h>

#include <deal.II/lac/trilinos_vector.h>

namespace rupture
{
  namespace TimeIntegration
  {
    /**
     * The state a time integrator advances: the displacement, velocity and
     * acceleration fields at the current time, the time itself, the step
     * that led there and its number. The simulator owns one; the
     * integrators, the energy budget, the output and the checkpoints read
     * and write it through this one object.
     *
     * `time` is the absolute time of the run (s); `clock` knows when the
     * current phase and the dynamic phase started, and the time since.
     */
    struct TimeState
    {
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      VectorType displacement;
      VectorType velocity;
      VectorType acceleration;
      /// Absolute time (s) of the fields.
      double time = 0;
      /// The step being taken, or the last one taken (s).
      double time_step = 0;
      /// Steps taken since the start of the run.
      unsigned int step = 0;
      /// The clock of the run's phases (loading, dynamic).
      PhaseClock clock;
    };
  } // namespace TimeIntegration
} // namespace rupture

#endif
