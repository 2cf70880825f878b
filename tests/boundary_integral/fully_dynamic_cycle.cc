// Earthquake cycles whose events are fully dynamic (<Boundary integral/
// Events> = fully dynamic; inputs/fully_dynamic.prm: BP1's friction on a
// fault 20 km deep, nodes 500 m apart) against the same problem
// quasi-dynamic, to the end of the second event:
// - each event is one fully dynamic phase, from the step whose largest slip
//   rate reached 1 mm/s until it fell below 0.5 mm/s (the catalogue ends
//   events there too), and the run goes on quasi-dynamically between them;
// - the first event starts when the quasi-dynamic run's does (the loading
//   before it is the same);
// - with inertia the events are faster and larger than with radiation
//   damping (peak slip rate and largest slip above the quasi-dynamic
//   run's), and the second event comes later (more slip to recover);
// - no jump where a dynamic phase starts: at the stations 0 and 5 km down
//   the slip rate changes by less than 1 % and the shear stress by less
//   than 1e-3 over the first dynamic step (it starts from the static
//   fields of the slip and of the slip rates);
// - a checkpoint every 5000 steps (they fall due in the dynamic phases
//   and are written after them), the run killed after the one before the
//   last and continued: every file the same, byte for byte;
// - prm/seas/bp1-fd.prm runs (coarse and short).

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::freopen("/dev/null", "w", stdout);
  const std::string prm = std::string(SOURCE_DIR) + "/inputs/fully_dynamic.prm";
  std::printf("quasi-dynamic: exit code %d\n",
              tests::run_in("qd",
                            {prm},
                            {"Boundary integral/Events=quasi-dynamic"}));
  std::printf("fully dynamic: exit code %d\n", tests::run_in("fd", {prm}, {}));
  const auto qd = tests::read_csv("qd/events.csv"),
             fd = tests::read_csv("fd/events.csv");
  const double phases =
    tests::find_number("fd/summary.json", "\"dynamic phases\":");
  std::printf("events: %zu quasi-dynamic, %zu fully dynamic in %g dynamic "
              "phases\n",
              qd.size(),
              fd.size(),
              phases);
  // Columns: event, start (s), start (years), end, duration, hypocentre x,
  // y, peak slip rate, moment, ruptured length, mean slip, largest slip.
  if (qd.size() == 2 && fd.size() == 2)
    {
      std::printf("first event at %.2f years in both: %s\n",
                  fd[0][2],
                  std::abs(fd[0][1] / qd[0][1] - 1) < 1e-12 ? "yes" : "no");
      for (unsigned int e = 0; e < 2; ++e)
        std::printf("event %u: peak slip rate %.3g m/s (quasi-dynamic %.3g), "
                    "higher: %s; largest slip %.3g m (%.3g), larger: %s\n",
                    e + 1,
                    fd[e][7],
                    qd[e][7],
                    fd[e][7] > qd[e][7] ? "yes" : "no",
                    fd[e][11],
                    qd[e][11],
                    fd[e][11] > qd[e][11] ? "yes" : "no");
      std::printf("recurrence %.1f years (quasi-dynamic %.1f), longer: %s\n",
                  fd[1][2] - fd[0][2],
                  qd[1][2] - qd[0][2],
                  fd[1][2] - fd[0][2] > qd[1][2] - qd[0][2] ? "yes" : "no");
    }

  // The switch to the first dynamic phase: the statistics' last row of the
  // quasi-dynamic phase and the first of the dynamic one (the time step
  // drops to the dynamic phase's), and the stations' rows at those times.
  {
    const auto   rows = tests::read_statistics("fd/statistics.dat");
    unsigned int k    = 1;
    while (k < rows.size() && !(rows[k][2] < 1 && rows[k - 1][2] > 1))
      ++k;
    if (k < rows.size())
      for (const std::string station : {"dp000", "dp050"})
        {
          // Columns: time, slip, log10 slip rate, shear stress (MPa),
          // log10 state.
          const auto series = tests::read_statistics("fd/" + station + ".dat");
          std::vector<double> before, after;
          for (const auto &r : series)
            {
              if (r[0] == rows[k - 1][1])
                before = r;
              if (r[0] == rows[k][1])
                after = r;
            }
          if (before.empty() || after.empty())
            std::printf("%s: the rows of the switch are missing\n",
                        station.c_str());
          else
            std::printf(
              "%s at the switch to the dynamic phase (one step "
              "of %.3g s): slip rate within 1 %%: %s, shear stress "
              "within 1e-3: %s\n",
              station.c_str(),
              rows[k][2],
              std::abs(std::pow(10, after[2] - before[2]) - 1) < 1e-2 ? "yes" :
                                                                        "no",
              std::abs(after[3] / before[3] - 1) < 1e-3 ? "yes" : "no");
        }
  }

  // Checkpoints and a continued run.
  const std::vector<std::string> stopped = {"Checkpoint/Interval=5000"};
  std::printf("with checkpoints: exit code %d\n",
              tests::run_in("stopped", {prm}, stopped));
  std::printf("continued (its screen output):\n");
  std::printf(
    "continued: exit code %d\n",
    tests::resume_from_previous_checkpoint(prm, "stopped", stopped, true));
  for (const std::string file : {"statistics.dat",
                                 "dp000.dat",
                                 "dp050.dat",
                                 "slip_profiles.dat",
                                 "events.csv"})
    std::printf("%s the same: %s\n",
                file.c_str(),
                tests::read_file("fd/" + file) ==
                    tests::read_file("stopped/" + file) ?
                  "yes" :
                  "no");

  // The shipped BP1-FD set-up reads and runs (coarse and short).
  std::printf("prm/seas/bp1-fd.prm, nodes 2 km apart, 10 years: exit code "
              "%d\n",
              tests::run_in("shipped",
                            {std::string(SOURCE_DIR) +
                             "/../../prm/seas/bp1-fd.prm"},
                            {"Boundary integral/Element size=2000",
                             "Boundary integral/Domain size=100e3",
                             "Boundary integral/Cell growth factor=1.5",
                             "Time integration/End time=3.15576e8",
                             "Test mode=true"}));
  return 0;
}
