// Anisotropic friction makes a rupture faster in the weaker direction. A
// square fault in the plane y = 0 (traction at split nodes, slip
// weakening with TPV3's coefficients and D_c = 0.2 m, 250 m cells), the
// prestress at 45 degrees between x and z, nucleated in a 2 km square
// patch. With isotropic friction the rupture runs along x and along z at
// the same speed (the problem is symmetric under x <-> z). With a friction
// ellipse twice as strong along e_2 = n x e_1, the slip turns towards the
// weaker e_1 and the front runs there in mode II, faster than along e_2 in
// mode III: e_1 = x makes the front along x faster, e_1 = z (then e_2 = x)
// the front along z. The prestress is scaled so that its ellipse norm
// |A^-1 tau| is the isotropic run's (70 MPa, 81.6 MPa in the patch). The
// front speed is the inverse slope of a straight line fitted to the
// rupture times (rupture_time.dat) of the nodes from 1.5 to 3.5 km from
// the centre along each axis, both ways.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace
{
  std::string
  input(const double ratio, const std::string &direction)
  {
    // |A^-1 tau| = tau sqrt(1/2 + 1/(2 r^2)) for tau at 45 degrees.
    const double scale =
      std::sqrt(0.5) / std::sqrt(0.5 + 0.5 / (ratio * ratio));
    char traction[400];
    std::snprintf(traction,
                  sizeof(traction),
                  "((abs(x) <= 1000 && abs(z) <= 1000) ? 81.6e6 : 70e6) * "
                  "%.15g; -120e6; -((abs(x) <= 1000 && abs(z) <= 1000) ? "
                  "81.6e6 : 70e6) * %.15g",
                  scale,
                  scale);
    return std::string("set Dimension = 3\n"
                       "set Test mode = true\n"
                       "subsection Scene\n"
                       "  subsection Box\n"
                       "    set Lower corner = -4500, -1000, -4500\n"
                       "    set Upper corner = 4500, 1000, 4500\n"
                       "    set Number of cells = 36, 8, 36\n"
                       "  end\n"
                       "end\n"
                       "subsection Material\n"
                       "  set Density = 2670\n"
                       "  set P-wave speed = 6000\n"
                       "  set S-wave speed = 3464\n"
                       "end\n"
                       "subsection Fault\n"
                       "  set Model = traction at split nodes\n"
                       "  set Plane point = 0, 0, 0\n"
                       "  set Plane normal = 0, 1, 0\n"
                       "  set Fault region = (abs(x) <= 4000 && abs(z) <= "
                       "4000) ? 1 : 0\n"
                       "  set Initial traction = ") +
           traction +
           "\n"
           "  subsection Linear slip weakening\n"
           "    set Static friction coefficient = 0.677\n"
           "    set Dynamic friction coefficient = 0.525\n"
           "    set Slip-weakening distance = 0.2\n"
           "  end\n"
           "  subsection Anisotropic friction\n"
           "    set Strength ratio = " +
           std::to_string(ratio) +
           "\n"
           "    set First direction = " +
           direction +
           "\n"
           "  end\n"
           "  subsection Output\n"
           "    set Output interval = 1.7\n"
           "  end\n"
           "end\n"
           "subsection Boundary conditions\n"
           "  set Absorbing = west, east, south, north, bottom, top\n"
           "end\n"
           "subsection Time integration\n"
           "  set Scheme = explicit central difference\n"
           "  set End time = 1.7\n"
           "  set Time step = 0.01\n"
           "end\n"
           "subsection Output\n"
           "  set Output interval = -1\n"
           "end\n";
  }

  /// The front speed (m/s) along strike (x, @p along_strike) or down dip
  /// (z), from rows (along strike, down dip, rupture time), the centre at
  /// down-dip distance @p centre.
  double
  front_speed(const std::vector<std::vector<double>> &rows,
              const bool                              along_strike,
              const double                            centre)
  {
    double       sx = 0, st = 0, sxx = 0, sxt = 0;
    unsigned int n = 0;
    for (const auto &row : rows)
      {
        const double j = row[0], k = row[1] - centre, t = row[2];
        const double across = along_strike ? k : j;
        const double d      = std::abs(along_strike ? j : k);
        if (std::abs(across) > 1 || d < 1500 || d > 3500 || t > 1e8)
          continue;
        sx += d;
        st += t;
        sxx += d * d;
        sxt += d * t;
        ++n;
      }
    if (n < 10)
      return 0;
    const double slope = (n * sxt - sx * st) / (n * sxx - sx * sx);
    return 1 / slope;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  struct Case
  {
    double      ratio;
    std::string direction, name;
  };
  for (const Case &c : {Case{1, "1, 0, 0", "isotropic"},
                        Case{2, "1, 0, 0", "ratio 2, e_1 = x"},
                        Case{2, "0, 0, 1", "ratio 2, e_1 = z"}})
    {
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::ofstream("front.prm") << input(c.ratio, c.direction);
      MPI_Barrier(MPI_COMM_WORLD);
      tests::run_in("front", {"front.prm"}, {});
      const auto rows = tests::read_statistics("front/rupture_time.dat");
      // The down-dip distance of the centre: the middle of the range.
      double low = 1e300, high = -1e300;
      for (const auto &row : rows)
        {
          low  = std::min(low, row[1]);
          high = std::max(high, row[1]);
        }
      const double x = front_speed(rows, true, 0.5 * (low + high));
      const double z = front_speed(rows, false, 0.5 * (low + high));
      const bool   expected =
        x > 0 && z > 0 &&
        (c.ratio == 1 ?
           std::abs(x / z - 1) < 0.02 :
           (c.direction == "1, 0, 0" ? x > 1.15 * z : z > 1.15 * x));
      std::printf("%-18s front along x %4.0f m/s, along z %4.0f m/s: %s\n",
                  c.name.c_str(),
                  std::round(x / 10) * 10,
                  std::round(z / 10) * 10,
                  !expected ?
                    "not as expected" :
                    (c.ratio == 1 ? "equal (within 2 %)" :
                                    "faster along e_1, the weaker direction "
                                    "(by more than 15 %)"));
    }
}
