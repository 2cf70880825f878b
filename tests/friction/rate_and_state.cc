// Dieterich-Ruina rate-and-state friction with one state variable, in both
// forms (regularised, logarithmic) and with both evolution laws (aging,
// slip), at the parameters of SCEC TPV101:
// - steady state: mu after many steps at a constant slip rate equals the
//   closed-form steady-state friction;
// - the initial state computed from the initial traction and slip rate
//   makes the law hold at t = 0;
// - a velocity step V1 -> V2: theta(t) and mu(t) against their closed forms
//   for steps with V dt / L from 5e-4 to 500 (the exact update), and the
//   forward-Euler update that fails beyond V dt / L = 2;
// - the consistent tangent d mu / d(slip increment) against central finite
//   differences: V = 0 (one-sided), near 0, steady sliding, after a
//   velocity step, very fast;
// - no NaN or Inf at V = 0 for 1e12 s, or at 1000 m/s;
// - bad parameters name the entry.

#include <rupture/base/utilities.h>
#include <rupture/friction/rate_and_state.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <cstdio>

using namespace dealii;
using rupture::Friction::RateAndState;
using rupture::Friction::State;

namespace
{
  std::unique_ptr<rupture::Friction::Interface>
  make(const std::string &formulation,
       const std::string &evolution,
       const std::string &a             = "0.008",
       const std::string &L             = "0.02",
       const std::string &initial_state = "")
  {
    ParameterHandler prm;
    prm.enter_subsection("Fault");
    rupture::Friction::declare_parameters(prm);
    prm.set("Friction law", "rate and state");
    prm.enter_subsection("Rate and state");
    prm.set("Formulation", formulation);
    prm.set("Evolution law", evolution);
    prm.set("Direct effect", a);
    prm.set("Evolution effect", "0.012");
    prm.set("Characteristic slip distance", L);
    prm.set("Reference friction coefficient", "0.6");
    prm.set("Reference slip rate", "1e-6");
    prm.set("Initial state", initial_state);
    prm.set("Initial slip rate", "1e-12");
    prm.leave_subsection();
    auto law = rupture::Friction::create(prm);
    prm.leave_subsection();
    return law;
  }

  const Point<3>                origin(0, 0, -7500);
  const RateAndState::Constants tpv101 = {{0.008, 0.012, 0.02, 0.6, 1e-6}};

  // The closed forms of the logarithmic law.
  double
  steady_log(const double V)
  {
    return 0.6 + (0.008 - 0.012) * std::log(V / 1e-6);
  }

  double
  steady_regularized(const double V)
  {
    const double psi = 0.6 + 0.012 * std::log(1e-6 / V);
    return 0.008 * std::asinh(V / 2e-6 * std::exp(psi / 0.008));
  }

  // theta at time t after a step to V2 from theta1, at constant V2.
  double
  theta_after_step(const bool   aging,
                   const double theta1,
                   const double V2,
                   const double t)
  {
    const double L = 0.02;
    if (aging)
      return L / V2 + (theta1 - L / V2) * std::exp(-V2 * t / L);
    return L / V2 * std::exp(std::log(V2 * theta1 / L) * std::exp(-V2 * t / L));
  }

