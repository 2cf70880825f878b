// Where the fault's output files put a point: along strike from <Fault/Plane
// point>, down-dip from the model's top, positive down, as SCEC's files do.
// The vertical fault of fault/split_node_3d.prm lies in a box whose top is
// z = 3000 m, with the plane point at z = 0: its stations at z = 0 are 3 km
// down-dip (0 and 1.5 km along strike). The fault's nodes (those inside the
// region |x| <= 2000, |z| <= 1500 m: its border is welded) are 7 x 5 at
// 500 m spacing, |z| <= 1000 m: 2 to 4 km down-dip in rupture_time.dat.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::freopen("/dev/null", "w", stdout);

  const std::string prm =
    std::string(SOURCE_DIR) + "/../fault/split_node_3d.prm";
  const int code = tests::run({prm,
                               "--set",
                               "Output directory=stations",
                               "--set",
                               "Time integration/End time=0.04"});
  std::printf("exit code %d\n", code);
  for (const std::string station : {"center", "edge"})
    {
      std::ifstream in("stations/" + station + ".dat");
      std::string   line;
      while (std::getline(in, line))
        if (line.rfind("# location", 0) == 0)
          std::printf("%s: %s\n", station.c_str(), line.c_str());
    }
  const auto rows   = tests::read_statistics("stations/rupture_time.dat");
  double     lowest = 1e300, highest = -1e300;
  for (const auto &row : rows)
    {
      lowest  = std::min(lowest, row[1]);
      highest = std::max(highest, row[1]);
    }
  std::printf("rupture_time.dat: %zu points, down-dip from %g to %g m\n",
              rows.size(),
              lowest,
              highest);
}
