// The quasi-dynamic radiation damping (<Fault/Radiation damping>, eta) on
// the block of inputs/stick_slip.prm, pushed over its fault at 0.1 m/s and
// back, in steps of 0.5 s: while it slips, the shear traction is the
// friction strength plus eta V, with V the slip rate of the step (tending
// to the push's 0.1 m/s, so 6 MPa + 0.462 MPa for eta = 4.62e6 Pa s/m, the
// SEAS benchmarks' value); every slip is that of a spring-slider with
// damping stepped by backward Euler; it sticks and slips at the same steps
// as without damping. eta = 0 is the run without the entry to the last
// digit. 'auto' (half the shear impedance across the fault from the
// material, isotropic or anisotropic) is the run with that number. Refused: eta
// > 0 with a dynamic scheme and with traction at split nodes, each with a
// message naming the entry.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string prm = std::string(SOURCE_DIR) + "/inputs/stick_slip.prm";
  // 0-based columns of statistics with a fault: time, slipping nodes,
  // maximum slip, mean normal and shear traction, Newton iterations.
  const unsigned int time = 1, slipping = 11, slip = 14, normal = 20,
                     shear = 21;
  const double eta         = 4.62e6;

  const auto run = [&](const std::string &directory, const double damping) {
    tests::run_in(directory,
                  {prm},
                  {"Fault/Radiation damping=" + std::to_string(damping),
                   "Time integration/Time step=0.5"});
    return tests::read_statistics(directory + "/statistics");
  };
  const auto plain  = run("plain", 0);
  const auto damped = run("damped", eta);

  std::printf(
    "  t (s)  state   slip (mm)  shear (MPa)  strength + eta V (MPa)\n");
  bool holds = plain.size() == damped.size() && !damped.empty();
  for (unsigned int i = 1; i < damped.size(); ++i)
    {
      const auto  &r     = damped[i];
      const bool   slips = r[slipping] > 0;
      const double rate =
        (r[slip] - damped[i - 1][slip]) / (r[time] - damped[i - 1][time]);
      const double strength = 0.6 * std::abs(r[normal]);
      const double expected = strength + eta * std::abs(rate);
      // The slip column is the whole jump, the penalty's compliance
      // included (1e-6 of a step's slip here): the damping's part within
      // 0.1 %.
      if (slips)
        holds =
          holds && std::abs(r[shear] - expected) <= 1e-3 * eta * std::abs(rate);
      else
        holds = holds && r[shear] < strength;
      holds = holds && i < plain.size() && slips == (plain[i][slipping] > 0);
      std::printf("  %5.1f  %-6s  %9.3f   %9.4f    %s\n",
                  r[time],
                  slips ? "slip" : "stick",
                  1e3 * r[slip],
                  r[shear] / 1e6,
                  slips ? std::to_string(expected / 1e6).substr(0, 6).c_str() :
                          "");
    }
  // The block above the fault is a spring of stiffness k (from the run
  // without damping, while it sticks: k = tau / (u_top - slip), u_top =
  // 0.1 t); a quasi-static step solves k (u_top - s_n) = tau_s + eta (s_n -
  // s_n-1) / dt, backward Euler for the slider: s_n = (k u_top - tau_s +
  // eta s_n-1 / dt) / (k + eta / dt).
  const double k = plain[6][shear] / (0.1 * plain[6][time] - plain[6][slip]);
  double       worst = 0;
  for (unsigned int i = 1; i < damped.size(); ++i)
    if (damped[i][slipping] > 0 && damped[i][time] <= 10)
      {
        const double dt    = damped[i][time] - damped[i - 1][time];
        const double tau_s = 0.6 * std::abs(damped[i][normal]);
        const double expected =
          (k * 0.1 * damped[i][time] - tau_s + eta * damped[i - 1][slip] / dt) /
          (k + eta / dt);
        worst =
          std::max(worst, std::abs(damped[i][slip] - expected) / expected);
      }
  std::printf("spring-slider stiffness k = %.4g Pa/m; the slip of every "
              "slipping step as backward Euler gives it for a damped "
              "slider, within 1e-4: %s\n",
              k,
              worst <= 1e-4 ? "yes" : "no");
  std::printf("final slip: %.1f mm (without damping %.1f mm: the damped "
              "fault holds a higher traction, so the block stretches more "
              "and slips less)\n",
              1e3 * damped.back()[slip],
              1e3 * plain.back()[slip]);
  std::printf("shear = strength + eta V while slipping, slipping at the "
              "same steps as without damping: %s\n",
              holds ? "yes" : "no");

  // eta = 0 is the run without the entry.
  tests::run_in("default", {prm}, {"Time integration/Time step=0.5"});
  std::printf("eta = 0 is the default to the last digit: %s\n",
              tests::read_file("default/statistics") ==
                  tests::read_file("plain/statistics") ?
                "yes" :
                "no");

  // 'auto': half the shear impedance across the fault (normal y) at each
  // node, sqrt(rho mu_n) / 2: mu = E / (2 (1 + nu)) = 1e10 Pa for the
  // block's isotropic rock, C66 (the shear across y along x) for an
  // orthotropic one whose other shear constants differ.
  const auto same_as_number = [&](const std::string              &name,
                                  const std::vector<std::string> &material,
                                  const double                    mu_n) {
    const double             value = 0.5 * std::sqrt(2670 * mu_n);
    std::vector<std::string> a = material, b = material;
    a.insert(a.end(),
             {"Fault/Radiation damping=auto",
              "Time integration/Time step=0.5"});
    char number[64];
    std::snprintf(number, sizeof(number), "%.17g", value);
    b.insert(b.end(),
             {std::string("Fault/Radiation damping=") + number,
              "Time integration/Time step=0.5"});
    tests::run_in(name + "-auto", {prm}, a);
    tests::run_in(name + "-number", {prm}, b);
    std::printf("'auto' in %s rock: the run with eta = sqrt(rho mu_n) / 2 = "
                "%.4g Pa s/m to 1e-12: %s\n",
                name.c_str(),
                value,
                tests::relative_difference(
                  tests::read_statistics(name + "-auto/statistics"),
                  tests::read_statistics(name + "-number/statistics")) < 1e-12 ?
                  "yes" :
                  "no");
  };
  same_as_number("isotropic", {}, 1e10);
  same_as_number("orthotropic",
                 {"Material/Symmetry=orthotropic",
                  "Material/Stiffness=C11 = 3e10, C22 = 2.5e10, C33 = 3e10, "
                  "C12 = 1e10, C13 = 1e10, C23 = 1e10, C44 = 0.5e10, C55 = "
                  "0.7e10, C66 = 2e10"},
                 2e10);

  // Refused combinations.
  for (const auto &sets :
       {std::vector<std::string>{"--set",
                                 "Fault/Radiation damping=1e6",
                                 "--set",
                                 "Time integration/Scheme=implicit Newmark"},
        std::vector<std::string>{"--set",
                                 "Fault/Radiation damping=auto",
                                 "--set",
                                 "Time integration/Scheme=implicit Newmark"},
        std::vector<std::string>{"--set",
                                 "Fault/Radiation damping=1e6",
                                 "--set",
                                 "Fault/Model=traction at split nodes",
                                 "--set",
                                 "Time integration/Scheme=explicit central "
                                 "difference"}})
    {
      std::vector<std::string> arguments = {prm};
      arguments.insert(arguments.end(), sets.begin(), sets.end());
      std::string errors;
      const int   code = tests::run_capture(arguments, errors);
      const auto  at   = errors.find("<Fault/Radiation damping>");
      std::printf("refused (exit code %d): %s\n",
                  code,
                  at == std::string::npos ?
                    "no message naming the entry" :
                    errors.substr(at, errors.find('\n', at) - at).c_str());
    }
}
