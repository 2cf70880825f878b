// The fault's own output interval (Fault/Output/Output interval): the fault
// surface can be written more often than the volume, or without any volume
// output; empty means the volume's interval; a value that is not one
// finite number is an error naming the entry. The times listed in
// fault.pvd and solution.pvd are printed.

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
}
