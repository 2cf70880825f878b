// Order p + 1 in space for every polynomial degree p = 1..4 in 3-D: the
// static manufactured solution of inputs/mms_static_3d.prm (elasticity on
// the unit cube, u = (1, 2, 3) sin(pi x) sin(pi y) sin(pi z), one
// quasi-static step, so no time error, solved matrix-free with the
// geometric multigrid at each degree) on two meshes, h = 1/4 and 1/8 at
// degree 1, h = 1/2 and 1/4 at degrees 2 to 4 (h along x and y; the cells
// are half as long along z). Degree 4's finer mesh takes most of the test's
// time (about 90 s in a Debug build). The L2
// error of the displacement must fall as h^(p+1): each degree prints the
// order between its two meshes and whether it reached p + 1 - 0.2.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <string>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (unsigned int p = 1; p <= 4; ++p)
    {
      std::printf("Q%u:\n  %-8s %-12s %s\n", p, "h", "L2 error", "order");
      const unsigned int coarse   = (p == 1 ? 2 : 1);
      double             previous = 0, order = 0;
      for (unsigned int level = coarse; level <= coarse + 1; ++level)
        {
          const std::string directory =
            "output-" + std::to_string(p) + "-" + std::to_string(level);
          const int code =
            tests::run({std::string(SOURCE_DIR) + "/inputs/mms_static_3d.prm",
                        "--set",
                        "Discretization/Polynomial degree=" + std::to_string(p),
                        "--set",
                        "Discretization/Initial global refinement=" +
                          std::to_string(level),
                        "--set",
                        "Output directory=" + directory});
          const auto   rows = tests::read_statistics(directory + "/statistics");
          const double error = rows.empty() ? -1 : rows.back().back();
          if (code != 0)
            std::printf("  run failed with exit code %d\n", code);
          const double h = 1.0 / (1 << level);
          if (level == coarse)
            std::printf("  %-8.5f %-12.3e -\n", h, error);
          else
            {
              order = std::log2(previous / error);
              std::printf("  %-8.5f %-12.3e %.2f\n", h, error, order);
            }
          previous = error;
        }
      std::printf("  order %u reached (within 0.2): %s\n",
                  p + 1,
                  order > p + 1 - 0.2 ? "yes" : "no");
    }
}
