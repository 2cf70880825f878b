// Ruina's law with two state variables (the review paper's eq. 4.4, with
// B1 = B2 = 0.006, d1 = 0.01 m, d2 = 0.1 m, A = 0.008, Vc = 1e-6 m/s):
// - steady state: mu = mu0 + (A - B1 - B2) ln(V/Vc) after many steps;
// - a velocity step 1e-6 -> 1e-4 m/s: mu(t) against the closed form with
//   its two decay lengths, for steps with V dt / d1 from 1e-3 to 1000;
// - the consistent tangent against central differences (both forms; the
//   regularised one also at V = 0);
// - the initial state from the initial traction, shared as B1 : B2.

#include <rupture/friction/two_state_variables.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <cstdio>

using namespace dealii;
using rupture::Friction::State;

namespace
{
  std::unique_ptr<rupture::Friction::Interface>
  make(const std::string &formulation)
  {
    ParameterHandler prm;
    prm.enter_subsection("Fault");
    rupture::Friction::declare_parameters(prm);
    prm.set("Friction law", "two state variables");
    prm.enter_subsection("Two state variables");
    prm.set("Formulation", formulation);
    prm.leave_subsection();
    auto law = rupture::Friction::create(prm);
    prm.leave_subsection();
    return law;
  }

  const Point<3> origin(0, 0, -7500);

  double
  relative_error(const double value, const double reference)
  {
    return std::abs(value - reference) / std::max(std::abs(reference), 1e-300);
  }

  State
  start(const rupture::Friction::Interface &law,
        const double                        th1,
        const double                        th2)
  {
    State state;
    law.initialize_state(origin, 0.6, state);
    state.variables = {th1, th2};
    return state;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  std::printf("1. Steady state (logarithmic): mu after 300 steps of dt = "
              "d2/V\n");
  {
    const auto law = make("logarithmic");
    for (const double V : {1e-12, 1e-6, 1e-3, 1.})
      {
        State        state = start(*law, 0.01, -0.02);
        const double dt    = 0.1 / V;
        for (unsigned int i = 0; i < 300; ++i)
          {
            State next;
            law->update_state(origin, state, V * dt, dt, 0., next);
            state = next;
          }
        double       d         = 0;
        const double mu        = law->coefficient(origin, state, V * dt, dt, d);
        const double reference = 0.6 + (0.008 - 0.012) * std::log(V / 1e-6);
        std::printf("   V = %-6.0e mu = %.8f, closed form %.8f: %s\n",
                    V,
                    mu,
                    reference,
                    relative_error(mu, reference) < 1e-10 ? "agree" : "DIFFER");
      }
  }

  std::printf("\n2. Velocity step 1e-6 -> 1e-4 m/s from steady state "
              "(logarithmic), to t = 5000 s\n");
  {
    const auto   law = make("logarithmic");
    const double V2  = 1e-4;
    const double ss  = -0.006 * std::log(V2 / 1e-6);
    for (const double x : {1e-3, 1., 1000.})
      {
        const double dt    = x * 0.01 / V2;
        State        state = start(*law, 0, 0);
        double       error = 0;
        const double end   = std::max(5000., dt);
        for (double t = dt; t <= end * (1 + 1e-12); t += dt)
          {
            double       d  = 0;
            const double mu = law->coefficient(origin, state, V2 * dt, dt, d);
            State        next;
            law->update_state(origin, state, V2 * dt, dt, 0., next);
            state              = next;
            const double th1   = ss * (1 - std::exp(-V2 * t / 0.01));
            const double th2   = ss * (1 - std::exp(-V2 * t / 0.1));
            const double exact = 0.6 + th1 + th2 + 0.008 * std::log(V2 / 1e-6);
            error              = std::max(error, relative_error(mu, exact));
          }
        std::printf("   V dt/d1 = %-6g mu: %s\n",
                    x,
                    error < 1e-12 ? "exact" : "INEXACT");
      }
  }

  std::printf("\n3. Consistent tangent against central differences (dt = "
              "0.01 s)\n");
  for (const std::string form : {"logarithmic", "regularized"})
    {
      const auto law = make(form);
      struct Case
      {
        const char *name;
        double      V;
      };
      for (const Case &c : {Case{"stick V = 0", 0.},
                            Case{"near V = 0", 1e-14},
                            Case{"steady", 1e-6},
                            Case{"vel. step", 1e-2},
                            Case{"very fast", 10.}})
        {
          if (c.V == 0 && form == "logarithmic")
            continue;
          const double dt    = 0.01;
          const State  state = start(*law, 0.02, 0.01);
          const double l     = c.V * dt;
          double       d = 0, u = 0;
          law->coefficient(origin, state, l, dt, d);
          const double h  = (l == 0) ? 1e-50 : 1e-6 * l;
          const double fd = (l == 0) ?
                              (law->coefficient(origin, state, h, dt, u) -
                               law->coefficient(origin, state, 0, dt, u)) /
                                h :
                              (law->coefficient(origin, state, l + h, dt, u) -
                               law->coefficient(origin, state, l - h, dt, u)) /
                                (2 * h);
          std::printf("   %-12s %-12s %s\n",
                      form.c_str(),
                      c.name,
                      relative_error(d, fd) < 1e-5 ? "agrees" : "DIFFERS");
        }
    }

  std::printf("\n4. Initial state for |tau|/|sigma| = 0.625 at V_ini = "
              "1e-12 m/s\n");
  for (const std::string form : {"logarithmic", "regularized"})
    {
      const auto law = make(form);
      State      state;
      law->initialize_state(origin, 0.625, state);
      double       d  = 0;
      const double mu = law->coefficient(origin, state, 1e-12 * 1e-9, 1e-9, d);
      std::printf("   %-12s th1 = %.8f, th2 = %.8f, mu(V_ini) = %.8f\n",
                  form.c_str(),
                  state.variables[0],
                  state.variables[1],
                  mu);
    }
}
