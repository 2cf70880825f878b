// The slowness law with cut-offs (the review paper's eq. 4.5) and Perrin's
// regularised form (eq. 4.6):
// - steady state of eq. 4.5 after many steps at constant slip rate against
//   its closed form;
// - Perrin's law sticks with a finite friction at V = 0 and its state stays
//   below L/V1 however long it sticks; eq. 4.5 grows theta by dt;
// - a velocity step against the closed form theta(t), for steps with
//   (V1 + V) dt / L from 1e-3 to 1000;
// - the consistent tangent against central differences, at V = 0 for
//   Perrin's law (one-sided), steady sliding and after a velocity step;
// - the initial state from the initial traction;
// - bad parameters name the entry.

#include <rupture/base/utilities.h>
#include <rupture/friction/slowness_law.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <cstdio>

using namespace dealii;
using rupture::Friction::SlownessLaw;
using rupture::Friction::State;

namespace
{
  // mu0 = 0.6, A = 0.008, B = 0.012, L = 0.02 m, Vinf = 1 m/s,
  // theta0 = 1e-3 s; Perrin's V0 = 1e-9 m/s and V1 = 1e-10 m/s when
  // perrin.
  std::unique_ptr<rupture::Friction::Interface>
  make(const bool         perrin,
       const std::string &L             = "0.02",
       const std::string &initial_state = "")
  {
    ParameterHandler prm;
    prm.enter_subsection("Fault");
    rupture::Friction::declare_parameters(prm);
    prm.set("Friction law", "slowness law");
    prm.enter_subsection("Slowness law");
    prm.set("Static friction coefficient", "0.6");
    prm.set("Direct effect", "0.008");
    prm.set("Evolution effect", "0.012");
    prm.set("Characteristic slip distance", L);
    prm.set("High-velocity cut-off", "1");
    prm.set("State cut-off", "1e-3");
    prm.set("Low-velocity cut-off", perrin ? "1e-9" : "0");
    prm.set("Healing cut-off", perrin ? "1e-10" : "0");
    prm.set("Initial state", initial_state);
    prm.leave_subsection();
    auto law = rupture::Friction::create(prm);
    prm.leave_subsection();
    return law;
  }

  const Point<3> origin(0, 0, -7500);

  double
  mu_of(const bool perrin, const double V, const double theta)
  {
    const double V0 = perrin ? 1e-9 : 0;
    return 0.6 + 0.008 * std::log((V0 + V) / (1 + V)) +
           0.012 * std::log(1 + theta / 1e-3);
  }

  double
  relative_error(const double value, const double reference)
  {
    return std::abs(value - reference) / std::max(std::abs(reference), 1e-300);
  }

  State
  start(const rupture::Friction::Interface &law, const double theta)
  {
    State state;
    law.initialize_state(origin, 0.6, state);
    state.variables = {theta};
    return state;
  }

