// A checkpoint in the middle of an earthquake of the boundary-integral
// method (inputs/spring_slider.prm: one element, three events in 2.9e8 s)
// continues to the last digit. The run writes a checkpoint every 800
// steps; the newest (the one at its end) is removed as if the run had
// been killed after the checkpoint before it, and --resume continues from
// that one. The continued run cuts the statistics, the station file and
// the profiles back to where the checkpoint left them and appends the
// same rows as the uninterrupted run: every file the same, byte for
// byte (the integrator's first stage, the slip-rate solves' first
// guesses and the event catalogue's open event are in the checkpoint).

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
  const std::string prm = std::string(SOURCE_DIR) + "/inputs/spring_slider.prm";
  const std::vector<std::string> profiles = {
    "Boundary integral/Profile interval between events=1e7",
    "Boundary integral/Profile interval during events=0.5"};
  std::vector<std::string> stopped = profiles;
  stopped.push_back("Checkpoint/Interval=800");
  std::printf("uninterrupted: exit code %d\n",
              tests::run_in("full", {prm}, profiles));
  std::printf("with checkpoints: exit code %d\n",
              tests::run_in("stopped", {prm}, stopped));
  // Killed after the checkpoint before the last.
  std::printf("continued (its screen output):\n");
  std::printf(
    "continued: exit code %d\n",
    tests::resume_from_previous_checkpoint(prm, "stopped", stopped, true));

  // Where the checkpoint was: step 1600, in the third event.
  const auto rows = tests::read_statistics("full/statistics.dat");
  for (const auto &r : rows)
    if (r[0] == 1600)
      std::printf("the checkpoint: step 1600 at t = %.4f years, slip rate "
                  "above 1 mm/s: %s\n",
                  r[1] / 3.15576e7,
                  r[3] > 1e-3 ? "yes" : "no");
  for (const std::string file :
       {"statistics.dat", "slider.dat", "slip_profiles.dat", "events.csv"})
    std::printf("%s the same: %s\n",
                file.c_str(),
                tests::read_file("full/" + file) ==
                    tests::read_file("stopped/" + file) ?
                  "yes" :
                  "no");
  return 0;
}
