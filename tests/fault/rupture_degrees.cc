// Every polynomial degree p = 1..4 through a whole rupture with the
// split-node method, on one rank and on two, at a fixed node spacing
// (cells p times larger at degree p):
// - 2-D: TPV205-2D (prm/tpv205-2d) at 500 m node spacing, model 60 x 24
//   km, to t = 4 s. Rupture times (slip rate above 1 mm/s) at the
//   hypocentre and at +-4.5 km, and the slip at 4.5 km at the end. At
//   degree 4 the stations at +-4.5 km lie between nodes (a quarter into a
//   2 km cell) and are interpolated with the face's Lagrange weights.
// - 3-D: the square patch of split_node_3d.prm on a 12 x 4 x 12 km model
//   at 1 km node spacing (two cell layers across the fault), to t = 1.2 s:
//   the centre station's rupture time and final slip.
// Checked: every degree runs, every station ruptures (in 2-D later at
// 4.5 km than at the hypocentre), and the degrees agree with degree 1 to
// within 0.15 s in rupture time and 25 % in slip. That is no accuracy
// claim: at this node spacing (the cohesive zone spans a few nodes) the
// degrees differ by up to 0.11 s and 23 % (measured), the resolution's
// error; at 250 m node spacing the 4.5 km station ruptures at 1.49 s (Q2)
// and 1.44 s (Q4), Q1 at 100 m at 1.53 s. A node at the wrong place, a
// wrong tributary area or a broken kernel moves them by far more.
// The stable explicit step is printed per degree as a fraction of the
// degree-1 step at the same node spacing.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
  double
  final_value(const std::vector<std::vector<double>> &rows,
              const unsigned int                      column)
  {
    return rows.empty() ? -1 : rows.back()[column];
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const std::string top = std::string(SOURCE_DIR) + "/../../";

  std::vector<double> first(4);
  double              first_step = 0;
  bool                agree      = true;
  if (root)
    std::printf("2-D, TPV205-2D at 500 m node spacing:\n");
  for (unsigned int p = 1; p <= 4; ++p)
    {
      const std::string dir  = "tpv205-q" + std::to_string(p);
      const int         code = tests::run(
        {top + "prm/tpv205-2d/tpv205-2d.prm",
                 "--set",
                 "Test mode=true",
                 "--set",
                 "Damping/Fault zone damping=0",
                 "--set",
                 "Output directory=" + dir,
                 "--set",
                 "Output/Output interval=-1",
                 "--set",
                 "Output/Receivers=",
                 "--set",
                 "Discretization/Polynomial degree=" + std::to_string(p),
                 "--set",
                 "Scene/Box/Lower corner=-30000, -12000",
                 "--set",
                 "Scene/Box/Upper corner=30000, 12000",
                 "--set",
                 "Scene/Box/Number of cells=" + std::to_string(120 / p) + ", " +
                   std::to_string(48 / p),
                 "--set",
                 "Fault/Output/Stations=faultst000: 0, 0; faultst045: 4500, 0; "
                         "faultst-045: -4500, 0",
                 "--set",
                 "Time integration/End time=4"});
      if (!root)
        continue;
      const auto   s0 = tests::read_statistics(dir + "/faultst000.dat");
      const auto   s1 = tests::read_statistics(dir + "/faultst045.dat");
      const auto   s2 = tests::read_statistics(dir + "/faultst-045.dat");
      const double step =
        tests::find_number(dir + "/log.txt", "Stable explicit time step:");
      const std::vector<double> r = {tests::rupture_time(s0),
                                     tests::rupture_time(s1),
                                     tests::rupture_time(s2),
                                     final_value(s1, 1)};
      if (p == 1)
        first = r, first_step = step;
      for (unsigned int k = 0; k < 3; ++k)
        agree = agree && r[k] >= 0 && std::abs(r[k] - first[k]) <= 0.15;
      agree = agree && r[0] < r[1] && r[0] < r[2] &&
              std::abs(r[3] - first[3]) <= 0.25 * first[3];
      std::printf("  Q%u: exit code %d, stable step %.3f of Q1's, rupture "
                  "at 0, 4.5, -4.5 km: %.2f %.2f %.2f s, slip at 4.5 km "
                  "%.2f m\n",
                  p,
                  code,
                  step / first_step,
                  r[0],
                  r[1],
                  r[2],
                  r[3]);
    }
  if (root)
    std::printf(
      "  all stations rupture, all degrees within 0.15 s and 25 %% of Q1: "
      "%s\n",
      agree ? "yes" : "no");

  agree = true;
  if (root)
    std::printf("3-D, a square patch at 1 km node spacing:\n");
  for (unsigned int p = 1; p <= 4; ++p)
    {
      const std::string dir  = "patch-q" + std::to_string(p);
      const std::string n    = std::to_string(12 / p);
      const int         code = tests::run(
        {top + "tests/fault/split_node_3d.prm",
                 "--set",
                 "Output directory=" + dir,
                 "--set",
                 "Discretization/Polynomial degree=" + std::to_string(p),
                 "--set",
                 "Scene/Box/Lower corner=-6000, -2000, -6000",
                 "--set",
                 "Scene/Box/Upper corner=6000, 2000, 6000",
                 "--set",
                 "Scene/Box/Number of cells=" + n + ", 2, " + n,
                 "--set",
                 "Fault/Fault region=(abs(x) <= 4500 && abs(z) <= 4500) ? 1 : 0",
                 "--set",
                 "Fault/Initial traction=(abs(x) <= 1500 && abs(z) <= 1500) ? "
                         "81.6e6 : 70e6; -120e6; 0",
                 "--set",
                 "Fault/Output/Stations=center: 0, 0, 0",
                 "--set",
                 "Time integration/Time step=0"});
      if (!root)
        continue;
      const auto rows             = tests::read_statistics(dir + "/center.dat");
      const std::vector<double> r = {tests::rupture_time(rows),
                                     final_value(rows, 1)};
      if (p == 1)
        first = r;
      agree = agree && r[0] >= 0 && std::abs(r[0] - first[0]) <= 0.15 &&
              std::abs(r[1] - first[1]) <= 0.25 * first[1];
      std::printf("  Q%u: exit code %d, centre ruptures at %.2f s, final "
                  "slip %.2f m\n",
                  p,
                  code,
                  r[0],
                  r[1]);
    }
  if (root)
    std::printf("  all degrees within 0.15 s and 25 %% of Q1: %s\n",
                agree ? "yes" : "no");
}
