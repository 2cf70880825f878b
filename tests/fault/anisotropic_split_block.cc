// Anisotropic friction at a single split node under a turning load (the
// closed-form block of tests/fault/anisotropic_contact for the other fault
// method, traction at split nodes, explicit), at the centre station of a
// 3 km square fault of 500 m cells (5 x 5 node pairs, welded at its
// border) under a uniform load: each pair is a block on an elastic
// support. The normal traction is 120 MPa and the friction coefficient 0.6
// (no weakening): strength S = 72 MPa. The shear load starts at 36 MPa
// along strike (x) and grows at 100 MPa/s along dip, so that it turns from
// strike towards dip while it grows. The friction ellipse |A^-1 tau| <= S
// is twice as strong along dip (r = 2, e_1 = x):
//  - stick below K: the block stays stuck while the shear traction exceeds
//    the isotropic strength S (up to 1.8 S), until its ellipse norm
//    reaches S (isotropic friction: as soon as |tau| = S);
//  - sliding: the traction stays on the ellipse (|A^-1 tau| = S), the slip
//    rate lies along the ellipse's normal A^-2 tau (within 1 degree), not
//    along the traction, and the dissipated power tau . V equals S |A V|
//    (the review paper's eq. 5.2; within 1 %).

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace
{
  constexpr double strength = 0.6 * 120; // MPa

  std::string
  input(const double ratio)
  {
    return "set Dimension = 3\n"
           "set Test mode = true\n"
           "subsection Scene\n"
           "  subsection Box\n"
           "    set Lower corner = -2000, -500, -2000\n"
           "    set Upper corner = 2000, 500, 2000\n"
           "    set Number of cells = 8, 2, 8\n"
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
           "  set Fault region = (abs(x) <= 1600 && abs(z) <= 1600) ? 1 : 0\n"
           "  set Initial traction = 36e6; -120e6; 0\n"
           "  subsection Traction perturbation\n"
           "    set Traction = 0; 0; 100e6\n"
           "    set Time function = t\n"
           "  end\n"
           "  subsection Linear slip weakening\n"
           "    set Static friction coefficient = 0.6\n"
           "    set Dynamic friction coefficient = 0.6\n"
           "    set Slip-weakening distance = 1\n"
           "  end\n"
           "  subsection Anisotropic friction\n"
           "    set Strength ratio = " +
           std::to_string(ratio) +
           "\n"
           "    set First direction = 1, 0, 0\n"
           "  end\n"
           "  subsection Output\n"
           "    set Stations = centre: 0, 0, 0\n"
           "  end\n"
           "end\n"
           "subsection Time integration\n"
           "  set Scheme = explicit central difference\n"
           "  set End time = 2\n"
           "  set Time step = 0.005\n"
           "end\n"
           "subsection Output\n"
           "  set Output interval = -1\n"
           "end\n";
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  for (const double r : {1., 2.})
    {
      const std::string name = (r == 1) ? "isotropic" : "ellipse";
      if (root)
        std::ofstream(name + ".prm") << input(r);
      MPI_Barrier(MPI_COMM_WORLD);
      const int code = tests::run_in(name, {name + ".prm"}, {});
      if (!root)
        continue;
      // t, then slip, slip rate and shear stress (MPa) along strike and
      // along dip.
      const auto rows  = tests::read_statistics(name + "/centre.dat");
      double     onset = -1, onset_norm = 0, onset_magnitude = 0;
      double stuck_above = 0, off_ellipse = 0, off_normal = 0, power_error = 0;
      unsigned int sliding = 0;
      for (const auto &row : rows)
        {
          const double vh = row[2], vv = row[5], th = row[3], tv = row[6];
          const double magnitude = std::hypot(th, tv),
                       norm      = std::hypot(th, tv / r);
          const double rate      = std::hypot(vh, vv);
          if (rate < 1e-4)
            {
              // Stuck: the largest traction seen, against S.
              if (onset < 0)
                stuck_above = std::max(stuck_above, magnitude / strength);
              continue;
            }
          if (onset < 0)
            onset = row[0], onset_norm = norm, onset_magnitude = magnitude;
          if (rate < 1e-2)
            continue; // starting or stopping
          ++sliding;
          off_ellipse = std::max(off_ellipse, std::abs(norm / strength - 1));
          // The normal of the ellipse at tau: A^-2 tau.
          const double nh = th, nv = tv / (r * r);
          const double angle =
            std::abs(std::atan2(nh * vv - nv * vh, nh * vh + nv * vv)) * 180 /
            M_PI;
          off_normal = std::max(off_normal, angle);
          power_error =
            std::max(power_error,
                     std::abs((th * vh + tv * vv) /
                                (strength * std::hypot(vh, r * vv)) -
                              1));
        }
      std::printf("%s (r = %g): exit code %d; stuck while |tau| reached "
                  "%.2f S; sliding from t = %.3f s at |tau| = %.2f S, "
                  "|A^-1 tau| = %.2f S\n",
                  name.c_str(),
                  r,
                  code,
                  stuck_above,
                  onset,
                  onset_magnitude / strength,
                  onset_norm / strength);
      std::printf("  %s: %s steps sliding faster than 1 cm/s; on the "
                  "ellipse within 1 %%: %s; slip rate within 1 degree of "
                  "the ellipse's normal: %s; tau . V = S |A V| within 1 %%: "
                  "%s\n",
                  name.c_str(),
                  sliding > 20 ? "more than 20" : "20 or fewer",
                  off_ellipse < 0.01 ? "yes" : "NO",
                  off_normal < 1 ? "yes" : "NO",
                  power_error < 0.01 ? "yes" : "NO");
    }
}
