// The order-of-convergence table of a static manufactured solution, shared
// by mms_degrees.cc (2-D) and mms_degrees_3d.cc.

#ifndef rupture_tests_simulator_mms_orders_h
#define rupture_tests_simulator_mms_orders_h

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace tests
{
  /**
   * Run @p prm at polynomial degree @p p with <Initial global refinement>
   * = @p first .. @p last, print the L2 error of the displacement (the
   * statistics' last column) and the order between consecutive meshes
   * (cell size @p coarse_h / 2^level), and whether the last order reached
   * p + 1 - 0.2.
   */
  inline void
  print_mms_orders(const std::string &prm,
                   const unsigned int p,
                   const unsigned int first,
                   const unsigned int last,
                   const double       coarse_h)
  {
    std::printf("Q%u:\n  %-8s %-12s %s\n", p, "h", "L2 error", "order");
    double previous = 0, order = 0;
    for (unsigned int level = first; level <= last; ++level)
      {
        const std::string directory =
          "output-" + std::to_string(p) + "-" + std::to_string(level);
        const int code = tests::run(
          {prm,
           "--set",
           "Discretization/Polynomial degree=" + std::to_string(p),
           "--set",
           "Discretization/Initial global refinement=" + std::to_string(level),
           "--set",
           "Output directory=" + directory});
        const auto   rows  = tests::read_statistics(directory + "/statistics");
        const double error = rows.empty() ? -1 : rows.back().back();
        if (code != 0)
          std::printf("  run failed with exit code %d\n", code);
        const double h = coarse_h / (1 << level);
        if (level == first)
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
} // namespace tests

#endif
