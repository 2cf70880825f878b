// SIGTERM during a fully dynamic phase (inputs/fully_dynamic.prm to the
// end of its first event, checkpoints on but none due before): the run
// stops cleanly (exit code 128 + 15, "Stopped by SIGTERM ... in the fully
// dynamic phase") and keeps the checkpoint of the phase's start, the
// quasi-dynamic state it switched from. --resume takes the phase's steps
// again: the statistics, the stations, the slip profiles and events.csv
// the same, byte for byte, as those of the uninterrupted run. The signal is
// sent once statistics.dat shows a row of the dynamic phase (its time step
// below a second); when that is depends on the machine, what is printed
// does not.

#include <deal.II/base/mpi.h>

#include "../tests.h"
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  namespace fs          = std::filesystem;
  const std::string prm = std::string(SOURCE_DIR) + "/inputs/fully_dynamic.prm";
  const std::vector<std::string> settings = {"Termination/Number of events=1",
                                             "Checkpoint/Interval=1000000"};
  std::printf("uninterrupted: exit code %d\n",
              tests::run_in("full", {prm}, settings));

  bool in_dynamic_phase = false;
  // (Before the signaller looks for files: an earlier run's would mislead
  // it.)
  fs::remove_all("signalled");
  std::thread              signaller([&]() {
    // (A row whose time step, the third column, is below a second: not
    // the first row, of time step 0.)
    const auto dynamic_row = []() {
      const auto rows = tests::read_statistics("signalled/statistics.dat");
      for (const auto &r : rows)
        if (r.size() > 2 && r[2] > 0 && r[2] < 1)
          return true;
      return false;
    };
    for (unsigned int i = 0; i < 60000 && !dynamic_row(); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    in_dynamic_phase = dynamic_row() && !fs::exists("signalled/summary.json");
    // (Not to a run that has ended: it no longer catches the signal.)
    if (!fs::exists("signalled/summary.json"))
      ::kill(::getpid(), SIGTERM);
  });
  std::vector<std::string> arguments = {prm,
                                                     "--set",
                                                     "Output directory=signalled"};
  for (const auto &s : settings)
    arguments.insert(arguments.end(), {"--set", s});
  std::string errors;
  const int   code = tests::run_capture(arguments, errors);
  signaller.join();
  const auto stopped = errors.find("Stopped");
  std::printf(
    "SIGTERM in the dynamic phase: %s; exit code %d, '%s'; "
    "in the fully dynamic phase: %s; a checkpoint: %s; ended "
    "early: %s\n",
    in_dynamic_phase ? "yes" : "no",
    code,
    stopped == std::string::npos ? "" : errors.substr(stopped, 18).c_str(),
    errors.find("in the fully dynamic phase") != std::string::npos ? "yes" :
                                                                     "no",
    fs::exists("signalled/checkpoint/boundary_integral.bin") ? "yes" : "no",
    !fs::exists("signalled/summary.json") ? "yes" : "no");

  arguments.push_back("--resume");
  std::printf("continued: exit code %d\n", tests::run(arguments));
  for (const std::string file : {"statistics.dat",
                                 "dp000.dat",
                                 "dp050.dat",
                                 "slip_profiles.dat",
                                 "events.csv"})
    std::printf("%s the same: %s\n",
                file.c_str(),
                tests::read_file("full/" + file) ==
                    tests::read_file("signalled/" + file) ?
                  "yes" :
                  "no");
  return 0;
}
