#ifndef rupture_solver_newton_h
#define rupture_solver_newton_h

#include <rupture/base/binary_io.h>

#include <array>
#include <stdexcept>
#include <string>

namespace rupture
{
  namespace Solver
  {
    /**
     * The controls of Newton's method for the implicit and quasi-static
     * steps with a fault (the Solver subsection of the parameter file).
     */
    struct NewtonParameters
    {
      /// <Newton force tolerance>.
      double force_tolerance = 0;
      /// <Newton displacement tolerance>.
      double displacement_tolerance = 0;
      /// <Maximum Newton iterations>.
      unsigned int max_iterations = 0;
      /// <Maximum step cuts>.
      unsigned int max_step_cuts = 0;
      /// <Newton stall iterations>.
      unsigned int stall_iterations = 0;
      /// <Newton forcing>.
      double forcing = 0;
      /// <Print Newton iterations>.
      bool print_iterations = false;
      /// <Newton predictor> of implicit dynamic steps.
      std::string predictor;
      /// <Limit stick crossings>.
      bool limit_stick_crossings = true;
    };

    /**
     * What Newton's method and its linear solves report and remember
     * between steps: iteration counts, the step cuts of the current step,
     * the state of the stick-crossing safeguard and the fault status the
     * preconditioner was built for.
     */
    struct NewtonStatus
    {
      /// Whether a stalled Newton iteration may give up (the step can be
      /// cut).
      bool may_cut = false;
      /// Stick crossings limited in the current (or last) Newton solve.
      unsigned int stick_crossings_limited = 0;
      /// True while a step is retried without the limit.
      bool stick_crossing_limit_suspended = false;
      /// Cuts of the current step.
      unsigned int n_step_cuts = 0;
      /// Cuts of every step since this process started (a continued run
      /// counts from its restart).
      unsigned long total_step_cuts = 0;
      /// Newton and Krylov iterations of the last solve.
      unsigned int last_iterations        = 0;
      unsigned int last_linear_iterations = 0;
      /// Krylov iterations and linear solves of the run, per phase
      /// (quasi-static, dynamic).
      std::array<unsigned long, 2> total_linear_iterations = {{0, 0}};
      std::array<unsigned long, 2> n_linear_solves         = {{0, 0}};
      /// Fault status for which the preconditioner was last built.
      unsigned long preconditioner_signature = 0;

      /// What a checkpoint keeps: the counts of the last solve.
      void
      save(BinaryIO::Records &records) const
      {
        records["newton/last linear iterations"] = last_linear_iterations;
        records["newton/last iterations"]        = last_iterations;
      }
      void
      load(const BinaryIO::Records &records)
      {
        last_linear_iterations = static_cast<unsigned int>(
          BinaryIO::record(records, "newton/last linear iterations"));
        last_iterations = static_cast<unsigned int>(
          BinaryIO::record(records, "newton/last iterations"));
      }
    };

    /// Newton's method did not converge (the step may be cut).
    struct NewtonFailure : public std::runtime_error
    {
      NewtonFailure(const std::string &message, const std::string &reason = "")
        : std::runtime_error(message)
        , reason(reason)
      {}
      /// A few words for the screen when the step is cut.
      std::string reason;
    };
  } // namespace Solver
} // namespace rupture

#endif
