// Signals to a run of the boundary-integral method (the one-element slider
// of inputs/spring_slider.prm over ten times its usual time, about ten
// cycles), without <Checkpoint> entries: SIGUSR1 once the run is stepping
// asks for a checkpoint, which the run writes after its step and goes on;
// SIGTERM once that checkpoint exists stops it cleanly (exit code
// 128 + 15, "Stopped by SIGTERM", no checkpoint of its own, as none was
// asked for).
// --resume then continues from the SIGUSR1 checkpoint to the end: the
// statistics, the station and events.csv the same, byte for byte, as
// those of the uninterrupted run. (When the signals come depends on the
// machine; what is printed does not.) The signalled run is given ten
// times the end time, so that SIGTERM, sent once the checkpoint exists,
// reaches it while it still steps even where the signalling thread wakes
// late (a release build under load once finished the whole run between
// the checkpoint and the signal); "ended early" means before its own end
// (a run writes summary.json only when it ends); --resume sets the end
// time back.

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
  const std::string prm = std::string(SOURCE_DIR) + "/inputs/spring_slider.prm";
  const std::vector<std::string> settings = {"Time integration/End time=2.9e9"};
  std::printf("uninterrupted: exit code %d\n",
              tests::run_in("full", {prm}, settings));

  const std::string checkpoint = "signalled/checkpoint/boundary_integral.bin";
  bool              usr1_while_running = false, checkpoint_written = false;
  // (Before the signaller looks for files: an earlier run's would mislead
  // it.)
  fs::remove_all("signalled");
  std::thread              signaller([&]() {
    const auto wait_for = [](const std::string &file) {
      for (unsigned int i = 0; i < 60000 && !fs::exists(file); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      return fs::exists(file);
    };
    if (!wait_for("signalled/statistics.dat"))
      return;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    usr1_while_running = !fs::exists("signalled/summary.json");
    ::kill(::getpid(), SIGUSR1);
    checkpoint_written = wait_for(checkpoint);
    ::kill(::getpid(), SIGTERM);
  });
  std::string              errors;
  std::vector<std::string> arguments = {prm,
                                        "--set",
                                        "Output directory=signalled",
                                        "--set",
                                        "Time integration/End time=2.9e10"};
  const int                code      = tests::run_capture(arguments, errors);
  signaller.join();
  std::printf("SIGUSR1 while the run steps: %s; it wrote a checkpoint and "
              "went on: %s\n",
              usr1_while_running ? "yes" : "no",
              checkpoint_written ? "yes" : "no");
  std::printf("SIGTERM: exit code %d, '%s'; no checkpoint of its own (the "
              "one before it is absent): %s; ended early: %s\n",
              code,
              errors.find("Stopped") == std::string::npos ?
                "" :
                errors.substr(errors.find("Stopped"), 18).c_str(),
              fs::exists("signalled/checkpoint/"
                         "boundary_integral.previous.bin") ?
                "no" :
                "yes",
              !fs::exists("signalled/summary.json") ? "yes" : "no");

  arguments.back() = settings[0];
  arguments.push_back("--resume");
  std::printf("continued: exit code %d\n", tests::run(arguments));
  for (const std::string file : {"statistics.dat", "slider.dat", "events.csv"})
    std::printf("%s the same: %s\n",
                file.c_str(),
                tests::read_file("full/" + file) ==
                    tests::read_file("signalled/" + file) ?
                  "yes" :
                  "no");
  return 0;
}
