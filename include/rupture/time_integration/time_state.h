#ifndef rupture_time_integration_time_state_h
#define rupture_time_integration_time_state_h

#include <rupture/base/binary_io.h>
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

      /// The scalars (not the fields) as named checkpoint records.
      void
      save(BinaryIO::Records &records) const
      {
        records["time/time"]               = time;
        records["time/time step"]          = time_step;
        records["time/step"]               = step;
        records["time/phase time"]         = clock.phase_time;
        records["time/dynamic start"]      = clock.dynamic_start;
        records["time/in dynamic phase"]   = clock.in_dynamic_phase;
        records["time/phase start time"]   = clock.phase_start_time;
        records["time/steps in phase"]     = clock.steps_in_phase;
        records["time/segment start time"] = clock.segment_start_time;
        records["time/segment first step"] = clock.segment_first_step;
        // (Adaptive steps only: the fixed steps' checkpoints stay as they
        // were.)
        if (clock.compensation != 0)
          records["time/compensation"] = clock.compensation;
      }
      void
      load(const BinaryIO::Records &records)
      {
        using BinaryIO::record;
        time      = record(records, "time/time");
        time_step = record(records, "time/time step");
        step      = static_cast<unsigned int>(record(records, "time/step"));
        clock.phase_time       = record(records, "time/phase time");
        clock.dynamic_start    = record(records, "time/dynamic start");
        clock.in_dynamic_phase = record(records, "time/in dynamic phase") != 0;
        clock.phase_start_time = record(records, "time/phase start time");
        clock.steps_in_phase =
          static_cast<unsigned int>(record(records, "time/steps in phase"));
        // (Checkpoints before variable steps had one segment per phase.)
        const auto start = records.find("time/segment start time");
        const auto first = records.find("time/segment first step");
        clock.segment_start_time =
          (start != records.end()) ? start->second : clock.phase_start_time;
        clock.segment_first_step = (first != records.end()) ?
                                     static_cast<unsigned int>(first->second) :
                                     0;
        const auto compensation  = records.find("time/compensation");
        clock.compensation =
          (compensation != records.end()) ? compensation->second : 0;
      }
    };
  } // namespace TimeIntegration
} // namespace rupture

#endif
