// Stick-slip-stick (inputs/stick_slip.prm): a block pushed over a fault and
// then back. Checks at every step that the fault sticks while the shear
// traction is below mu |sigma_n| and slips at exactly that traction, that
// the transitions happen when simple shear predicts them, and that the
// same block with its fault welded by mistake (Fault region = 0) does not
// slip at all: a split that does not really split fails here.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string prm = std::string(SOURCE_DIR) + "/inputs/stick_slip.prm";

  // 0-based columns of statistics with a fault.
  const unsigned int slipping = 11, slip = 14, normal = 20, shear = 21;

  if (tests::run({prm}) != 0)
    std::printf("run failed\n");
  const auto rows = tests::read_statistics("output-stick-slip/statistics");
  std::printf("  t (s)  state   slip (mm)   shear (MPa)  mu|sigma_n| (MPa)\n");
  bool coulomb = true;
  for (unsigned int i = 1; i < rows.size(); ++i)
    {
      const auto  &r            = rows[i];
      const double strength     = 0.6 * std::abs(r[normal]);
      const bool   slipping_now = r[slipping] > 0;
      if (slipping_now)
        coulomb = coulomb && std::abs(r[shear] - strength) <= 1e-6 * strength;
      else
        coulomb = coulomb && r[shear] < strength;
      std::printf("  %5.1f  %-6s  %9.3f   %9.4f    %9.4f\n",
                  r[1],
                  slipping_now ? "slip" : "stick",
                  1e3 * r[slip],
                  r[shear] / 1e6,
                  strength / 1e6);
    }
  std::printf("Coulomb's law holds at every step: %s\n",
              coulomb ? "yes" : "no");
  std::printf("slip at the end within 1 mm of 400 mm: %s\n",
              std::abs(rows.back()[slip] - 0.4) < 1e-3 ? "yes" : "no");

  // A station between fault nodes, in the SCEC format.
  if (tests::run(
        {prm, "--set", "Fault/Output/Stations=faultst0125: 125, 500"}) != 0)
    std::printf("run with a station failed\n");
  const auto station =
    tests::read_statistics("output-stick-slip/faultst0125.dat");
  std::printf("station file: %zu rows of %zu columns, final h-slip %.4f m, "
              "h-shear-stress %.4f MPa\n",
              station.size(),
              station.empty() ? 0 : station.back().size(),
              station.empty() ? 0. : station.back()[1],
              station.empty() ? 0. : station.back()[3]);
  std::string errors;
  std::printf("station off the fault: exit code %d\n",
              tests::run_capture(
                {prm, "--set", "Fault/Output/Stations=offfault: 100, 400"},
                errors));
  std::printf("  %s", errors.substr(errors.find("Error")).c_str());

  if (tests::run({prm, "--set", "Fault/Fault region=0"}) != 0)
    std::printf("welded run failed\n");
  const auto welded   = tests::read_statistics("output-stick-slip/statistics");
  double     max_slip = 0;
  for (const auto &r : welded)
    max_slip = std::max(max_slip, r[slip]);
  std::printf("welded fault (Fault region = 0) slips: %s\n",
              max_slip > 1e-9 ? "yes" : "no");
}
