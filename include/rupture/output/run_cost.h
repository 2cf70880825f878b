#ifndef rupture_output_run_cost_h
#define rupture_output_run_cost_h

#include <string>
#include <utility>
#include <vector>

namespace rupture
{
  namespace Output
  {
    /**
     * What a run has cost so far, for the performance summary on the screen
     * and summary.json.
     */
    struct RunCost
    {
      /// The wall time (MPI_Wtime()) at the start of the run.
      double wall_time_start = 0;
      /// Wall time spent in the time loops (s).
      double time_loop_seconds = 0;
      /// The DoFs summed over the steps this process ran, and their peak.
      double dof_steps = 0;
      double peak_dofs = 0;
      /// Resident memory (bytes, all ranks) after each set-up stage.
      std::vector<std::pair<std::string, double>> memory_by_stage;
    };
  } // namespace Output
} // namespace rupture

#endif
