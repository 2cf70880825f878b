// Order p + 1 in space for every polynomial degree p = 1..4: the static
// manufactured solution of inputs/mms_static.prm (2-D elasticity on the
// unit square, one quasi-static step, so no time error) on meshes of
// h = 1/4, 1/8, 1/16. The L2 error of the displacement must fall as
// h^(p+1); each line prints the order between two meshes, and the last
// line of each degree whether the finest pair reached p + 1 - 0.2.

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
      double previous = 0, order = 0;
      for (unsigned int level = 1; level <= 3; ++level)
        {
          const std::string directory =
            "output-" + std::to_string(p) + "-" + std::to_string(level);
          const int code =
            tests::run({std::string(SOURCE_DIR) + "/inputs/mms_static.prm",
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
          const double h = 0.5 / (1 << level);
          if (level == 1)
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
