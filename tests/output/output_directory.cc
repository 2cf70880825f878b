// The rules of the output directory (issue 18): a run writes a manifest of
// its files; the next run into the directory removes exactly those (also
// the pieces of ranks it does not have, and the snapshots of a longer
// run) and nothing a user put there; a second concurrent run is refused
// by the lock and changes nothing; a lock left by a dead run is taken
// over; station and receiver files may not collide; SIGTERM stops a run
// cleanly after a step with code 143 and every file complete.

#include <deal.II/base/mpi.h>

#include "../tests.h"
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <set>
#include <thread>

namespace fs = std::filesystem;

namespace
{
  std::string
  input(const double end_time, const std::string &extra = "")
  {
    return R"(set Dimension = 2
set Test mode = true
set Output directory = results
subsection Scene
  subsection Box
    set Number of cells = 4
  end
end
subsection Boundary conditions
  set Fixed = bottom
end
subsection Loads
  set Gravity = 9.81
end
subsection Time integration
  set Time step = 0.01
  set End time = )" +
           std::to_string(end_time) + R"(
end
subsection Output
  set Output interval = 0.01
  set Cells per output piece = 8
  set Receivers = top: 500, 1000
end
)" + extra;
  }

  // The files below results/, sorted, with a '*' for the rank counts that
  // vary: printed so that the serial and 2-rank outputs agree.
  std::set<std::string>
  listing()
  {
    std::set<std::string> files;
    for (const auto &entry : fs::recursive_directory_iterator("results"))
      if (entry.is_regular_file())
        files.insert(fs::relative(entry.path(), "results").string());
    return files;
  }

  void
  print(const std::string &title, const std::set<std::string> &files)
  {
    unsigned int pieces = 0, manifests = 0, tmp = 0;
    std::printf("%s:", title.c_str());
    for (const auto &f : files)
      if (f.find(".vtu") != std::string::npos && f.find("solution/") == 0)
        ++pieces;
      else if (f.rfind(".rupture-manifest.", 0) == 0)
        ++manifests;
      else
        {
          if (f.find(".tmp") != std::string::npos)
            ++tmp;
          std::printf(" %s", f.c_str());
        }
    // The manifests are one per rank that wrote: checked separately.
    (void)manifests;
    std::printf("\n  (and %u pieces, %u temporary files)\n", pieces, tmp);
  }

  // The message from @p key on (rank 0 prints it; the others have none).
  std::string
  from(const std::string &errors, const std::string &key)
  {
    const auto at = errors.find(key);
    return at == std::string::npos ? std::string() : errors.substr(at);
  }

  int
  run(const std::string &prm, const MPI_Comm comm, std::string &errors)
  {
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      std::ofstream("run.prm") << prm;
    MPI_Barrier(comm);
    std::ostringstream sink, error_sink;
    std::streambuf    *old     = std::cout.rdbuf(sink.rdbuf());
    std::streambuf    *old_err = std::cerr.rdbuf(error_sink.rdbuf());
    const int          code    = rupture::run_program({"run.prm"}, comm);
    std::cout.rdbuf(old);
    std::cerr.rdbuf(old_err);
    errors = error_sink.str();
    return code;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const unsigned int n_ranks =
    dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  if (!root)
    std::freopen("/dev/null", "w", stdout);
  if (root)
    fs::remove_all("results");
  std::string errors;

  // 1. A run of 5 steps on all ranks, then a file of the user's.
  int code = run(input(0.05), MPI_COMM_WORLD, errors);
  std::printf("first run: exit code %d\n", code);
  std::set<std::string> first;
  unsigned int          first_pieces = 0;
  if (root)
    {
      first = listing();
      for (const auto &f : first)
        first_pieces += f.find(".vtu") != std::string::npos;
      print("files", first);
      std::printf("  manifests = ranks: %s\n",
                  fs::exists("results/.rupture-manifest." +
                             std::to_string(n_ranks - 1)) &&
                      !fs::exists("results/.rupture-manifest." +
                                  std::to_string(n_ranks)) ?
                    "yes" :
                    "no");
      std::ofstream("results/notes.txt") << "the user's own file\n";
      fs::create_directories("results/solution");
      std::ofstream("results/solution/my_plot.py") << "# the user's\n";
      // What a killed run leaves: a temporary file of a manifest entry.
      std::ofstream("results/solution/solution_00005.0.vtu.tmp") << "half";
    }

  // 2. A shorter run on rank 0 alone: the later snapshots and the other
  //    ranks' pieces of the first run go; the user's files stay.
  MPI_Comm alone;
  MPI_Comm_split(MPI_COMM_WORLD, root ? 0 : MPI_UNDEFINED, 0, &alone);
  if (root)
    {
      code = run(input(0.02), alone, errors);
      std::printf("second run (one rank, 2 steps): exit code %d\n", code);
      const auto second = listing();
      print("files", second);
      unsigned int pieces = 0;
      for (const auto &f : second)
        pieces +=
          f.find(".vtu") != std::string::npos && f.find("solution/") == 0;
      std::printf("  pieces: %u (3 snapshots of 2 pieces; the first run had "
                  "%s)\n",
                  pieces,
                  first_pieces > pieces ? "more" : "not more");
      std::printf("  statistics rows: %zu\n",
                  tests::read_statistics("results/statistics").size());
      MPI_Comm_free(&alone);
    }
  MPI_Barrier(MPI_COMM_WORLD);

  // 3. A run that holds the lock: a second run is refused and changes
  //    nothing, on every rank.
  int lock_fd = -1;
  if (root)
    {
      lock_fd = ::open("results/.rupture.lock", O_RDWR | O_CREAT, 0644);
      const std::string holder = "process 4242 on elsewhere, started today\n";
      if (::write(lock_fd, holder.data(), holder.size()) < 0 ||
          ::flock(lock_fd, LOCK_EX | LOCK_NB) != 0)
        std::printf("cannot take the lock in the test\n");
    }
  std::set<std::string> before;
  if (root)
    before = listing();
  code = run(input(0.05), MPI_COMM_WORLD, errors);
  std::printf("concurrent run: exit code %d\n  %s",
              code,
              from(errors, "Error").c_str());
  if (root)
    {
      std::printf("  directory unchanged: %s\n",
                  listing() == before ? "yes" : "no");
      // The holder dies: its lock file stays, its flock goes.
      ::close(lock_fd);
    }
  code = run(input(0.03), MPI_COMM_WORLD, errors);
  std::printf("run after the holder died: exit code %d, lock file left: %s\n",
              code,
              fs::exists("results/.rupture.lock") ? "yes" : "no");

  // 4. Colliding file names.
  code = run(input(0.02,
                   "subsection Output\n  set Receivers = a: 250, 250\nend\n"
                   "subsection Fault\n  set Model = penalty contact\n"
                   "  set Plane point = 0, 500\n  set Plane normal = 0, 1\n"
                   "  subsection Output\n    set Stations = a: 500, 500\n"
                   "  end\nend\n"),
             MPI_COMM_WORLD,
             errors);
  std::printf("station and receiver of one name: exit code %d\n  %s",
              code,
              from(errors, "Error").c_str());

  // 5. SIGTERM into a long run (500 000 steps), once it is stepping (its
  //    statistics of step 0 exist; the earlier run's are removed first,
  //    so that a loaded machine's slow set-up cannot be hit): it ends
  //    after the step it is in, with every file written and complete.
  std::thread signaller;
  if (root)
    {
      fs::remove("results/statistics");
      signaller = std::thread([]() {
        for (unsigned int i = 0; i < 1200 && !fs::exists("results/statistics");
             ++i)
          std::this_thread::sleep_for(std::chrono::milliseconds(100));
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        ::kill(::getpid(), SIGTERM);
      });
    }
  MPI_Barrier(MPI_COMM_WORLD);
  code = run(input(5000.), MPI_COMM_WORLD, errors);
  if (root)
    signaller.join();
  std::printf("SIGTERM: exit code %d\n  %s",
              code,
              from(errors, "Stopped").substr(0, 30).c_str());
  std::printf("\n");
  if (root)
    {
      // The number of snapshots depends on when the signal came: count.
      unsigned int tmp = 0, snapshots = 0;
      for (const auto &f : listing())
        {
          tmp += f.find(".tmp") != std::string::npos;
          snapshots += f.find(".pvtu") != std::string::npos;
        }
      std::printf("  temporary files: %u; snapshots: one per step: %s\n",
                  tmp,
                  tests::read_statistics("results/statistics").size() ==
                      snapshots ?
                    "yes" :
                    "no");
      // The statistics end with the step the message names.
      const auto         rows = tests::read_statistics("results/statistics");
      const std::string  key  = "after step ";
      const unsigned int step =
        std::stoul(errors.substr(errors.find(key) + key.size()));
      std::printf("  statistics rows = steps + 1: %s; receiver rows = "
                  "statistics rows: %s\n",
                  rows.size() == step + 1 ? "yes" : "no",
                  tests::read_statistics("results/top.dat").size() ==
                      rows.size() ?
                    "yes" :
                    "no");
      std::printf("  last snapshot is the stop's: %s\n",
                  fs::exists("results/solution/solution_" +
                             std::string(5 - std::min<std::size_t>(
                                               5, std::to_string(step).size()),
                                         '0') +
                             std::to_string(step) + ".pvtu") ?
                    "yes" :
                    "no");
    }
  return 0;
}
