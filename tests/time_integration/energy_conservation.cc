// Undamped, unloaded free vibration: implicit average-acceleration Newmark
// (beta = 1/4, gamma = 1/2) conserves kinetic + strain energy to round-off
// in every step; gamma > 1/2 dissipates it; the explicit scheme below its
// stable step keeps it bounded (it conserves a nearby modified energy).
// The energy budget kinetic + strain + dissipated - work closes to
// round-off for the average-acceleration rule.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace
{
  struct Drift
  {
    double max_step_change = 0; // max |E_{n+1} - E_n| / E_0
    double max_change      = 0; // max |E_n - E_0| / E_0
    double final_change    = 0; // (E_N - E_0) / E_0
    double balance         = 0; // max |balance error| / E_0
  };

  Drift
  drift(const std::vector<std::string> &extra)
  {
    std::vector<std::string> args = {std::string(SOURCE_DIR) +
                                     "/inputs/free_vibration.prm"};
    args.insert(args.end(), extra.begin(), extra.end());
    if (tests::run(args) != 0)
      std::printf("run failed\n");
    const auto rows =
      tests::read_statistics("output-free-vibration/statistics");
    Drift        d;
    const double e0 = rows[0][4] + rows[0][5];
    for (unsigned int i = 1; i < rows.size(); ++i)
      {
        const double e    = rows[i][4] + rows[i][5];
        const double ep   = rows[i - 1][4] + rows[i - 1][5];
        d.max_step_change = std::max(d.max_step_change, std::abs(e - ep) / e0);
        d.max_change      = std::max(d.max_change, std::abs(e - e0) / e0);
        d.balance         = std::max(d.balance, std::abs(rows[i][8]) / e0);
      }
    d.final_change = (rows.back()[4] + rows.back()[5] - e0) / e0;
    std::printf("  %zu steps, initial energy %.6e J\n", rows.size() - 1, e0);
    return d;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  std::printf("Implicit Newmark, beta = 1/4, gamma = 1/2:\n");
  Drift d = drift({});
  std::printf("  max relative energy change per step below 1e-11: %s\n",
              d.max_step_change < 1e-11 ? "yes" : "no");
  std::printf("  max relative energy balance error below 1e-11: %s\n",
              d.balance < 1e-11 ? "yes" : "no");

  std::printf(
    "Implicit Newmark, beta = 0.3025, gamma = 0.6 (damping variant):\n");
  d = drift({"--set",
             "Time integration/Newmark beta=0.3025",
             "--set",
             "Time integration/Newmark gamma=0.6"});
  std::printf("  energy lost over the run, percent: %.0f\n",
              -100 * d.final_change);
  std::printf("  energy decreased: %s\n",
              d.final_change < -1e-3 ? "yes" : "no");

  std::printf("Explicit central difference at half the stable step:\n");
  d = drift({"--set",
             "Time integration/Scheme=explicit central difference",
             "--set",
             "Time integration/Time step=0",
             "--set",
             "Time integration/Courant fraction=0.5"});
  // Central difference conserves a modified energy; the energy measured at
  // whole steps oscillates by O((omega dt)^2) around it, here about 1.3%.
  std::printf("  max relative energy change below 2e-2: %s\n",
              d.max_change < 2e-2 ? "yes" : "no");
}
