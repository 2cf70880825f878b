// The fault's own output interval (Fault/Output/Output interval): the fault
// surface can be written more often than the volume, or without any volume
// output; empty means the volume's interval; a value that is not one
// finite number is an error naming the entry. The times listed in
// fault.pvd and solution.pvd are printed. After a loading phase, the
// loading phase's snapshots are time series of their own
// (solution-loading.pvd, fault-loading.pvd) and those of the dynamic phase
// count from its start, as the statistics' time column does (with the phase
// and the time since the start of the run in its last two columns).

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cstdio>
#include <fstream>
#include <regex>

namespace
{
  void
  list_times(const std::string &file)
  {
    std::ifstream in(file);
    if (!in)
      {
        std::printf("  %s: none\n", file.c_str());
        return;
      }
    const std::string text = tests::read_file(file);
    const std::regex  dataset("timestep=\"([^\"]+)\"");
    std::printf("  %s times:", file.c_str());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), dataset);
         it != std::sregex_iterator();
         ++it)
      std::printf(" %g", std::stod((*it)[1].str()));
    std::printf("\n");
  }

  void
  run_case(const std::string &name,
           const std::string &volume,
           const std::string &fault)
  {
    const std::string prm =
      std::string(SOURCE_DIR) + "/../fault/stick_slip_parallel.prm";
    std::string errors;
    const int   code =
      tests::run_capture({prm,
                          "--set",
                          "Output directory=" + name,
                          "--set",
                          "Output/Output interval=" + volume,
                          "--set",
                          "Fault/Output/Output interval=" + fault},
                         errors);
    std::printf("volume interval <%s>, fault interval <%s>: exit code %d\n",
                volume.c_str(),
                fault.c_str(),
                code);
    if (code != 0)
      std::printf("%s", errors.c_str());
    else
      {
        list_times(name + "/fault.pvd");
        list_times(name + "/solution.pvd");
      }
  }

  void
  run_loading_case()
  {
    const std::string prm =
      std::string(SOURCE_DIR) + "/../fault/load_sequence_block_jacobi.prm";
    std::string errors;
    const int   code = tests::run_capture({prm,
                                           "--set",
                                           "Output directory=loading",
                                           "--set",
                                           "Output/Output interval=1000",
                                           "--set",
                                           "Fault/Output/Output interval=0.25",
                                           "--set",
                                           "Time integration/End time=0.5"},
                                        errors);
    std::printf("loading phase, then 0.5 s of rupture: exit code %d\n", code);
    if (code != 0)
      {
        std::printf("%s", errors.c_str());
        return;
      }
    for (const std::string f : {"solution-loading.pvd",
                                "fault-loading.pvd",
                                "solution.pvd",
                                "fault.pvd"})
      list_times("loading/" + f);
    // step, time, phase, time since the start: the first and last row of
    // each phase.
    const auto rows  = tests::read_statistics("loading/statistics");
    const auto phase = [&](const unsigned int i) {
      return rows[i][rows[i].size() - 2];
    };
    for (unsigned int i = 0; i < rows.size(); ++i)
      if (i == 0 || i + 1 == rows.size() || phase(i) != phase(i - 1) ||
          phase(i) != phase(i + 1))
        std::printf("  statistics: step %g, time %g s, phase %g, %g s "
                    "since the start\n",
                    rows[i][0],
                    rows[i][1],
                    phase(i),
                    rows[i].back());
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::freopen("/dev/null", "w", stdout);

  // The fault every 4 s, no volume.
  run_case("fault-only", "-1", "4");
  // The fault every step, the volume every 5 s.
  run_case("both", "5", "0");
  // Empty: the fault follows the volume.
  run_case("same", "5", "");
  // No fault surface.
  run_case("none", "5", "-1");
  // Not a number.
  run_case("bad", "5", "often");
  run_case("bad-inf", "5", "inf");
  run_loading_case();
}
