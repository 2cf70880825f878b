// Cochard and Madariaga's rate weakening on the plane-wave column of
// plane_wave.cc (rho = c_s = 1, absorbing ends): strength
// tau_r + sigma_0 V0 / (V0 + V) with tau_r = 5, sigma_0 = 1, V0 = 4, under
// tau_0 = 6.5 (above the strength at rest, 6). Each side radiates, so on
// the fault tau_0 - (rho c_s / 2) V = tau_r + sigma_0 V0 / (V0 + V); the
// law has no state, so from t = 0 on the fault slides at the root of
//   V^2 + V - 4 = 0,  V = (sqrt(17) - 1) / 2 = 1.5616,
// with the shear traction tau_0 - V / 2 = 5.7192 and the slip V t (the
// law's steady state; unique, since sigma_0 / V0 = 0.25 is below the
// radiation impedance 1/2). The law has no direct effect to damp the
// grid's own oscillations, which the sudden start excites: the slip rate
// of a step rings about V (by +-20 % for the implicit method, more for the
// explicit one), so the slip at t = 1 (within 1 %), the mean slip rate
// over [0.5, 1] (within 2 %) and the mean shear traction over [0.5, 1]
// (within 0.5 %) are compared. Measured: implicit (h = 0.05, dt = 0.005)
// -0.5 %, +0.6 %, 0.00 %; explicit with split nodes (h = 0.0125) -0.7 %,
// +1.4 %, -0.2 % (at h = 0.05: -3.4 %, -3.5 %, +0.3 %). Then the strength
// falls faster than the nodes' impedance (sigma_0 = 6, V0 = 1e-3,
// tau_r = 0: 6000 Pa s/m, against about 1 for the split nodes and
// penalty * dt = 500 for penalty contact): the run stops with a message
// that names the law's parameters.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string prm = std::string(SOURCE_DIR) + "/inputs/plane_wave.prm";
  // 0-based columns of statistics with a fault: 14 max slip, 21 mean shear
  // traction.
  const unsigned int slip = 14, shear = 21;
  const double       V = (std::sqrt(17.) - 1) / 2, tau = 6.5 - V / 2;
  std::printf("reference: slip rate %.4f, shear traction %.4f\n", V, tau);

  const std::vector<std::string> law = {
    "--set",
    "Fault/Friction law=cochard madariaga",
    "--set",
    "Fault/Cochard Madariaga/Maximum traction drop=1",
    "--set",
    "Fault/Cochard Madariaga/Reference slip rate=4",
    "--set",
    "Fault/Cochard Madariaga/Residual strength=5",
    "--set",
    "Fault/Initial traction=6.5; -10",
    "--set",
    "Time integration/End time=1"};
  const std::vector<std::vector<std::string>> methods = {
    {"--set", "Time integration/Time step=0.005"},
    {"--set",
     "Fault/Model=traction at split nodes",
     "--set",
     "Time integration/Scheme=explicit central difference",
     "--set",
     "Time integration/Time step=0",
     "--set",
     "Scene/Box/Number of cells=1, 640",
     "--set",
     "Scene/Box/Upper corner=0.0125, 4"}};
  const char *names[] = {"implicit Newmark (dt = 0.005), penalty contact",
                         "explicit, traction at split nodes"};
  for (unsigned int m = 0; m < 2; ++m)
    {
      std::vector<std::string> args = {prm};
      args.insert(args.end(), law.begin(), law.end());
      args.insert(args.end(), methods[m].begin(), methods[m].end());
      std::printf("%s:\n", names[m]);
      std::string errors;
      if (tests::run_capture(args, errors) != 0)
        {
          std::printf("  run failed: %s\n", errors.c_str());
          continue;
        }
      const auto rows = tests::read_statistics("output-plane-wave/statistics");
      // Means over [0.5, 1].
      const std::vector<double> *start    = nullptr;
      double                     traction = 0;
      unsigned int               n        = 0;
      for (const auto &r : rows)
        if (r[1] >= 0.5 - 1e-9)
          {
            if (!start)
              start = &r;
            traction += std::abs(r[shear]);
            ++n;
          }
      const auto &last  = rows.back();
      const auto  close = [](const double x, const double y, const double tol) {
        return std::abs(x - y) <= tol * std::abs(y) ? "yes" : "NO";
      };
      const double rate =
        (last[slip] - (*start)[slip]) / (last[1] - (*start)[1]);
      std::printf("  slip at t = %.2f %s, mean slip rate %s, mean shear "
                  "traction %s\n",
                  last[1],
                  close(last[slip], V * last[1], 0.01),
                  close(rate, V, 0.02),
                  close(traction / n, tau, 0.005));
    }

  const std::vector<std::string> steep = {
    "--set",
    "Fault/Cochard Madariaga/Maximum traction drop=6",
    "--set",
    "Fault/Cochard Madariaga/Reference slip rate=1e-3",
    "--set",
    "Fault/Cochard Madariaga/Residual strength=0"};
  for (unsigned int m = 0; m < 2; ++m)
    {
      std::vector<std::string> args = {prm};
      args.insert(args.end(), law.begin(), law.end());
      args.insert(args.end(), steep.begin(), steep.end());
      args.insert(args.end(), methods[m].begin(), methods[m].end());
      std::string errors;
      const int   code = tests::run_capture(args, errors);
      std::printf("%s, sigma_0 / V0 = 6000: exit code %d, the message names "
                  "both parameters: %s\n",
                  names[m],
                  code,
                  (errors.find("Maximum traction drop") != std::string::npos &&
                   errors.find("Reference slip rate") != std::string::npos) ?
                    "yes" :
                    "NO");
    }
}
