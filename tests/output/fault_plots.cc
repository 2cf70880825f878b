// contrib/plot-fault on the output of a small 3-D and a 2-D fault run: its
// self-check reads every fault snapshot (arrays complete, finite and
// consistent with fault.pvd) and writes the PNG figure; a field it does not
// know is refused with exit code 1.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace
{
  int
  plot(const std::string &arguments)
  {
    const std::string command = std::string(SOURCE_DIR) +
                                "/../../contrib/plot-fault " + arguments +
                                " > plot.txt 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  bool
  exists(const std::string &file)
  {
    return std::ifstream(file).good();
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string faults = std::string(SOURCE_DIR) + "/../fault/";

  std::printf("3-D split-node run, snapshots every 0.2 s:\n");
  if (tests::run({faults + "split_node_3d.prm",
                  "--set",
                  "Output directory=plots-3d",
                  "--set",
                  "Output/Output interval=0.2"}) != 0)
    std::printf("  run failed\n");
  int code = plot("--check plots-3d --fields slip,friction,rupture-time");
  std::printf("  --check exit code %d, figure written: %s\n",
              code,
              exists("plots-3d/fault-snapshots.png") ? "yes" : "no");

  std::printf("2-D stick-slip run, a snapshot every step:\n");
  if (tests::run({faults + "stick_slip_parallel.prm",
                  "--set",
                  "Output directory=plots-2d",
                  "--set",
                  "Output/Output interval=0"}) != 0)
    std::printf("  run failed\n");
  code = plot("--check plots-2d --output plots-2d/slip.png");
  std::printf("  --check exit code %d, figure written: %s\n",
              code,
              exists("plots-2d/slip.png") ? "yes" : "no");

  std::printf("unknown field: exit code %d\n",
              plot("plots-2d --fields temperature"));
}
