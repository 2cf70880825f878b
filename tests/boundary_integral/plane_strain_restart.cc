// A checkpoint of a cycle run on a dipping fault in a plane-strain body
// (prm/seas/bp3-qd-60.prm, node pairs 2 km apart, a box of 100 km: coarse,
// but every file of the run, to its first event) continues to the last
// digit: the normal stress and the surface stations (their files' lengths)
// are in the checkpoint as the antiplane problem's fields are. The run
// writes a checkpoint every 300 steps; the newest is removed as if the run
// had been killed after the one before it, and --resume continues from
// that. Every file the same, byte for byte.
// Also: a normal fault under 0.5 MPa whose initial shear stress (29 MPa,
// for 50 MPa) makes it slip at metres per second at once unclamps itself
// until it would open; the run stops with a message that says so and
// names <Boundary integral/Normal stress> (its numbers, a trial step's,
// are not compared).

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cstdio>
#include <string>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        prm =
    std::string(SOURCE_DIR) + "/../../prm/seas/bp3-qd-60.prm";
  const std::vector<std::string> common = {
    "Boundary integral/Element size=2000",
    "Boundary integral/Domain size=100e3",
    "Boundary integral/Cell growth factor=1.5",
    "Fault/Rate and state/Characteristic slip distance=0.256",
    "Fault/Output/Stations=fltst_dp100: 5000, -8660.25",
    "Boundary integral/Surface stations=surfst_m080: -8000, 0; "
    "surfst_p080: 8000, 0",
    "Termination/Number of events=1",
    "Boundary integral/Profile interval between events=3.15576e8",
    "Test mode=true"};
  std::vector<std::string> stopped = common;
  stopped.push_back("Checkpoint/Interval=300");
  std::printf("uninterrupted: exit code %d\n",
              tests::run_in("full", {prm}, common));
  std::printf("with checkpoints: exit code %d\n",
              tests::run_in("stopped", {prm}, stopped));
  const auto steps = tests::read_statistics("full/statistics.dat");
  std::printf("the uninterrupted run: %zu rows, past step 600: %s\n",
              steps.size(),
              steps.back()[0] > 600 ? "yes" : "no");
  // Killed after the checkpoint before the last.
  std::printf("continued: exit code %d\n",
              tests::resume_from_previous_checkpoint(prm, "stopped", stopped));
  for (const std::string file : {"statistics.dat",
                                 "fltst_dp100.dat",
                                 "surfst_m080.dat",
                                 "surfst_p080.dat",
                                 "slip_profiles.dat",
                                 "events.csv"})
    std::printf("%s the same: %s\n",
                file.c_str(),
                tests::read_file("full/" + file) ==
                    tests::read_file("stopped/" + file) ?
                  "yes" :
                  "no");

  std::string errors;
  const int   code =
    tests::run_capture({prm,
                        "--set",
                        "Output directory=opened",
                        "--set",
                        "Boundary integral/Element size=10000",
                        "--set",
                        "Boundary integral/Normal stress=5e5",
                        "--set",
                        "Boundary integral/Sense of slip=normal",
                        "--set",
                        "Fault/Rate and state/Initial state=8e6"},
                       errors);
  std::printf("a fault that would open: exit code %d, says so: %s, names "
              "the entry: %s\n",
              code,
              errors.find("The fault would open") != std::string::npos ? "yes" :
                                                                         "no",
              errors.find("<Boundary integral/Normal stress>") !=
                  std::string::npos ?
                "yes" :
                "no");
  return 0;
}
