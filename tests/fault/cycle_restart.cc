// A checkpoint in the middle of an earthquake cycle run with adaptive time
// steps: the spring-slider of inputs/spring_slider_cycles.prm over its
// first event (2e7 s, 971 steps of 4e-4 s to 2.5e6 s) with a checkpoint
// every 500 steps, the last one (at the end) removed as if the run had
// been killed after step 500, in the middle of the event (slip rate
// 0.14 m/s, steps of milliseconds). Continued with --resume, the run takes
// the same steps (the step controller's state and the compensated sum of
// the time are in the checkpoint): the same number, and times, step
// sizes, slip, slip rates and tractions within 1e-9 (relative; the
// energies within 1e-9 of their scale, the slip rate within 1e-9 of at
// least the plate rate). Not to the last digit: the
// continued run's linear solves start from a new preconditioner and end
// with other round-off (1e-14 relative in the tractions eight steps after
// the checkpoint, an iteration count that differs by one), noise far
// below Newton's tolerance (1e-8) that the following steps carry along
// (1e-10 in the slip rate of 5e-14 m/s at the end of the locked phase,
// 1e-11 in the last step); the solver iteration counts are not compared.
// The event catalogue's open event is in the checkpoint too: the
// continued run ends it with the uninterrupted run's row. A run to 2.9e8 s
// with <Termination/Number of events> = 1 ends after that event, with the
// same row.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  namespace fs = std::filesystem;
  const std::string prm =
    std::string(SOURCE_DIR) + "/inputs/spring_slider_cycles.prm";
  const std::vector<std::string> end   = {"Time integration/End time=2e7",
                                          "Fault/Output/Event catalogue=true"};
  std::vector<std::string>       every = end;
  every.push_back("Checkpoint/Interval=500");

  tests::run_in("full", {prm}, end);
  tests::run_in("stopped", {prm}, every);
  std::vector<std::string> kept;
  for (const auto &e : fs::directory_iterator("stopped/checkpoint"))
    kept.push_back(e.path().filename().string());
  std::sort(kept.begin(), kept.end());
  std::printf("checkpoints kept:");
  for (const auto &k : kept)
    std::printf(" %s", k.c_str());
  std::printf("\n");
  if (!kept.empty())
    fs::remove_all("stopped/checkpoint/" + kept.back());
  std::vector<std::string> resume = {prm, "--resume"};
  for (const auto &s : every)
    {
      resume.push_back("--set");
      resume.push_back(s);
    }
  resume.push_back("--set");
  resume.push_back("Output directory=stopped");
  const int code = tests::run(resume);
  std::printf("resumed: exit code %d\n", code);

  const auto a = tests::read_statistics("full/statistics");
  const auto b = tests::read_statistics("stopped/statistics");
  // 0-based columns: 3 and 10 the solver iterations; 4-8 energies and
  // their balance, 18-19 the fault's dissipation and work.
  const auto energy = [](const unsigned int j) {
    return (j >= 4 && j <= 8) || j == 18 || j == 19;
  };
  // Column 15, the largest slip rate, relative to at least the plate rate
  // (1e-9 m/s): in the locked phase it falls to 5e-14 m/s, where the
  // round-off the continued run carries along is a larger part of it than
  // of anything else (1e-10 of it on one machine, 1.06e-9 on another, whose
  // BLAS rounds otherwise: 5e-23 m/s).
  const auto   floor = [](const unsigned int j) { return j == 15 ? 1e-9 : 0.; };
  bool         close = a.size() == b.size() && !a.empty();
  unsigned int rate_steps = 0;
  for (unsigned int i = 0; close && i < a.size(); ++i)
    {
      double scale = 0;
      for (unsigned int j = 4; j <= 7; ++j)
        scale += std::abs(a[i][j]);
      for (unsigned int j = 0; j < a[i].size(); ++j)
        if (j != 3 && j != 10)
          close = close &&
                  std::abs(a[i][j] - b[i][j]) <=
                    1e-9 * (energy(j) ? std::max(scale, std::abs(a[i][j])) :
                                        std::max(floor(j), std::abs(a[i][j])));
      if (i >= 500 && a[i][15] > 1e-3)
        ++rate_steps;
    }
  std::printf("steps: %zu; steps after the checkpoint in the event: %s\n",
              a.size(),
              rate_steps > 100 ? "more than 100" : "too few");
  std::printf("times, step sizes, slip, rates, tractions, energies within "
              "1e-9: %s\n",
              close ? "yes" : "no");

  // The event catalogue: the event open at the checkpoint ends in the
  // continued run with the uninterrupted run's row.
  const auto full_events    = tests::read_csv("full/events.csv");
  const auto stopped_events = tests::read_csv("stopped/events.csv");
  bool       same_events    = full_events.size() == 1 &&
                     stopped_events.size() == full_events.size() &&
                     full_events[0].size() == stopped_events[0].size();
  for (unsigned int j = 0; same_events && j < full_events[0].size(); ++j)
    same_events = std::abs(full_events[0][j] - stopped_events[0][j]) <=
                  1e-9 * std::abs(full_events[0][j]);
  std::printf("the event open at the checkpoint: one complete row, as the "
              "uninterrupted run's within 1e-9: %s\n",
              same_events && full_events[0].back() == 1 ? "yes" : "no");

  // <Termination/Number of events> = 1 over a longer run: it ends after
  // the first event, with the uninterrupted run's row.
  tests::run_in("counted",
                {prm},
                {"Time integration/End time=2.9e8",
                 "Fault/Output/Event catalogue=true",
                 "Termination/Number of events=1"});
  const auto counted = tests::read_csv("counted/events.csv");
  const auto summary = tests::read_file("counted/summary.json");
  bool       as_full = counted.size() == 1 && !full_events.empty() &&
                 counted[0].size() == full_events[0].size();
  for (unsigned int j = 0; as_full && j < counted[0].size(); ++j)
    as_full = std::abs(counted[0][j] - full_events[0][j]) <=
              1e-9 * std::abs(full_events[0][j]);
  std::printf("ended by <Termination/Number of events> = 1 after the first "
              "event (summary: \"number of events\"), its row as the "
              "uninterrupted run's: %s\n",
              as_full &&
                  summary.find("\"number of events\"") != std::string::npos ?
                "yes" :
                "no");
  return 0;
}
