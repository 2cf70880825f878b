// Steady rate-and-state creep with penalty contact in a quasi-static run
// (inputs/rate_and_state_creep.prm): a block whose top is pushed at
// V_p = 1e-5 m/s over a fault with the regularised aging law of TPV101.
// The shear traction builds up until the fault slides at V_p and then
// holds the steady-state strength sigma mu_ss(V_p). Printed: the slip rate
// and the mean shear traction every 20 000 s, and the last traction against
// the closed form, and the state variable log10(theta) on the fault
// surface against log10(L / V_p).

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        prm =
    std::string(SOURCE_DIR) + "/inputs/rate_and_state_creep.prm";
  const int code =
    tests::run({prm, "--set", "Fault/Output/Output interval=200000"});
  std::printf("exit code: %d\n", code);

  const auto rows = tests::read_statistics("results/statistics");
  std::printf("t (s)      Newton  max slip rate (m/s)  mean shear traction "
              "(MPa)\n");
  for (const auto &row : rows)
    if (std::fmod(row[1], 20000.) == 0)
      std::printf("%-10.0f %-7.0f %-20.4e %.6f\n",
                  row[1],
                  row[10],
                  row[15],
                  row[21] / 1e6);

  const double a = 0.008, b = 0.012, f0 = 0.6, V0 = 1e-6, Vp = 1e-5;
  const double mu_ss =
    a * std::asinh(Vp / (2 * V0) * std::exp((f0 + b * std::log(V0 / Vp)) / a));
  const double tau = rows.back()[21];
  std::printf("steady state: shear traction %.6f MPa, closed form 10 MPa x "
              "mu_ss = %.6f MPa, relative difference below 1e-6: %s\n",
              std::abs(tau) / 1e6,
              10 * mu_ss,
              std::abs(std::abs(tau) / 1e7 - mu_ss) < 1e-6 * mu_ss ? "yes" :
                                                                     "no");
  std::printf("slip rate at the end equals V_p to 1e-6: %s\n",
              std::abs(rows.back()[15] - Vp) < 1e-6 * Vp ? "yes" : "no");

  // The state variable on the fault surface: theta = L / V_p at steady
  // sliding (the aging law), log10(0.02 / 1e-5) = 3.30103.
  {
    const auto values =
      tests::vtu_field(tests::read_file("results/fault/fault_00040.vtu"),
                       "log10_theta");
    if (values.empty())
      std::printf("log10_theta: not in the fault output\n");
    else
      {
        const double low  = *std::min_element(values.begin(), values.end());
        const double high = *std::max_element(values.begin(), values.end());
        const auto   n    = static_cast<unsigned int>(values.size());
        std::printf("log10_theta on the fault at the end: %u nodes, from "
                    "%.6f to %.6f (L/V_p: %.6f)\n",
                    n,
                    low,
                    high,
                    std::log10(0.02 / Vp));
      }
  }
}
