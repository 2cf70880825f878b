// Convergence of the dynamic elasticity solver against manufactured
// solutions: second order in space (Q1, L2 norm, with dt refined alongside
// h) for the implicit and the explicit scheme, and second order in time for
// implicit average-acceleration Newmark (with a solution the Q2 space
// represents exactly, so that only the time error remains).

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>

namespace
{
  double
  final_error(const std::string &output)
  {
    const auto rows = tests::read_statistics(output + "/statistics");
    return rows.empty() ? -1 : rows.back().back();
  }

  void
  study(const std::string              &title,
        const std::string              &prm,
        const std::vector<std::string> &extra,
        const unsigned int              n_levels,
        const bool                      refine_space,
        const double                    dt0)
  {
    std::printf("%s\n", title.c_str());
    std::printf("  %-8s %-10s %-12s %s\n", "h", "dt", "L2 error", "order");
    double previous = 0;
    for (unsigned int level = 0; level < n_levels; ++level)
      {
        const double             h  = refine_space ? 0.25 / (1 << level) : 0.5;
        const double             dt = dt0 / (1 << level);
        std::vector<std::string> args = {std::string(SOURCE_DIR) + "/inputs/" +
                                         prm};
        args.insert(args.end(), extra.begin(), extra.end());
        args.push_back("--set");
        args.push_back("Discretization/Initial global refinement=" +
                       std::to_string(refine_space ? level : 0));
        args.push_back("--set");
        args.push_back("Time integration/Time step=" + std::to_string(dt));
        args.push_back("--set");
        args.push_back("Output directory=output-" + std::to_string(level));
        const int    code  = tests::run(args);
        const double error = final_error("output-" + std::to_string(level));
        if (code != 0)
          std::printf("  run failed with exit code %d\n", code);
        if (level == 0)
          std::printf("  %-8.5f %-10.6f %-12.3e -\n", h, dt, error);
        else
          std::printf("  %-8.5f %-10.6f %-12.3e %.2f\n",
                      h,
                      dt,
                      error,
                      std::log2(previous / error));
        previous = error;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  study(
    "Implicit Newmark (beta = 1/4, gamma = 1/2), Q1, h and dt halved together:",
    "mms_space.prm",
    {},
    4,
    true,
    0.1);
  study(
    "Explicit central difference, Q1, lumped mass, h and dt halved together:",
    "mms_space.prm",
    {"--set", "Time integration/Scheme=explicit central difference"},
    4,
    true,
    0.02);
  study("Implicit Newmark, Q2 (exact in space), dt halved:",
        "mms_time.prm",
        {},
        4,
        false,
        0.1);
}
