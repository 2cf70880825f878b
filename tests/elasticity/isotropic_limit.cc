// The isotropic limit of anisotropic elasticity in whole runs: five test
// inputs of other rooms, each run as it is (isotropic material: 2670
// kg/m^3, 6000 and 3464 m/s) and again with the same constants given as a
// general 21-constant tensor (<Material/Symmetry> = general), which takes
// the anisotropic code paths everywhere (matrix-free kernel, assembled
// element matrices, stable step, absorbing boundaries, fault shear
// stiffness, adaptive band speed). The statistics must agree: every column
// within 1e-9 of its largest value (round-off, which the friction carries
// along, is all that differs; 2e-11 at most on the developers' machine). The
// cases: explicit split nodes in 3-D, explicit split nodes in 2-D with adaptive
// refinement, implicit Newmark with penalty contact in 3-D, and the
// quasi-static then dynamic load sequence in 2-D with an assembled matrix and
// with matrix-free multigrid.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             rho = 2670, vp = 6000, vs = 3464;
  const double       mu = rho * vs * vs, lambda = rho * vp * vp - 2 * mu;
  std::ostringstream general;
  general << "Material/Stiffness=" << std::setprecision(17);
  for (unsigned int I = 0; I < 6; ++I)
    for (unsigned int J = I; J < 6; ++J)
      general << (I + J > 0 ? ", " : "") << "C" << I + 1 << J + 1 << " = "
              << ((I < 3 && J < 3) ? lambda + (I == J ? 2 * mu : 0.) :
                                     (I == J ? mu : 0.));

  const std::string source = SOURCE_DIR;
  for (const std::string input : {"fault/split_node_3d.prm",
                                  "simulator/inputs/adaptive_front.prm",
                                  "fault/penalty_rupture_3d.prm",
                                  "fault/load_sequence.prm",
                                  "fault/load_sequence_multigrid.prm"})
    {
      const std::string prm = source + "/../" + input;
      const int         a   = tests::run_in("isotropic", {prm}, {});
      const int         b   = tests::run_in("general",
                                  {prm},
                                  {"Material/Symmetry=general", general.str()});
      const auto        x   = tests::read_statistics("isotropic/statistics");
      const auto        y   = tests::read_statistics("general/statistics");
      bool   same  = (a == 0 && b == 0 && !x.empty() && x.size() == y.size());
      double worst = 0;
      // 1-based columns 4 and 11 count solver iterations (round-off may
      // change them by one), 10 and 24 are wall times; the energy balance
      // error (9) is compared with the energies' scale (5 and 6).
      double energy = 0;
      for (const auto &row : x)
        energy = std::max(energy, std::abs(row[4]) + std::abs(row[5]));
      for (unsigned int j = 0; same && j < x[0].size(); ++j)
        {
          if (j + 1 == 4 || j + 1 == 11 || j + 1 == 10 || j + 1 == 24)
            continue;
          double scale = (j + 1 == 9 ? energy : 0.), difference = 0;
          for (unsigned int i = 0; i < x.size(); ++i)
            {
              scale      = std::max(scale, std::abs(x[i][j]));
              difference = std::max(difference, std::abs(x[i][j] - y[i].at(j)));
            }
          if (scale > 0)
            worst = std::max(worst, difference / scale);
        }
      std::printf("%s: exit codes %d %d, %zu rows, every column within 1e-9 "
                  "of its largest value: %s\n",
                  input.c_str(),
                  a,
                  b,
                  x.size(),
                  same && worst <= 1e-9 ? "yes" : "no");
    }
}
