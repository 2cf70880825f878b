// Kelvin-Voigt damping in the cells that touch the fault (<Damping/Fault
// zone damping>), on one rank and on two:
// - Explicit, split nodes: TPV205-2D (prm/tpv205-2d) at 500 m, degree 1,
//   model 60 x 24 km, to t = 4 s, without and with eta = 0.3 dt. Checked:
//   the zone is the two rows of cells along the fault (240 of 5760); the
//   stable step shrinks by 1/sqrt(1 + 2 * 0.3); the oscillation of the
//   slip rate at 4.5 km after the front (its total variation beyond one
//   rise and one fall, over its peak; at this coarse resolution the
//   oscillation has a period of about 2.4 node spacings over the
//   shear-wave speed) falls by a quarter or more (measured: 2.72 to
//   1.45); the rupture time there moves by less than 0.05 s and the slip
//   at 4 s by less than 5 % (measured: 0.018 s, 2.8 %); the damping
//   dissipates energy and the energy balance
//   still closes (to 1e-2 of the work done on the fault). The damped run
//   once more with the stored stiffness and zone matrices
//   (<Discretization/Stiffness operator> = matrix) must agree with the
//   matrix-free one.
// - Implicit, penalty contact: tests/fault/load_sequence.prm with
//   eta = 1 dt, with the stored system matrix (AMG) and matrix-free (block
//   Jacobi): both must give the same slip (1e-6), which checks the zone's
//   part of the matrix-free product and its diagonal against the
//   assembled matrix; and the damping must change the slip.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  /// The slip rate's oscillation: its total variation beyond that of one
  /// rise to the peak and one fall to the last value, over the peak (0 for
  /// a history that rises and falls once; each further swing of amplitude
  /// A adds 2 A / peak).
  double
  oscillation(const std::vector<std::vector<double>> &rows)
  {
    double variation = 0, peak = 0;
    for (std::size_t k = 0; k < rows.size(); ++k)
      {
        peak = std::max(peak, std::abs(rows[k][2]));
        if (k > 0)
          variation +=
            std::abs(std::abs(rows[k][2]) - std::abs(rows[k - 1][2]));
      }
    if (rows.empty() || peak == 0)
      return -1;
    return (variation -
            (2 * peak - std::abs(rows.front()[2]) - std::abs(rows.back()[2]))) /
           peak;
  }

  /// The value in the column whose name (line "# n: name") starts with
  /// @p name, in the last row of the statistics file of @p dir.
  double
  last_statistic(const std::string &dir, const std::string &name)
  {
    const std::string  file = dir + "/statistics";
    std::istringstream in(tests::read_file(file));
    std::string        line;
    int                column = -1;
    while (std::getline(in, line))
      if (line.rfind("# ", 0) == 0 &&
          line.find(": " + name) != std::string::npos)
        column = std::stoi(line.substr(2)) - 1;
    const auto rows = tests::read_statistics(file);
    return (rows.empty() || column < 0) ? 0 : rows.back()[column];
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const std::string top = std::string(SOURCE_DIR) + "/../../";

  double step[3], rupture[3], slip[3], rough[3], dissipated[3], balance[3];
  double zone_cells = 0;
  for (unsigned int damped = 0; damped < 3; ++damped)
    {
      // (2: damped, with the stored stiffness matrix and zone matrix.)
      const std::string dir  = damped == 0 ? "explicit" :
                               damped == 1 ? "explicit-damped" :
                                             "explicit-damped-stored";
      const int         code = tests::run(
        {top + "prm/tpv205-2d/tpv205-2d.prm",
                 "--set",
                 "Test mode=true",
                 "--set",
                 "Discretization/Polynomial degree=1",
                 "--set",
                 "Output directory=" + dir,
                 "--set",
                 "Output/Output interval=-1",
                 "--set",
                 "Output/Receivers=",
                 "--set",
                 "Scene/Box/Lower corner=-30000, -12000",
                 "--set",
                 "Scene/Box/Upper corner=30000, 12000",
                 "--set",
                 "Scene/Box/Number of cells=120, 48",
                 "--set",
                 "Fault/Output/Stations=faultst045: 4500, 0",
                 "--set",
                 "Damping/Fault zone damping=" + std::string(damped ? "0.3" : "0"),
                 "--set",
                 "Discretization/Stiffness operator=" +
                   std::string(damped == 2 ? "matrix" : "matrix free"),
                 "--set",
                 "Time integration/End time=4"});
      if (!root)
        continue;
      const auto rows = tests::read_statistics(dir + "/faultst045.dat");
      step[damped] =
        tests::find_number(dir + "/log.txt", "Stable explicit time step:");
      if (damped)
        zone_cells =
          tests::find_number(dir + "/log.txt", "Fault zone damping:");
      rupture[damped]    = tests::rupture_time(rows);
      slip[damped]       = rows.empty() ? -1 : rows.back()[1];
      rough[damped]      = oscillation(rows);
      dissipated[damped] = last_statistic(dir, "Energy dissipated");
      // The balance error relative to the work done on the fault.
      balance[damped] = last_statistic(dir, "Energy balance error") /
                        last_statistic(dir, "Work done on the fault");
      std::printf("%s: exit code %d, rupture at 4.5 km %.3f s, final slip "
                  "%.3f m, slip-rate oscillation %.2f, energy balance error "
                  "below 1e-2 of the fault's work: %s\n",
                  dir.c_str(),
                  code,
                  rupture[damped],
                  slip[damped],
                  rough[damped],
                  std::abs(balance[damped]) < 1e-2 ? "yes" : "no");
    }
  if (root)
    {
      std::printf("zone: %.0f cells\n", zone_cells);
      std::printf("the damping dissipates energy: %s\n",
                  dissipated[1] > dissipated[0] ? "yes" : "no");
      std::printf("stable step ratio %.4f (1/sqrt(1.6) = %.4f)\n",
                  step[1] / step[0],
                  1 / std::sqrt(1.6));
      std::printf("stored zone matrix = matrix-free zone (1e-9): %s\n",
                  (std::abs(rupture[2] - rupture[1]) <= 1e-9 &&
                   std::abs(slip[2] - slip[1]) <= 1e-9 * slip[1]) ?
                    "yes" :
                    "no");
      std::printf("oscillation down by a quarter or more: %s\n",
                  (rough[1] > 0 && rough[1] < 0.75 * rough[0]) ? "yes" : "no");
      std::printf("rupture time within 0.05 s, slip within 5 %%: %s\n",
                  (std::abs(rupture[1] - rupture[0]) < 0.05 &&
                   std::abs(slip[1] - slip[0]) < 0.05 * slip[0]) ?
                    "yes" :
                    "no");
    }

  double implicit_slip[3];
  for (unsigned int k = 0; k < 3; ++k)
    {
      const std::string dir =
        std::string("implicit-") + (k == 0 ? "undamped" :
                                    k == 1 ? "damped-amg" :
                                             "damped-block-jacobi");
      const int code = tests::run(
        {top + "tests/fault/load_sequence.prm",
         "--set",
         "Output directory=" + dir,
         "--set",
         "Damping/Fault zone damping=" + std::string(k == 0 ? "0" : "1"),
         "--set",
         "Solver/Preconditioner=" +
           std::string(k == 2 ? "block Jacobi" : "AMG")});
      if (!root)
        continue;
      const auto rows  = tests::read_statistics(dir + "/centre.dat");
      implicit_slip[k] = rows.empty() ? -1 : rows.back()[1];
      std::printf("implicit %s: exit code %d, final slip at the centre "
                  "%.6f m\n",
                  dir.c_str(),
                  code,
                  implicit_slip[k]);
    }
  if (root)
    std::printf("matrix-free = stored (1e-6): %s; the damping changes the "
                "slip: %s\n",
                std::abs(implicit_slip[2] - implicit_slip[1]) <=
                    1e-6 * std::abs(implicit_slip[1]) ?
                  "yes" :
                  "no",
                std::abs(implicit_slip[1] - implicit_slip[0]) >
                    1e-3 * std::abs(implicit_slip[0]) ?
                  "yes" :
                  "no");
}
