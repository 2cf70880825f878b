// The convergence table of a time-dependent manufactured solution whose
// time integrators are exact (u = U(x) (1 + t^2)), shared by
// anisotropic_mms.cc and inhomogeneous_mms.cc.

#ifndef rupture_tests_elasticity_mms_ladder_h
#define rupture_tests_elasticity_mms_ladder_h

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace tests
{
  /**
   * Run @p prm with @p settings under <Time integration/Scheme> @p scheme
   * (implicit: step 0.1; explicit: the stable step) at polynomial degree
   * @p degree on meshes refined 0 to 3 times (degree 1) or 0 to 2 times
   * (degree 2), or @p levels - 1 times where given, and print the L2
   * error at the end (the statistics' last column) against the cell size
   * 0.25 / 2^level with the order between consecutive meshes.
   */
  inline void
  print_mms_ladder(const std::string              &prm,
                   const std::string              &scheme,
                   const std::vector<std::string> &settings,
                   const unsigned int              degree,
                   const unsigned int              levels = 0)
  {
    std::printf("  %-8s %-12s %s\n", "h", "L2 error", "order");
    double             previous = 0;
    const unsigned int n        = levels > 0 ? levels : (degree == 1 ? 4u : 3u);
    for (unsigned int level = 0; level < n; ++level)
      {
        const std::string        out = "output-" + std::to_string(level);
        std::vector<std::string> all = settings;
        all.insert(all.end(),
                   {"Time integration/Scheme=" + scheme,
                    "Time integration/Time step=" +
                      std::string(scheme[0] == 'e' ? "0" : "0.1"),
                    "Discretization/Polynomial degree=" +
                      std::to_string(degree),
                    "Discretization/Initial global refinement=" +
                      std::to_string(level)});
        tests::run_in(out, {prm}, all);
        const auto   rows  = tests::read_statistics(out + "/statistics");
        const double error = rows.empty() ? -1 : rows.back().back();
        const double h     = 0.25 / (1 << level);
        if (level == 0)
          std::printf("  %-8.5f %-12.3e -\n", h, error);
        else
          std::printf("  %-8.5f %-12.3e %.2f\n",
                      h,
                      error,
                      std::log2(previous / error));
        previous = error;
      }
  }
} // namespace tests

#endif
