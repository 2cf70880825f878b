// What a run leaves in its output directory: log.txt mirrors the screen,
// parameters.prm reproduces the run, statistics documents its columns and
// has one row per step, solution.pvd lists one .pvtu per output time and
// each .pvtu exists.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cstdio>
#include <regex>

namespace
{
  const std::string input = R"(set Dimension = 2
set Test mode = true
set Output directory = results
subsection Scene
  subsection Box
    set Number of cells = 2
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
  set End time = 0.05
end
subsection Output
  set Output interval = 0.02
  set Cells per output piece = 3
end
)";
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Only rank 0 reports; all ranks take part in the runs.
  const bool root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  if (!root)
    std::freopen("/dev/null", "w", stdout);
  if (root)
    std::ofstream("run.prm") << input;
  MPI_Barrier(MPI_COMM_WORLD);

  // Capture the screen to compare it with log.txt.
  std::ostringstream screen;
  std::streambuf    *old  = std::cout.rdbuf(screen.rdbuf());
  const int          code = rupture::run_program({"run.prm"}, MPI_COMM_WORLD);
  std::cout.rdbuf(old);
  std::printf("exit code: %d\n", code);

  std::printf("log.txt equals the screen output: %s\n",
              !root || tests::read_file("results/log.txt") == screen.str() ?
                "yes" :
                "no");

  const std::string statistics = tests::read_file("results/statistics");
  std::printf("statistics header:\n");
  std::istringstream lines(statistics);
  std::string        line;
  while (std::getline(lines, line))
    if (!line.empty() && line[0] == '#')
      std::printf("  %s\n", line.c_str());
  const auto rows = tests::read_statistics("results/statistics");
  std::printf("statistics rows (steps 0..5): %zu\n", rows.size());

  const std::string pvd = tests::read_file("results/solution.pvd");
  const std::regex  dataset("file=\"(solution/solution_[0-9]+\\.pvtu)\"");
  std::printf("solution.pvd records:\n");
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), dataset);
       it != std::sregex_iterator();
       ++it)
    {
      // Each .pvtu lists its pieces (4 cells in pieces of at most 3: one
      // piece of 3 and one of 1 on one rank; one of 2 on each of 2 ranks),
      // and each piece exists.
      const std::string pvtu_name = (*it)[1].str();
      const std::string pvtu      = tests::read_file("results/" + pvtu_name);
      const std::regex  piece("Source=\"([^\"]+\\.vtu)\"");
      unsigned int      n_pieces = 0, n_found = 0;
      for (auto p = std::sregex_iterator(pvtu.begin(), pvtu.end(), piece);
           p != std::sregex_iterator();
           ++p, ++n_pieces)
        if (tests::file_exists("results/solution/" + (*p)[1].str()))
          ++n_found;
      std::printf("  %s exists: %s, %u pieces, %u of them found\n",
                  pvtu_name.c_str(),
                  tests::file_exists("results/" + pvtu_name) ? "yes" : "no",
                  n_pieces,
                  n_found);
    }

  // The recorded parameters repeat the run exactly.
  const auto first = rows;
  tests::run(
    {"results/parameters.prm", "--set", "Output directory=results-again"});
  const auto again = tests::read_statistics("results-again/statistics");
  bool       same  = (again.size() == first.size());
  for (unsigned int i = 0; same && i < again.size(); ++i)
    for (unsigned int c = 0; c < again[i].size(); ++c)
      if (c != 9 && again[i][c] != first[i][c]) // column 10 is wall time
        same = false;
  std::printf("parameters.prm repeats the run: %s\n", same ? "yes" : "no");
  std::printf("no temporary files left: %s\n",
              !tests::file_exists("results/statistics.tmp") &&
                  !tests::file_exists("results/solution.pvd.tmp") ?
                "yes" :
                "no");
}
