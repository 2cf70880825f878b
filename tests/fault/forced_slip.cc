// The forced-slip trigger on the 1-D plane-wave column of plane_wave.cc:
// slip imposed at the rate V = 0.5 on the whole fault (no friction). The
// fault then radiates a shear wave into either side, and the shear
// traction drops by the radiation damping rho c_s V / 2 = 0.25 from its
// initial 6.1 to 5.85 (rho = c_s = 1), while the slip is 0.5 t.
//
// Implicit Newmark with penalty contact needs numerical damping here (gamma
// = 0.6, beta = 0.3025): the sudden start of the imposed slip rings the
// stiff penalty springs, which the trapezoidal rule never damps. The
// explicit split-node method imposes the slip exactly. Tolerance: 0.5 % on
// the slip at t = 1 and 2 and on the mean shear traction over t in [1, 2].

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string prm = std::string(SOURCE_DIR) + "/inputs/plane_wave.prm";
  // 0-based columns of statistics with a fault: 14 max slip, 21 mean shear
  // traction.
  const unsigned int slip = 14, shear = 21;

  const std::vector<std::string>              forced  = {"--set",
                                                         "Fault/Forced slip/Region=1",
                                                         "--set",
                                                         "Fault/Forced slip/Slip=0.5*t",
                                                         "--set",
                                                         "Fault/Forced slip/Direction=1, 0",
                                                         "--set",
                                                         "Time integration/End time=2"};
  const std::vector<std::vector<std::string>> methods = {
    {"--set",
     "Time integration/Newmark gamma=0.6",
     "--set",
     "Time integration/Newmark beta=0.3025"},
    {"--set",
     "Fault/Model=traction at split nodes",
     "--set",
     "Time integration/Scheme=explicit central difference",
     "--set",
     "Time integration/Time step=0"}};
  const char *names[] = {"implicit Newmark, penalty contact",
                         "explicit, traction at split nodes"};

  for (unsigned int m = 0; m < 2; ++m)
    {
      std::vector<std::string> args = {prm};
      args.insert(args.end(), forced.begin(), forced.end());
      args.insert(args.end(), methods[m].begin(), methods[m].end());
      std::printf("%s:\n", names[m]);
      if (tests::run(args) != 0)
        std::printf("  run failed\n");
      const auto rows = tests::read_statistics("output-plane-wave/statistics");
      double     traction = 0, slip_1 = 0;
      unsigned   n = 0;
      for (const auto &r : rows)
        {
          if (r[1] >= 1 - 1e-9)
            {
              traction += r[shear];
              ++n;
            }
          if (slip_1 == 0 && r[1] >= 1 - 1e-9)
            slip_1 = r[slip] * 1 / r[1];
        }
      traction /= n;
      const double slip_2 = rows.back()[slip];
      std::printf("  slip at t = 1: within 0.5%% of 0.5: %s\n",
                  std::abs(slip_1 - 0.5) < 0.0025 ? "yes" : "no");
      std::printf("  slip at t = 2: within 0.5%% of 1.0: %s\n",
                  std::abs(slip_2 - 1.0) < 0.005 ? "yes" : "no");
      std::printf("  mean shear traction over [1, 2]: %.3f (analytic 5.85), "
                  "within 0.5%%: %s\n",
                  traction,
                  std::abs(traction - 5.85) < 0.005 * 5.85 ? "yes" : "no");
    }
}
