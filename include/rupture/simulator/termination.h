#ifndef rupture_simulator_termination_h
#define rupture_simulator_termination_h

#include <deal.II/base/parameter_handler.h>

#include <deque>
#include <iosfwd>
#include <string>

namespace rupture
{
  namespace Termination
  {
    /**
     * Why a run ended: at its end time, or early by one of the criteria of
     * the <tt>Termination</tt> subsection. The names are those of the run's
     * summary.json ("end").
     */
    enum class Reason
    {
      end_time,
      rupture_died,
      steady_state,
      runaway,
      wall_clock,
      events
    };

    /**
     * The name of @p reason in summary.json: "end time", "rupture died",
     * "steady state", "runaway", "wall-clock limit" or "number of events".
     */
    std::string
    name(const Reason reason);

    /// How a run ended, for its summary.json: the reason, the message of
    /// an early end, and the largest slip rate of the dynamic phase.
    struct Outcome
    {
      Reason      reason = Reason::end_time;
      std::string message;
      double      peak_slip_rate = 0;
    };

    /**
     * What the criteria look at after a step. Every value is the same on
     * all ranks (the fault's statistics are reduced over them, and the
     * wall time is rank 0's), so all ranks decide alike.
     */
    struct Sample
    {
      /// The phase's time (s).
      double time = 0;
      /// Seconds since the run started (rank 0's clock).
      double wall_seconds   = 0;
      double kinetic_energy = 0;
      /// The fault's values; all zero without a fault.
      double max_slip_rate       = 0;
      double mean_shear_traction = 0;
      double seismic_moment      = 0;
      double max_slip            = 0;
      double slipping_area       = 0;
      /// The number of events the event catalogue holds (ended ones).
      double events = 0;
    };

    /**
     * Early ends of a run, so that a parameter sweep does not spend its
     * time on runs whose outcome is known: the rupture has died, the run
     * has reached a steady state, the rupture has run away, or the
     * wall-clock limit is near. Each criterion is off unless its entry is
     * set. The run then ends as at its end time: the last step's output is
     * written, and the screen, log.txt and summary.json say why it ended.
     *
     * The fault criteria apply to the dynamic phase (the only phase of a
     * run without a loading phase); the wall-clock limit applies
     * throughout.
     */
    class Criteria
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /**
       * Read the subsection. @p has_fault: criteria that look at the
       * fault are an error without one.
       */
      void
      parse_parameters(dealii::ParameterHandler &prm, const bool has_fault);

      /**
       * Whether any criterion is set, and whether the wall-clock limit is
       * (the simulator then reads the clock after every step).
       */
      bool
      any() const;
      bool
      uses_wall_clock() const;
      /// Whether <Number of events> is set (it needs the event catalogue).
      bool
      uses_events() const
      {
        return max_events > 0;
      }

      /**
       * A line for the screen that lists the criteria in force, or "".
       */
      std::string
      description() const;

      /**
       * Start a phase: @p watched says whether the fault criteria apply to
       * it. Forgets what earlier steps showed.
       */
      void
      start_phase(const bool watched);

      /**
       * Look at the state after a step. Returns Reason::end_time to go on,
       * or the reason to end the run now, with the message in
       * @p message.
       */
      Reason
      check(const Sample &sample, std::string &message);

      /**
       * Write what the criteria remember of earlier steps, and read it
       * back (checkpoints).
       */
      void
      save(std::ostream &out) const;
      void
      load(std::istream &in);

    private:
      double       slip_rate_threshold = 1e-3;
      double       died_after          = 0;
      double       steady_window       = 0;
      double       steady_tolerance    = 1e-3;
      double       max_moment          = 0;
      double       max_slip            = 0;
      unsigned int max_events          = 0;
      double       max_area            = 0;
      double       wall_clock_minutes  = 0;

      bool               watched       = false;
      bool               rupture_began = false;
      double             quiet_since   = 0;
      double             phase_start   = 0;
      bool               started       = false;
      std::deque<Sample> window;
      /// What the steady state watches, and the largest magnitude of each
      /// in the phase.
      static constexpr double Sample::*quantities[3] = {
        &Sample::kinetic_energy,
        &Sample::max_slip_rate,
        &Sample::mean_shear_traction};
      double largest[3] = {0, 0, 0};
    };
  } // namespace Termination
} // namespace rupture

#endif
