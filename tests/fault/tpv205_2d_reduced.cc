// A reduced TPV205-2D (prm/tpv205-2d/tpv205-2d.prm at degree 1 without
// damping, with 500 m cells
// instead of 100 m, to t = 6 s instead of 12 s): the explicit split-node
// method in 2-D through the benchmark's outputs, on one rank and on two.
// The run writes the seven on-fault stations in the SCEC format and the
// two off-fault receivers 3 km from the fault at x = +-12 km. Checked:
// - the rupture spreads both ways from the nucleation zone: every station
//   within 7.5 km of it ruptures (slip rate above 1 mm/s), later the
//   farther it is;
// - it runs faster towards the 78 MPa patch (x < 0) than towards the
//   62 MPa one: the station at -7.5 km ruptures before the one at +7.5 km
//   (100 m, 12 s, in doc/verification.md: 1.833 s against 2.648 s);
// - the off-fault receivers move, and their fault-normal displacements
//   have opposite signs on the two sides of the hypocentre while the
//   fault-parallel ones have the same sign (the in-plane radiation
//   pattern).
// Measured at 500 m: rupture at 0.04, 1.51, 1.51, 1.94 and 2.91 s at
// x = 0, -4.5, 4.5, -7.5 and 7.5 km (100 m: 0.007, -, 1.53, 1.83 and
// 2.65 s).

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const std::string top  = std::string(SOURCE_DIR) + "/../../";
  const int         code = tests::run({top + "prm/tpv205-2d/tpv205-2d.prm",
                                       "--set",
                                       "Test mode=true",
                                       "--set",
                                       "Discretization/Polynomial degree=1",
                                       "--set",
                                       "Damping/Fault zone damping=0",
                                       "--set",
                                       "Output directory=tpv205",
                                       "--set",
                                       "Output/Output interval=1000",
                                       "--set",
                                       "Scene/Box/Number of cells=120, 60",
                                       "--set",
                                       "Time integration/End time=6"});
  if (!root)
    return 0;
  std::printf("exit code %d\n", code);

  std::map<std::string, double> t;
  for (const std::string name :
       {"000", "045", "-045", "075", "-075", "120", "-120"})
    {
      const auto rows =
        tests::read_statistics("tpv205/faultst" + name + ".dat");
      t[name] = tests::rupture_time(rows);
      std::printf("station %s: %zu rows\n", name.c_str(), rows.size());
    }
  const bool inner = t["000"] >= 0 && t["045"] >= 0 && t["-045"] >= 0 &&
                     t["075"] >= 0 && t["-075"] >= 0;
  std::printf("stations within 7.5 km rupture: %s\n", inner ? "yes" : "no");
  std::printf("later the farther from the hypocentre: %s\n",
              (inner && t["000"] < t["045"] && t["045"] < t["075"] &&
               t["000"] < t["-045"] && t["-045"] < t["-075"]) ?
                "yes" :
                "no");
  std::printf("faster towards the 78 MPa patch (-7.5 km before +7.5 km): %s\n",
              (inner && t["-075"] < t["075"]) ? "yes" : "no");

  // Receivers: t x-disp x-vel y-disp y-vel.
  const auto plus  = tests::read_statistics("tpv205/body030st120dp000.dat");
  const auto minus = tests::read_statistics("tpv205/body030st-120dp000.dat");
  if (plus.empty() || minus.empty())
    {
      std::printf("receiver files missing\n");
      return 0;
    }
  const auto &p = plus.back(), &m = minus.back();
  std::printf("receivers moved by more than 1 cm: %s\n",
              (std::hypot(p[1], p[3]) > 0.01 && std::hypot(m[1], m[3]) > 0.01) ?
                "yes" :
                "no");
  std::printf("fault-normal displacements of opposite sign: %s\n",
              p[3] * m[3] < 0 ? "yes" : "no");
  std::printf("fault-parallel displacements of the same sign: %s\n",
              p[1] * m[1] > 0 ? "yes" : "no");
}
