// A reduced 3-D TPV101 (prm/tpv101/tpv101.prm at degree 1, regularised
// rate-and-state
// friction with the aging law, the velocity-strengthening border, the
// initial slip velocity of 1e-12 m/s and the smooth nucleation pulse) on
// 1500 m cells instead of 100 m, in a box of 48 km x 12 km x 33 km around
// the core (graded cells, absorbing sides) instead of 120 km x 90 km x
// 100 km, far too coarse for the rupture to run, but enough to check the
// 3-D set-up through the benchmark's outputs:
// - the initial state follows from the traction: log10(theta) = 9.2058 at
//   the hypocentre (theta = 1.606e9 s where a = 0.008) and 13.2058 far
//   out in the strengthening border (a = 0.016), from the statistics;
// - the nine SCEC stations are written with nine columns (n-stress,
//   log-theta);
// - the pulse accelerates the hypocentre by many orders of magnitude in
//   its first 2 s;
// - without the pulse nothing happens: the largest slip stays below
//   1e-10 m for the 12 s of the benchmark.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const std::string prm =
    std::string(SOURCE_DIR) + "/../../prm/tpv101/tpv101.prm";
  const std::vector<std::string> coarse = {
    "--set",
    "Test mode=true",
    "--set",
    "Discretization/Polynomial degree=1",
    "--set",
    "Output/Output interval=-1",
    "--set",
    "Scene/Box/Number of cells=24, 2, 14",
    "--set",
    "Scene/Box/Lower corner=-24000, -6000, -16500",
    "--set",
    "Scene/Box/Upper corner=24000, 6000, 16500",
    // The grading of degree 1 (the prm's is that of its degree 3).
    "--set",
    "Scene/Box/Grading/Growth factor=1.2"};

  std::vector<std::string> args = {prm};
  args.insert(args.end(), coarse.begin(), coarse.end());
  for (const std::string s :
       {"Output directory=tpv101", "Time integration/End time=2"})
    {
      args.push_back("--set");
      args.push_back(s);
    }
  const int code = tests::run(args);
  if (root)
    {
      std::printf("with the pulse: exit code %d\n", code);
      unsigned int n = 0, columns = 0;
      for (const std::string name : {"000dp030",
                                     "000dp075",
                                     "000dp120",
                                     "090dp075",
                                     "-090dp075",
                                     "120dp030",
                                     "-120dp030",
                                     "120dp120",
                                     "-120dp120"})
        {
          const auto rows =
            tests::read_statistics("tpv101/faultst" + name + ".dat");
          if (!rows.empty())
            {
              ++n;
              columns = std::max<unsigned int>(columns, rows.back().size());
            }
        }
      std::printf("stations written: %u, columns: %u\n", n, columns);
      const auto hypo = tests::read_statistics("tpv101/faultst000dp075.dat");
      std::printf("hypocentre: log-theta at t = 0: %.4f\n", hypo.front()[8]);
      double peak = 0;
      for (const auto &r : hypo)
        peak = std::max(peak, std::abs(r[2]));
      std::printf("hypocentre slip rate above 1e-6 m/s by t = 2 s: %s\n",
                  peak > 1e-6 ? "yes" : "NO");
      const auto  stats = tests::read_statistics("tpv101/statistics");
      const auto &first = stats.front();
      std::printf("statistics at t = 0: log10(theta) from %.4f to %.4f\n",
                  first[first.size() - 2],
                  first[first.size() - 1]);
    }

  args = {prm};
  args.insert(args.end(), coarse.begin(), coarse.end());
  for (const std::string s : {"Output directory=tpv101-quiet",
                              "Fault/Traction perturbation/Traction="})
    {
      args.push_back("--set");
      args.push_back(s);
    }
  const int quiet = tests::run(args);
  if (root)
    {
      const auto rows    = tests::read_statistics("tpv101-quiet/statistics");
      double     largest = 0;
      for (const auto &r : rows)
        largest = std::max(largest, std::abs(r[14]));
      std::printf("without the pulse: exit code %d, t = %.1f s, largest "
                  "slip below 1e-10 m: %s\n",
                  quiet,
                  rows.back()[1],
                  largest < 1e-10 ? "yes" : "NO");
    }
}
