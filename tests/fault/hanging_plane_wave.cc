// A fault with hanging nodes in both coupling methods, against an exact
// solution, on one process and on two: the 1-D plane-wave slip-weakening
// interface of plane_wave.cc (doc/verification.md, section 5) in a 3-D
// column whose middle cells next to the fault are refined once on both
// sides (inputs/hanging_plane_wave.prm). The rollers make the exact
// solution that of the 1-D problem, the same at every node of the fault,
// so each node's slip must follow the analytic history, whether it is a
// node of the coarse part, a fine node inside the refined part, a hanging
// node or a node it hangs from.
// - Explicit, traction at split nodes (h = 0.025, the stable step): the
//   hanging pairs pass their areas to the pairs they follow and take
//   their interpolated tractions. Without that passing of areas the slip
//   at t = 0.5 is about 10 % low everywhere.
// - Implicit Newmark, penalty contact (dt = 0.01, to t = 0.5): the hanging
//   pairs keep their contact, whose force and tangent reach the nodes they
//   follow through the constraints.
// Tolerance: 1 % of the analytic slip at every station, and 0.5 % between
// the stations.

#include <deal.II/base/mpi.h>

#include "../tests.h"
#include "plane_wave_solution.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace
{
  void
  check(const std::string              &title,
        const std::vector<std::string> &settings,
        const std::vector<double>      &times)
  {
    std::vector<std::string> arguments = {std::string(SOURCE_DIR) +
                                          "/inputs/hanging_plane_wave.prm"};
    for (const auto &s : settings)
      {
        arguments.push_back("--set");
        arguments.push_back(s);
      }
    const int code = tests::run(arguments);
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    const std::string dir = "output-hanging-plane-wave/";
    std::printf("%s: exit code %d, %.0f fault pairs\n",
                title.c_str(),
                code,
                tests::find_number(dir + "log.txt", "Fault: "));
    std::printf("  t     analytic  coarse   fine     hanging  master   "
                "within 1%%  spread below 0.5%%\n");
    for (const double t : times)
      {
        const double a   = tests::plane_wave_slip(t);
        double       low = 1e300, high = -1e300;
        bool         within = true;
        std::printf("  %.1f   %.4f  ", t, a);
        for (const char *station : {"coarse", "fine", "hanging", "master"})
          {
            const double s = tests::value_at(
              tests::read_statistics(dir + station + ".dat"), 0, 1, t);
            std::printf("  %.4f", s);
            low    = std::min(low, s);
            high   = std::max(high, s);
            within = within && std::abs(s - a) < 0.01 * a;
          }
        std::printf("   %-9s  %s\n",
                    within ? "yes" : "no",
                    high - low < 0.005 * a ? "yes" : "no");
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check("explicit, traction at split nodes", {}, {0.5, 1.0, 1.5});
  check("implicit Newmark, penalty contact",
        {"Fault/Model=penalty contact",
         "Time integration/Scheme=implicit Newmark",
         "Time integration/Time step=0.01",
         "Time integration/End time=0.5"},
        {0.5});
}
