// The flash-heating rate-and-state law of SCEC TPV103/104, at TPV103's
// parameters (a = 0.01, b = 0.014, L = 0.4 m, f0 = 0.6, V0 = 1e-6 m/s,
// f_w = 0.2, V_w = 0.1 m/s):
// - steady state: mu after many steps at a constant slip rate equals
//   f_ss(V), from 1e-12 m/s to 10 m/s (the weakening above V_w);
// - a velocity step: psi(t) against its closed form for steps with
//   V dt / L from 1e-3 to 1000;
// - the consistent tangent against central differences, at V = 0
//   (one-sided), steady creep, a velocity step and fast slip;
// - the initial state from TPV103's initial traction (40 MPa / 120 MPa at
//   V_ini = 1e-16 m/s);
// - no NaN or Inf at V = 0 for 1e12 s or at 1000 m/s.

#include <rupture/friction/flash_heating.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <cstdio>

using namespace dealii;
using rupture::Friction::FlashHeating;
using rupture::Friction::State;

namespace
{
  std::unique_ptr<rupture::Friction::Interface>
  make()
  {
    ParameterHandler prm;
    prm.enter_subsection("Fault");
    rupture::Friction::declare_parameters(prm);
    prm.set("Friction law", "flash heating");
    auto law = rupture::Friction::create(prm);
    prm.leave_subsection();
    return law;
  }

  const Point<3>                origin(0, 0, -7500);
  const FlashHeating::Constants tpv103 = {
    {0.01, 0.014, 0.4, 0.6, 1e-6, 0.2, 0.1}};

  // f_ss(V) written out.
  double
  f_ss(const double V)
  {
    const double f_lv = 0.6 - 0.004 * std::log(V / 1e-6);
    return 0.2 + (f_lv - 0.2) / std::pow(1 + std::pow(V / 0.1, 8), 0.125);
  }

  double
  relative_error(const double value, const double reference)
  {
    return std::abs(value - reference) / std::max(std::abs(reference), 1e-300);
  }

  State
  start(const rupture::Friction::Interface &law, const double psi)
  {
    State state;
    law.initialize_state(origin, 0.6, state);
    state.variables = {psi};
    return state;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                       law = make();

  std::printf("1. Steady state: mu after 200 steps of dt = 10 L/V from psi "
              "= 0.5\n");
  for (const double V : {1e-12, 1e-6, 1e-3, 0.1, 1., 10.})
    {
      State        state = start(*law, 0.5);
      const double dt    = 10 * 0.4 / V;
      for (unsigned int i = 0; i < 200; ++i)
        {
          State next;
          law->update_state(origin, state, V * dt, dt, 0., next);
          state = next;
        }
      double       d  = 0;
      const double mu = law->coefficient(origin, state, V * dt, dt, d);
      std::printf("   V = %-6.0e mu = %.8f, f_ss = %.8f: %s\n",
                  V,
                  mu,
                  f_ss(V),
                  relative_error(mu, f_ss(V)) < 1e-9 ? "agree" : "DIFFER");
    }

  std::printf("\n2. Velocity step 1e-6 -> 1 m/s from steady state, to "
              "t = 4 s\n");
  {
    double       unused = 0;
    const double psi1   = FlashHeating::steady_state(tpv103, 1e-6, unused);
    const double psi2   = FlashHeating::steady_state(tpv103, 1., unused);
    for (const double x : {1e-3, 1., 1000.})
      {
        const double V = 1., dt = x * 0.4 / V;
        State        state = start(*law, psi1);
        double       error = 0;
        const double end   = std::max(4., dt);
        for (double t = dt; t <= end * (1 + 1e-12); t += dt)
          {
            State next;
            law->update_state(origin, state, V * dt, dt, 0., next);
            state            = next;
            const double psi = psi2 + (psi1 - psi2) * std::exp(-V * t / 0.4);
            error = std::max(error, relative_error(state.variables[0], psi));
          }
        std::printf("   V dt/L = %-6g psi: %s\n",
                    x,
                    error < 1e-12 ? "exact" : "INEXACT");
      }
  }

  std::printf("\n3. Consistent tangent against central differences (dt = "
              "0.01 s)\n");
  {
    double       unused = 0;
    const double creep  = FlashHeating::steady_state(tpv103, 1e-9, unused);
    struct Case
    {
      const char *name;
      double      V;
      double      psi;
    };
    for (const Case &c : {Case{"stick V = 0", 0., creep},
                          Case{"steady creep", 1e-9, creep},
                          Case{"vel. step", 1e-3, creep},
                          Case{"fast", 5., creep}})
      {
        const double dt    = 0.01;
        const State  state = start(*law, c.psi);
        const double l     = c.V * dt;
        double       d = 0, u = 0;
        law->coefficient(origin, state, l, dt, d);
        const double h  = (l == 0) ? 1e-45 : 1e-6 * l;
        const double fd = (l == 0) ?
                            (law->coefficient(origin, state, h, dt, u) -
                             law->coefficient(origin, state, 0, dt, u)) /
                              h :
                            (law->coefficient(origin, state, l + h, dt, u) -
                             law->coefficient(origin, state, l - h, dt, u)) /
                              (2 * h);
        std::printf("   %-13s %s\n",
                    c.name,
                    relative_error(d, fd) < 1e-5 ? "agrees" : "DIFFERS");
      }
  }

  std::printf("\n4. Initial state for 40 MPa / 120 MPa at V_ini = 1e-16 "
              "m/s\n");
  {
    State state;
    law->initialize_state(origin, 40. / 120., state);
    double       dV = 0, dpsi = 0;
    const double mu = dynamic_cast<const FlashHeating &>(*law).friction(
      tpv103, state.variables, 1e-16, state.variables[0], dV, dpsi);
    std::printf("   psi = %.8f, mu(V_ini, psi) = %.10f\n",
                state.variables[0],
                mu);
  }

  std::printf("\n5. Extremes\n");
  {
    State  state = start(*law, 0.5), next;
    double d     = 0;
    law->update_state(origin, state, 0, 1e12, 0., next);
    double mu = law->coefficient(origin, state, 0, 1e12, d);
    std::printf("   V = 0 for 1e12 s: psi = %.6f, mu = %g, finite: %s\n",
                next.variables[0],
                mu,
                std::isfinite(d) ? "yes" : "no");
    law->update_state(origin, state, 1000., 1., 0., next);
    mu = law->coefficient(origin, state, 1000., 1., d);
    std::printf("   V = 1000 m/s for 1 s: mu = %.6f (f_ss = %.6f), finite: "
                "%s\n",
                mu,
                f_ss(1000.),
                std::isfinite(mu) && std::isfinite(d) ? "yes" : "no");
  }
}
