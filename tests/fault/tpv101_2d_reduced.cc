// A reduced TPV101-2D (prm/tpv101-2d/tpv101-2d.prm, regularised
// rate-and-state friction with the aging law, the smooth nucleation pulse
// and the velocity-strengthening border): 250 m cells instead of 100 m, to
// t = 5 s instead of 12 s, in a box of 40 km x 12 km instead of 60 km x
// 30 km (its absorbing sides take the waves the larger box would let
// pass), on one rank and on two. Checked:
// - the rupture nucleates at the hypocentre and spreads both ways: the
//   stations at 0, +-3 and +-6 km rupture (slip rate above 1 mm/s), later
//   the farther they are, symmetrically (the two sides within one step);
// - the station files have the nine SCEC rate-and-state columns and
//   log-theta falls where the fault slips (the state is renewed);
// - the statistics carry the state variable's range;
// - without the nucleation pulse nothing happens: the largest slip stays
//   below 1e-10 m over the 12 s of the benchmark (1000 m cells).

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
  const std::string prm  = top + "prm/tpv101-2d/tpv101-2d.prm";
  const int         code = tests::run({prm,
                                       "--set",
                                       "Test mode=true",
                                       "--set",
                                       "Output directory=tpv101",
                                       "--set",
                                       "Output/Output interval=-1",
                                       "--set",
                                       "Scene/Box/Number of cells=160, 48",
                                       "--set",
                                       "Discretization/Polynomial degree=1",
                                       "--set",
                                       "Scene/Box/Lower corner=-20000, -6000",
                                       "--set",
                                       "Scene/Box/Upper corner=20000, 6000",
                                       "--set",
                                       "Fault/Output/Stations=faultst000: 0, 0; "
                                               "faultst030: 3000, 0; faultst-030: "
                                               "-3000, 0; faultst060: 6000, 0; "
                                               "faultst-060: -6000, 0",
                                       "--set",
                                       "Time integration/End time=5"});
  if (root)
    {
      std::printf("exit code %d\n", code);
      std::map<std::string, double> t;
      for (const std::string name : {"000", "030", "-030", "060", "-060"})
        {
          const auto rows =
            tests::read_statistics("tpv101/faultst" + name + ".dat");
          t[name] = tests::rupture_time(rows);
          std::printf("station %s: %zu rows, %zu columns, ruptures: %s\n",
                      name.c_str(),
                      rows.size(),
                      rows.empty() ? 0 : rows.back().size(),
                      t[name] >= 0 ? "yes" : "no");
          if (name == "000" && !rows.empty())
            std::printf("  log-theta falls from %.3f: %s\n",
                        rows.front()[8],
                        rows.back()[8] < rows.front()[8] - 1 ? "yes" : "NO");
        }
      const bool all = t["000"] >= 0 && t["030"] >= 0 && t["-030"] >= 0 &&
                       t["060"] >= 0 && t["-060"] >= 0;
      std::printf("later the farther from the hypocentre: %s\n",
                  (all && t["000"] < t["030"] && t["030"] < t["060"] &&
                   t["000"] < t["-030"] && t["-030"] < t["-060"]) ?
                    "yes" :
                    "no");
      const auto   stats = tests::read_statistics("tpv101/statistics");
      const double dt    = stats.back()[2];
      std::printf("symmetric within a step: %s\n",
                  (all && std::abs(t["060"] - t["-060"]) <= 1.01 * dt &&
                   std::abs(t["030"] - t["-030"]) <= 1.01 * dt) ?
                    "yes" :
                    "no");
      // The last two columns: the range of log10(theta) over the fault.
      const auto &last = stats.back();
      std::printf("statistics: log10(theta) from %.2f to %.2f\n",
                  last[last.size() - 2],
                  last[last.size() - 1]);
    }

  const int quiet = tests::run({prm,
                                "--set",
                                "Test mode=true",
                                "--set",
                                "Output directory=tpv101-quiet",
                                "--set",
                                "Output/Output interval=-1",
                                "--set",
                                "Scene/Box/Number of cells=60, 30",
                                "--set",
                                "Fault/Traction perturbation/Traction="});
  if (root)
    {
      const auto rows    = tests::read_statistics("tpv101-quiet/statistics");
      double     largest = 0;
      for (const auto &r : rows)
        largest = std::max(largest, std::abs(r[14]));
      std::printf("without nucleation: exit code %d, t = %.1f s, largest "
                  "slip below 1e-10 m: %s\n",
                  quiet,
                  rows.back()[1],
                  largest < 1e-10 ? "yes" : "NO");
    }
}
