// A run killed by SIGKILL (a batch system's hard limit, an out-of-memory
// kill) leaves only complete files: statistics rows of equal length,
// station rows of equal length, a solution.pvd whose every .pvtu exists and
// whose every .pvtu names pieces that exist and end their XML. The next run
// into the directory removes what the killed run wrote, its temporary files
// included, and nothing else. The program runs as its own process
// (../../../rupture), killed at three times once it has started writing.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

namespace fs = std::filesystem;

namespace
{
  // The shared small box, run for a long time, with receivers.
  const std::string input =
    tests::read_file(std::string(SOURCE_DIR) + "/inputs/gravity_box.prm") +
    "subsection Time integration\n  set End time = 100000\nend\n"
    "subsection Output\n  set Receivers = top: 500, 1000\nend\n";

  // Whether every row of a table has as many numbers as the first.
  bool
  rows_complete(const std::string &file, std::size_t &n_rows)
  {
    const auto rows = tests::read_statistics(file);
    n_rows          = rows.size();
    for (const auto &r : rows)
      if (r.size() != rows.front().size())
        return false;
    return !rows.empty();
  }

  // Whether the .pvd's files exist, and each .pvtu's pieces exist and end
  // with the closing tag of a VTK file.
  bool
  snapshots_complete(unsigned int &n_snapshots)
  {
    n_snapshots = 0;
    const std::regex file_attribute("file=\"([^\"]+)\"");
    const std::regex source_attribute("Source=\"([^\"]+)\"");
    const auto       pvd = tests::read_file("results/solution.pvd");
    if (pvd.find("</VTKFile>") == std::string::npos)
      return false;
    for (std::sregex_iterator i(pvd.begin(), pvd.end(), file_attribute), end;
         i != end;
         ++i)
      {
        const std::string pvtu = "results/" + (*i)[1].str();
        const std::string text = tests::read_file(pvtu);
        if (text.find("</VTKFile>") == std::string::npos)
          return false;
        for (std::sregex_iterator j(text.begin(), text.end(), source_attribute);
             j != end;
             ++j)
          if (tests::read_file("results/solution/" + (*j)[1].str())
                .find("</VTKFile>") == std::string::npos)
            return false;
        ++n_snapshots;
      }
    return true;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream("run.prm") << input;
  std::ofstream("short.prm")
    << std::regex_replace(input, std::regex("100000"), "0.02");

  // Killed at once, 0.3 s and 1 s after the run wrote its first statistics
  // (set-up takes a while in a Debug build).
  for (const char *delay : {"0", "0.3", "1"})
    {
      fs::remove_all("results");
      const std::string command =
        std::string("../../../rupture run.prm > run.log 2>&1 & pid=$!; "
                    "for i in $(seq 600); do test -s results/statistics && "
                    "break; sleep 0.1; done; sleep ") +
        delay + "; kill -KILL $pid; wait $pid 2> /dev/null";
      const int status = std::system(command.c_str());
      (void)status;
      std::size_t  n_rows = 0, n_receiver_rows = 0;
      unsigned int n_snapshots = 0;
      const bool   statistics  = rows_complete("results/statistics", n_rows);
      const bool receivers = rows_complete("results/top.dat", n_receiver_rows);
      const bool snapshots = snapshots_complete(n_snapshots);
      std::printf("killed after %s s: statistics complete: %s, receiver "
                  "series complete: %s, snapshots complete: %s, some steps "
                  "written: %s\n",
                  delay,
                  statistics ? "yes" : "no",
                  receivers ? "yes" : "no",
                  snapshots ? "yes" : "no",
                  n_rows >= 1 && n_snapshots >= 1 ? "yes" : "no");
    }

  // The next run cleans up after the killed one: a file of the user's
  // stays, the killed run's later snapshots and temporary files go.
  std::ofstream("results/notes.txt") << "mine\n";
  std::ofstream("results/solution/solution_00001.0.vtu.tmp") << "half";
  const int    code = tests::run({"short.prm"});
  unsigned int tmp = 0, pvtu = 0;
  for (const auto &entry : fs::recursive_directory_iterator("results"))
    {
      const std::string name = entry.path().string();
      tmp += name.find(".tmp") != std::string::npos;
      pvtu += name.find(".pvtu") != std::string::npos;
    }
  std::printf("next run: exit code %d, temporary files %u, snapshots %u (its "
              "own 3), the user's file kept: %s\n",
              code,
              tmp,
              pvtu,
              fs::exists("results/notes.txt") ? "yes" : "no");
}
