#ifndef rupture_time_integration_phase_clock_h
#define rupture_time_integration_phase_clock_h

#include <cmath>

namespace rupture
{
  namespace TimeIntegration
  {
    /**
     * The clock of the phases of a run: a quasi-static loading phase
     * (gravity, plate motion) over years, then a dynamic phase of seconds.
     *
     * Steps are counted in the phase's own time. After a long loading
     * phase the absolute time has lost the digits of a short dynamic phase
     * (3e9 s + 0.3 s), so the time since the dynamic phase started
     * (phase_time) is computed from step counts, and the absolute time of
     * a step from the phase's start plus the steps taken in it, never by
     * adding steps one by one.
     */
    struct PhaseClock
    {
      /// The time of the current phase's clock: since the start of the
      /// dynamic phase (in its steps and after), since the start of the run
      /// before. Printed and written everywhere; the absolute time goes in
      /// a column of its own.
      double phase_time = 0;
      /// Start of the dynamic phase (0 without a loading phase): the time 0
      /// of station files and rupture times.
      double dynamic_start = 0;
      /// Whether the dynamic phase after a loading phase has started.
      bool in_dynamic_phase = false;
      /// The absolute time at which the current phase started.
      double phase_start_time = 0;
      /// Steps done in the current phase.
      unsigned int steps_in_phase = 0;
      /// The time step may change within a phase (after the mesh changed):
      /// the steps of the current step size started at the absolute time
      /// segment_start_time, after segment_first_step steps of the phase.
      /// A phase of one step size has one segment, from its start.
      double       segment_start_time = 0;
      unsigned int segment_first_step = 0;

      /**
       * The number of steps of @p dt that cover @p duration (the last one
       * may be shorter), as a floating-point number.
       */
      static double
      steps_to_cover(const double duration, const double dt)
      {
        return std::ceil(duration / dt - 1e-9);
      }

      /**
       * Start a phase at the absolute time @p now, or continue the current
       * one after @p steps_done of its steps (a run read from a
       * checkpoint). Returns the phase's start time.
       */
      double
      begin_phase(const double now, const unsigned int steps_done)
      {
        const double start = (steps_done > 0) ? phase_start_time : now;
        phase_start_time   = start;
        steps_in_phase     = steps_done;
        if (steps_done == 0)
          {
            segment_start_time = start;
            segment_first_step = 0;
            compensation       = 0;
          }
        return start;
      }

      /**
       * The time the current segment has left of a phase of @p duration.
       */
      double
      segment_duration(const double duration) const
      {
        return (segment_first_step == 0) ?
                 duration :
                 (phase_start_time + duration) - segment_start_time;
      }

      /**
       * The number of steps of the phase of @p duration: those before the
       * current segment and the steps of @p dt that cover the rest.
       */
      double
      steps_of_phase(const double duration, const double dt) const
      {
        return segment_first_step +
               steps_to_cover(segment_duration(duration), dt);
      }

      /**
       * Start a segment of a new step size after @p steps_done steps of
       * the phase, at the absolute time @p now.
       */
      void
      start_segment(const double now, const unsigned int steps_done)
      {
        segment_start_time = now;
        segment_first_step = steps_done;
      }

      /**
       * Enter step @p i of the @p n_steps steps (of @p dt in the current
       * segment) that cover @p duration from the phase's start: sets
       * phase_time and the steps done, and returns the absolute time at
       * the end of the step (the phase's end time at the last step).
       */
      double
      enter_step(const unsigned int i,
                 const unsigned int n_steps,
                 const double       duration,
                 const double       dt)
      {
        const double start    = phase_start_time;
        const double end_time = start + duration;
        steps_in_phase        = i;
        const double in_segment =
          (segment_start_time - start) + (i - segment_first_step) * dt;
        phase_time =
          (start - dynamic_start) + ((i == n_steps) ? duration : in_segment);
        return (i == n_steps) ?
                 end_time :
                 segment_start_time + (i - segment_first_step) * dt;
      }

      /**
       * The round-off that adding steps of changing size to the absolute
       * time lost so far (compensated summation), for the adaptive steps.
       */
      double compensation = 0;

      /**
       * Enter step @p i of a phase of @p duration whose steps a controller
       * chooses: the step of @p dt starts at the absolute time @p now and
       * is a segment of its own. The last step (@p last) ends at the
       * phase's end time exactly; the others add @p dt to @p now by
       * compensated (Kahan) summation, so that a million steps of
       * milliseconds after years keep their sum. Returns the absolute time
       * at the end of the step.
       */
      double
      enter_adaptive_step(const unsigned int i,
                          const double       now,
                          const double       dt,
                          const double       duration,
                          const bool         last)
      {
        start_segment(now, i - 1);
        steps_in_phase = i;
        double end     = phase_start_time + duration;
        if (last)
          compensation = 0;
        else
          {
            const double add = dt - compensation;
            end              = now + add;
            compensation     = (end - now) - add;
          }
        phase_time = (phase_start_time - dynamic_start) +
                     (last ? duration : end - phase_start_time);
        return end;
      }

      /**
       * The dynamic phase starts at the absolute time @p now: its clock
       * reads 0.
       */
      void
      start_dynamic_phase(const double now)
      {
        dynamic_start    = now;
        phase_time       = 0;
        in_dynamic_phase = true;
      }
    };
  } // namespace TimeIntegration
} // namespace rupture

#endif
