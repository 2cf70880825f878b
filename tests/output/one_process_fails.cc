// A failure on one process of two does not hang the run: process 1 cannot
// write its piece of the second snapshot (a directory stands where the file
// goes), while process 0 writes its own and goes on to the next step's
// collective operations. Before, process 0 waited there for ever; now
// process 1 waits ten seconds for the others at the end, says what failed,
// naming itself, and aborts the run. The program runs as its own job of two
// processes (mpirun -np 2 ../../../rupture), under a time limit that a hang
// would exceed.

#include "../tests.h"
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

int
main()
{
  fs::remove_all("results");
  fs::create_directories("results/solution/solution_00001.1.vtu");
  std::ofstream("results/solution/solution_00001.1.vtu/keep") << "a user's\n";

  const int status = std::system(
    ("timeout 300 mpirun -np 2 --oversubscribe ../../../rupture " +
     std::string(SOURCE_DIR) + "/inputs/gravity_box.prm > run.log 2>&1")
      .c_str());
  const bool        timed_out = WIFEXITED(status) && WEXITSTATUS(status) == 124;
  const std::string log       = tests::read_file("run.log");
  const auto        has       = [&](const std::string &text) {
    return log.find(text) != std::string::npos ? "yes" : "no";
  };
  std::printf("the run ended before the time limit: %s; its exit code is "
              "not 0: %s\n",
              timed_out ? "no" : "yes",
              status != 0 ? "yes" : "no");
  std::printf("the message names process 1 of 2: %s; the file it could not "
              "write: %s; the abort: %s\n",
              has("Error on process 1 of 2: Cannot write the file"),
              has("solution_00001.1.vtu>"),
              has("the run is aborted (MPI_Abort)"));
  std::printf("the user's file in the way is kept: %s\n",
              fs::exists("results/solution/solution_00001.1.vtu/keep") ? "yes" :
                                                                         "no");
  return 0;
}
