// Chester's law in the fault-only solver (the boundary-integral method with
// one element: the spring-slider of inputs/spring_slider.prm), its
// temperature warmed by the friction and relaxing over t_c = 1 s, moved at
// its rate of the step's start through the explicit pair's stages and
// advanced exactly from the start after each step
// (QuasiDynamicFault::relax()):
// - the run takes its three events in a few thousand steps, not the steps
//   of about t_c over years that the pair would need for the temperature;
// - the heating matters: with the default heat capacity the events recur
//   more than 1 % sooner than with a heat capacity that keeps the fault at
//   its reservoir temperature;
// - the splitting converges with the tolerance: the third event's start at
//   relative tolerances 1e-7 and 1e-9 against 1e-11, the error falling more
//   than 4 times (second order in the step, which falls as the tolerance's
//   fifth root: 6.3 times; first order, as without the held rate, 2.5) and
//   below 2e-5 of the interval between events at 1e-9;
// On one process and on two (the one element's rows on one of them).
// - a run continued from a checkpoint in the third event (the heating at
//   the step's start comes from the checkpoint's traction and slip rate)
//   writes the same files, byte for byte.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
  std::string
  number(const double x)
  {
    char text[64];
    std::snprintf(text, sizeof(text), "%.17g", x);
    return text;
  }

  struct Run
  {
    std::vector<std::vector<double>> events;
    double                           steps = 0;
  };

  const std::string input =
    std::string(SOURCE_DIR) + "/inputs/spring_slider.prm";

  std::vector<std::string>
  settings(const double tolerance, const double H)
  {
    const std::string cs = "Fault/Chester/";
    return {"Termination/Number of events=3",
            "Boundary integral/Relative tolerance=" + number(tolerance),
            "Fault/Friction law=chester",
            cs + "Direct effect=0.01",
            cs + "Evolution effect=0.015",
            cs + "Characteristic slip distance=1e-3",
            cs + "Reference friction coefficient=0.6",
            cs + "Reference slip rate=1e-6",
            cs + "Heat capacity per area=" + number(H),
            // (The aging law's state 1.2e6 s of the input as Chester's theta.)
            cs + "Initial state=" + number(std::log(1e-6 * 1.2e6 / 1e-3))};
  }

  Run
  run(const std::string &directory, const double tolerance, const double H)
  {
    tests::run_in(directory, {input}, settings(tolerance, H));
    Run r;
    r.events = tests::read_csv(directory + "/events.csv");
    r.steps  = tests::find_number(directory + "/summary.json", "\"steps\": ");
    return r;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             H = 2.7e4;
  const Run coarse = run("coarse", 1e-7, H), middle = run("middle", 1e-9, H),
            fine = run("fine", 1e-11, H), cold = run("cold", 1e-9, 2.7e10);
  const bool root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const bool three = coarse.events.size() == 3 && middle.events.size() == 3 &&
                     fine.events.size() == 3 && cold.events.size() == 3;
  // (The checkpointed run too, on every process.)
  std::vector<std::string> stopped = settings(1e-9, H);
  stopped.push_back("Checkpoint/Interval=800");
  tests::run_in("stopped", {input}, stopped);
  const int code =
    tests::resume_from_previous_checkpoint(input, "stopped", stopped);
  if (!root)
    return 0;
  std::printf("three events in every run: %s\n", three ? "yes" : "no");
  if (!three)
    return 0;
  // 0-based column 1: the start (s).
  const auto start = [](const Run &r, const unsigned int k) {
    return r.events[k][1];
  };
  const double interval = start(fine, 2) - start(fine, 1);
  std::printf("steps at the tolerance 1e-9 below 20000: %s\n",
              middle.steps > 0 && middle.steps < 20000 ? "yes" : "no");
  const double warm = start(middle, 2) - start(middle, 1),
               kept = start(cold, 2) - start(cold, 1);
  std::printf("the heated fault's events recur more than 1 %% sooner than "
              "the fault kept at its reservoir temperature: %s\n",
              warm < 0.99 * kept ? "yes" : "no");
  const double e7 = std::abs(start(coarse, 2) - start(fine, 2)) / interval,
               e9 = std::abs(start(middle, 2) - start(fine, 2)) / interval;
  std::printf("the third event's start against the tolerance 1e-11: the "
              "error falls more than 4 times from 1e-7 to 1e-9: %s; below "
              "2e-5 of the interval at 1e-9: %s\n",
              e9 < 0.25 * e7 ? "yes" : "no",
              e9 < 2e-5 ? "yes" : "no");

  bool same = code == 0;
  for (const std::string file : {"statistics.dat", "slider.dat", "events.csv"})
    same = same && tests::read_file("middle/" + file) ==
                     tests::read_file("stopped/" + file);
  std::printf("continued from the checkpoint at step 1600: the same files: "
              "%s\n",
              same ? "yes" : "no");
}