  double
  relative_error(const double value, const double reference)
  {
    return std::abs(value - reference) / std::max(std::abs(reference), 1e-300);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  std::printf("1. Steady state: mu after 200 steps of dt = 10 L/V from "
              "theta = 1 s\n");
  std::printf("   form         law    V (m/s)   mu          closed form  "
              "agree\n");
  for (const std::string form : {"logarithmic", "regularized"})
    for (const std::string evolution : {"aging", "slip"})
      {
        const auto law = make(form, evolution);
        for (const double V : {1e-12, 1e-9, 1e-6, 1e-3, 1.})
          {
            State state;
            law->initialize_state(origin, 0.6, state);
            state.variables = {1.};
            const double dt = 10 * 0.02 / V;
            for (unsigned int i = 0; i < 200; ++i)
              {
                State next;
                law->update_state(origin, state, V * dt, dt, 0., next);
                state = next;
              }
            double       d  = 0;
            const double mu = law->coefficient(origin, state, V * dt, dt, d);
            const double reference =
              (form == "logarithmic") ? steady_log(V) : steady_regularized(V);
            std::printf("   %-12s %-6s %-9.0e %.8f  %.8f   %s\n",
                        form.c_str(),
                        evolution.c_str(),
                        V,
                        mu,
                        reference,
                        relative_error(mu, reference) < 1e-10 ? "yes" : "NO");
          }
      }

  std::printf("\n2. Initial state from tau_0/sigma_0 = 75/120 and V_ini = "
              "1e-12 m/s\n");
  for (const std::string form : {"logarithmic", "regularized"})
    {
      const auto  law = make(form, "aging");
      State       state;
      const auto &rs = dynamic_cast<const RateAndState &>(*law);
      law->initialize_state(origin, 75. / 120., state);
      double       dV = 0, dtheta = 0;
      const double mu = rs.friction(
        tpv101, state.variables, 1e-12, state.variables[0], dV, dtheta);
      std::printf("   %-12s theta = %.6e s, mu(V_ini, theta) = %.10f\n",
                  form.c_str(),
                  state.variables[0],
                  mu);
    }

  std::printf("\n3. Velocity step 1e-6 -> 1e-5 m/s from steady state, "
              "logarithmic form, to t = 2000 s\n");
  std::printf("   law    V dt/L   max rel. error theta   max rel. error "
              "mu\n");
  for (const std::string evolution : {"aging", "slip"})
    {
      const auto   law = make("logarithmic", evolution);
      const double V1 = 1e-6, V2 = 1e-5, L = 0.02;
      const double theta1 = L / V1;
      for (const double x : {5e-4, 0.5, 5., 500.})
        {
          const double dt = x * L / V2;
          State        state;
          law->initialize_state(origin, 0.6, state);
          state.variables          = {theta1};
          double       error_theta = 0, error_mu = 0;
          const double end = std::max(2000., dt);
          for (double t = dt; t <= end * (1 + 1e-12); t += dt)
            {
              double       d  = 0;
              const double mu = law->coefficient(origin, state, V2 * dt, dt, d);
              State        next;
              law->update_state(origin, state, V2 * dt, dt, 0., next);
              state = next;
              const double theta =
                theta_after_step(evolution == "aging", theta1, V2, t);
              const double mu_exact = 0.6 + 0.008 * std::log(V2 / 1e-6) +
                                      0.012 * std::log(1e-6 * theta / L);
              error_theta = std::max(error_theta,
                                     relative_error(state.variables[0], theta));
              error_mu    = std::max(error_mu, relative_error(mu, mu_exact));
            }
          std::printf("   %-6s %-8g %s                   %s\n",
                      evolution.c_str(),
                      x,
                      error_theta < 1e-12 ? "< 1e-12" : "LARGE  ",
                      error_mu < 1e-12 ? "< 1e-12" : "LARGE");
        }
      // The forward-Euler update of the aging law at V dt / L = 5.
      if (evolution == "aging")
        {
          const double dt    = 5 * L / V2;
          double       theta = theta1;
          bool         fails = false;
          for (unsigned int i = 0; i < 20; ++i)
            {
              theta += dt * (1 - V2 * theta / L);
              fails = fails || !(theta > 0);
            }
          std::printf("   forward Euler (aging, V dt/L = 5): theta leaves the "
                      "positive numbers: %s\n",
                      fails ? "yes" : "no");
        }
    }

  std::printf("\n4. Consistent tangent d mu/d(slip increment) against "
              "central differences (dt = 0.01 s)\n");
  std::printf("   form         law    case          agree\n");
  struct Case
  {
    const char *name;
    double      V;
    double      theta;
  };
  const Case cases[] = {{"stick V = 0", 0., 0.02 / 1e-12},
                        {"near V = 0", 1e-15, 0.02 / 1e-12},
                        {"steady", 1e-6, 0.02 / 1e-6},
                        {"vel. step", 1e-3, 0.02 / 1e-6},
                        {"very fast", 10., 0.02 / 1e-6}};
  for (const std::string form : {"logarithmic", "regularized"})
    for (const std::string evolution : {"aging", "slip"})
      {
        const auto law = make(form, evolution);
        for (const Case &c : cases)
          {
            if (c.V == 0 && form == "logarithmic")
              continue; // no value at V = 0
            const double dt = 0.01;
            State        state;
            law->initialize_state(origin, 0.6, state);
            state.variables = {c.theta};
            const double l  = c.V * dt;
            double       d = 0, unused = 0;
            law->coefficient(origin, state, l, dt, d);
            double fd = 0;
            if (l == 0)
              {
                // One-sided, at a slip increment far below the curvature
                // scale of the regularised law at V = 0.
                const double h = 1e-60;
                fd = (law->coefficient(origin, state, h, dt, unused) -
                      law->coefficient(origin, state, 0, dt, unused)) /
                     h;
              }
            else
              {
                const double h = 1e-6 * l;
                fd = (law->coefficient(origin, state, l + h, dt, unused) -
                      law->coefficient(origin, state, l - h, dt, unused)) /
                     (2 * h);
              }
            std::printf("   %-12s %-6s %-13s %s\n",
                        form.c_str(),
                        evolution.c_str(),
                        c.name,
                        relative_error(d, fd) < 1e-5 ? "yes" : "NO");
          }
      }

  std::printf("\n5. Extremes (regularised form)\n");
  for (const std::string evolution : {"aging", "slip"})
    {
      const auto law = make("regularized", evolution);
      State      state;
      law->initialize_state(origin, 0.6, state);
      state.variables = {1.};
      State  next;
      double d = 0;
      law->update_state(origin, state, 0, 1e12, 0., next);
      const double mu0 = law->coefficient(origin, state, 0, 1e12, d);
      std::printf("   %-6s V = 0 for 1e12 s: theta = %.6e s, mu = %g, "
                  "finite: %s\n",
                  evolution.c_str(),
                  next.variables[0],
                  mu0,
                  std::isfinite(next.variables[0]) && std::isfinite(d) ? "yes" :
                                                                         "no");
      law->update_state(origin, state, 1000., 1., 0., next);
      const double mu1 = law->coefficient(origin, state, 1000., 1., d);
      std::printf("   %-6s V = 1000 m/s for 1 s: theta = %.6e s (L/V = "
                  "2e-05), mu = %.6f, finite: %s\n",
                  evolution.c_str(),
                  next.variables[0],
                  mu1,
                  std::isfinite(mu1) && std::isfinite(d) ? "yes" : "no");
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
  report("a = 0", [] {
    State s;
    make("regularized", "aging", "0")->initialize_state(origin, 0.6, s);
  });
  report("L = -1 where x > 0", [] {
    State s;
    make("regularized", "aging", "0.008", "(x > 0) ? -1 : 0.02")
      ->initialize_state(Point<3>(1, 0, 0), 0.6, s);
  });
  report("no initial state and no initial traction", [] {
    State s;
    make("regularized", "aging")->initialize_state(origin, s);
  });
  report("initial state 0", [] {
    State s;
    make("regularized", "aging", "0.008", "0.02", "0")
      ->initialize_state(origin, 0.6, s);
  });
}