  State
  advance(const rupture::Friction::Interface &law,
          State                               state,
          const double                        V,
          const double                        dt,
          const unsigned int                  n)
  {
    for (unsigned int i = 0; i < n; ++i)
      {
        State next;
        law.update_state(origin, state, V * dt, dt, 0., next);
        state = next;
      }
    return state;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  std::printf("1. Steady state of eq. 4.5 (theta = L/V): mu after 200 steps "
              "of dt = 10 L/V\n");
  {
    const auto law = make(false);
    for (const double V : {1e-12, 1e-9, 1e-6, 1e-3, 1.})
      {
        const double dt        = 10 * 0.02 / V;
        const State  state     = advance(*law, start(*law, 5.), V, dt, 200);
        double       d         = 0;
        const double mu        = law->coefficient(origin, state, V * dt, dt, d);
        const double reference = mu_of(false, V, 0.02 / V);
        std::printf("   V = %-6.0e mu = %.8f, closed form %.8f: %s\n",
                    V,
                    mu,
                    reference,
                    relative_error(mu, reference) < 1e-10 ? "agree" : "DIFFER");
      }
  }

  std::printf("\n2. Sticking (V = 0) for 1e12 s from theta = 1 s\n");
  for (const bool perrin : {false, true})
    {
      const auto   law   = make(perrin);
      const State  state = advance(*law, start(*law, 1.), 0, 1e11, 10);
      double       d     = 0;
      const double mu    = law->coefficient(origin, state, 0, 1e11, d);
      // The coefficient of a further step of 1e11 s at V = 0 (theta
      // grows by 1e11 s in eq. 4.5, stays at L/V1 in Perrin's law). Eq. 4.5
      // has no value at V = 0: the law takes it at 1e-30 m/s.
      const double reference = perrin ?
                                 mu_of(true, 0, state.variables[0]) :
                                 mu_of(false, 1e-30, state.variables[0] + 1e11);
      std::printf("   %s: theta = %.6e s%s, mu(V = 0) = %.6f, closed form "
                  "%.6f%s: %s\n",
                  perrin ? "Perrin (eq. 4.6)" : "eq. 4.5         ",
                  state.variables[0],
                  perrin ? " (L/V1 = 2e+08 s)" : " (1 + 1e12 s)",
                  mu,
                  reference,
                  perrin ? "" : " at V = 1e-30 m/s",
                  relative_error(mu, reference) < 1e-10 ? "agree" : "DIFFER");
    }

  std::printf("\n3. Velocity step 1e-6 -> 1e-5 m/s from steady state, to "
              "t = 2000 s\n");
  for (const bool perrin : {false, true})
    {
      const auto   law = make(perrin);
      const double V1 = 1e-6, V2 = 1e-5, L = 0.02;
      const double Vh     = perrin ? 1e-10 : 0;
      const double theta1 = L / (Vh + V1);
      for (const double x : {1e-3, 1., 1000.})
        {
          const double dt          = x * L / (Vh + V2);
          State        state       = start(*law, theta1);
          double       error_theta = 0, error_mu = 0;
          const double end = std::max(2000., dt);
          for (double t = dt; t <= end * (1 + 1e-12); t += dt)
            {
              double       d  = 0;
              const double mu = law->coefficient(origin, state, V2 * dt, dt, d);
              state           = advance(*law, state, V2, dt, 1);
              const double r  = (Vh + V2) / L;
              const double theta = 1 / r + (theta1 - 1 / r) * std::exp(-r * t);
              error_theta        = std::max(error_theta,
                                     relative_error(state.variables[0], theta));
              error_mu           = std::max(error_mu,
                                  relative_error(mu, mu_of(perrin, V2, theta)));
            }
          std::printf("   %s (V1 + V) dt/L = %-6g theta: %s, mu: %s\n",
                      perrin ? "Perrin " : "eq. 4.5",
                      x,
                      error_theta < 1e-12 ? "exact" : "INEXACT",
                      error_mu < 1e-12 ? "exact" : "INEXACT");
        }
    }

  std::printf("\n4. Consistent tangent against central differences (dt = "
              "0.01 s)\n");
  for (const bool perrin : {false, true})
    {
      const auto law = make(perrin);
      struct Case
      {
        const char *name;
        double      V;
        double      theta;
      };
      for (const Case &c : {Case{"stick V = 0", 0., 2e8},
                            Case{"steady", 1e-6, 2e4},
                            Case{"vel. step", 1e-3, 2e4},
                            Case{"very fast", 10., 2e4}})
        {
          if (c.V == 0 && !perrin)
            continue;
          const double dt    = 0.01;
          const State  state = start(*law, c.theta);
          const double l     = c.V * dt;
          double       d = 0, unused = 0;
          law->coefficient(origin, state, l, dt, d);
          const double h = (l == 0) ? 1e-16 : 1e-6 * l;
          const double fd =
            (l == 0) ? (law->coefficient(origin, state, h, dt, unused) -
                        law->coefficient(origin, state, 0, dt, unused)) /
                         h :
                       (law->coefficient(origin, state, l + h, dt, unused) -
                        law->coefficient(origin, state, l - h, dt, unused)) /
                         (2 * h);
          std::printf("   %s %-12s %s\n",
                      perrin ? "Perrin " : "eq. 4.5",
                      c.name,
                      relative_error(d, fd) < 1e-5 ? "agrees" : "DIFFERS");
        }
    }

  std::printf("\n5. Initial state for |tau|/|sigma| = 0.62 at V_ini = 1e-12 "
              "m/s\n");
  for (const bool perrin : {false, true})
    {
      const auto law = make(perrin);
      State      state;
      law->initialize_state(origin, 0.62, state);
      std::printf("   %s theta = %.6e s, mu(V_ini, theta) = %.10f\n",
                  perrin ? "Perrin " : "eq. 4.5",
                  state.variables[0],
                  mu_of(perrin, 1e-12, state.variables[0]));
    }

  std::printf("\n6. Bad parameters\n");
  const auto report = [](const std::string &what, const auto &action) {
    try
      {
        action();
        std::printf("   %s: accepted\n", what.c_str());
      }
    catch (const ExceptionBase &e)
      {
        std::printf("   %s:\n     %s\n",
                    what.c_str(),
                    rupture::Utilities::message_of(e).c_str());
      }
  };
  report("L = 0", [] {
    State s;
    make(false, "0")->initialize_state(origin, 0.6, s);
  });
  report("initial state -1", [] {
    State s;
    make(true, "0.02", "-1")->initialize_state(origin, 0.6, s);
  });
  report("initial friction below the law's range", [] {
    State s;
    make(false)->initialize_state(origin, 0.1, s);
  });
}
