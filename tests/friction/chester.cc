// Chester's temperature-dependent rate-and-state law (the review's eq.
// 4.7-4.8) with A = 0.01, B = 0.015, d_c = 0.4 m, mu0 = 0.6, V_c = 1e-6 m/s,
// Q_A = Q_B = 1.3e5 J/mol, T* = 573 K, H = 2.7e4 J/(m^2 K), t_c = 1 s:
// - steady state at a constant slip rate and temperature against the
//   review's eq. 4.9, in both forms;
// - a velocity step at constant temperature: theta(t) against its closed
//   form for steps with V dt / d_c from 1e-3 to 1000;
// - a temperature step at constant V (Chester's experiment): the direct
//   jump A Q_A / R (1/T2 - 1/T1), then the new steady state;
// - frictional heating at a constant traction and slip rate: T(t) against
//   the closed form of dT/dt = tau V / H - (T - T_r) / t_c;
// - the consistent tangent against central differences;
// - the initial state from the initial traction;
// - no NaN or Inf at V = 0 for 1e12 s or at 1000 m/s.

#include <rupture/friction/chester.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <cstdio>

using namespace dealii;
using rupture::Friction::Chester;
using rupture::Friction::State;

namespace
{
  std::unique_ptr<rupture::Friction::Interface>
  make(const std::string &formulation, const std::string &reservoir = "573")
  {
    ParameterHandler prm;
    prm.enter_subsection("Fault");
    rupture::Friction::declare_parameters(prm);
    prm.set("Friction law", "chester");
    prm.enter_subsection("Chester");
    prm.set("Formulation", formulation);
    prm.set("Reservoir temperature", reservoir);
    prm.set("Initial temperature", reservoir);
    prm.leave_subsection();
    auto law = rupture::Friction::create(prm);
    prm.leave_subsection();
    return law;
  }

  const Point<3> origin(0, 0, -7500);
  const double A = 0.01, B = 0.015, d_c = 0.4, mu0 = 0.6, V_c = 1e-6, Q = 1.3e5,
               T_star = 573, H = 2.7e4, t_c = 1, R = Chester::gas_constant;

  // Eq. 4.9 written out.
  double
  mu_ss(const double V, const double T)
  {
    return mu0 + (A - B) * std::log(V / V_c) +
           (A * Q - B * Q) / R * (1 / T - 1 / T_star);
  }

  double
  relative_error(const double value, const double reference)
  {
    return std::abs(value - reference) / std::max(std::abs(reference), 1e-300);
  }

  State
  start(const rupture::Friction::Interface &law,
        const double                        theta,
        const double                        T)
  {
    State state;
    law.initialize_state(origin, 0.6, state);
    state.variables = {theta, T};
    return state;
  }

  // Steps of dt at the slip rate V and shear traction tau.
  State
  run(const rupture::Friction::Interface &law,
      State                               state,
      const double                        V,
      const double                        tau,
      const double                        dt,
      const unsigned int                  steps)
  {
    for (unsigned int i = 0; i < steps; ++i)
      {
        State next;
        law.update_state(origin, state, V * dt, dt, tau, next);
        state = next;
      }
    return state;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  std::printf("1. Steady state (no heating): mu after 200 steps of dt = 10 "
              "d_c/V against eq. 4.9\n");
  for (const std::string form : {"logarithmic", "regularized"})
    for (const double T : {500., 573., 700.})
      {
        const auto law = make(form, std::to_string(T));
        for (const double V : {1e-9, 1e-3, 1.})
          {
            const double dt    = 10 * d_c / V;
            const State  state = run(*law, start(*law, 0, T), V, 0, dt, 200);
            double       d     = 0;
            const double mu    = law->coefficient(origin, state, V * dt, dt, d);
            std::printf("   %-11s T = %3.0f K V = %-6.0e mu = %.8f, eq. 4.9 "
                        "%.8f: %s\n",
                        form.c_str(),
                        T,
                        V,
                        mu,
                        mu_ss(V, T),
                        relative_error(mu, mu_ss(V, T)) < 1e-10 ? "agree" :
                                                                  "DIFFER");
          }
      }

  const auto   law = make("regularized");
  const double T1 = 573, T2 = 623;
  const auto   theta_ss = [](const double V, const double T) {
    return -std::log(V / V_c) - Q / R * (1 / T - 1 / T_star);
  };

  std::printf("\n2. Velocity step 1e-6 -> 1 m/s at 573 K, to t = 4 s\n");
  for (const double x : {1e-3, 1., 1000.})
    {
      const double V = 1., dt = x * d_c / V;
      const double th1 = theta_ss(1e-6, T1), th2 = theta_ss(1., T1);
      State        state = start(*law, th1, T1);
      double       error = 0;
      const double end   = std::max(4., dt);
      for (double t = dt; t <= end * (1 + 1e-12); t += dt)
        {
          state            = run(*law, state, V, 0, dt, 1);
          const double ref = th2 + (th1 - th2) * std::exp(-V * t / d_c);
          error = std::max(error, relative_error(state.variables[0], ref));
        }
      std::printf("   V dt/d_c = %-6g theta: %s\n",
                  x,
                  error < 1e-12 ? "exact" : "INEXACT");
    }

  std::printf("\n3. Temperature step 573 -> 623 K at V = 1e-6 m/s\n");
  {
    const double V = 1e-6, dt = 1e-3;
    State        state  = start(*law, theta_ss(V, T1), T1);
    double       d      = 0;
    const double before = law->coefficient(origin, state, V * dt, dt, d);
    state.variables[1]  = T2;
    const double jump   = law->coefficient(origin, state, V * dt, dt, d);
    const double direct = A * Q / R * (1 / T2 - 1 / T1);
    std::printf("   direct jump %.8f, A Q_A/R (1/T2 - 1/T1) = %.8f: %s\n",
                jump - before,
                direct,
                std::abs(jump - before - direct) < 1e-9 ? "agree" : "DIFFER");
    // Hold T2: the same law with its reservoir at T2 (theta evolves at
    // the mean temperature of a step, which must stay T2).
    // (Its constants, which a state caches, are those of that law.)
    const auto held  = make("regularized", std::to_string(T2));
    state.parameters = start(*held, 0, T2).parameters;
    for (unsigned int i = 0; i < 100; ++i)
      state = run(*held, state, V, 0, 10 * d_c / V, 1);
    const double after = law->coefficient(origin, state, V * dt, dt, d);
    std::printf("   after 1000 d_c: mu = %.8f, eq. 4.9 at T2 %.8f: %s\n",
                after,
                mu_ss(V, T2),
                relative_error(after, mu_ss(V, T2)) < 1e-6 ? "agree" :
                                                             "DIFFER");
  }

  std::printf("\n4. Heating by tau = 3e7 Pa at V = 1 m/s from T_r = 573 K\n");
  for (const double dt : {1e-3, 0.1, 10.})
    {
      const double tau = 3e7, V = 1, T_inf = T1 + tau * V * t_c / H;
      State        state = start(*law, theta_ss(V, T1), T1);
      double       error = 0;
      for (double t = dt; t <= 20 * (1 + 1e-12); t += dt)
        {
          state            = run(*law, state, V, tau, dt, 1);
          const double ref = T_inf + (T1 - T_inf) * std::exp(-t / t_c);
          error = std::max(error, relative_error(state.variables[1], ref));
        }
      std::printf("   dt = %-5g T(20 s) = %.4f K (T_inf = %.4f K): %s\n",
                  dt,
                  state.variables[1],
                  T_inf,
                  error < 1e-12 ? "exact" : "INEXACT");
    }

  std::printf("\n5. Consistent tangent against central differences (dt = "
              "0.01 s)\n");
  {
    struct Case
    {
      const char *name;
      double      V;
      double      theta;
      double      T;
    };
    const double creep = theta_ss(1e-9, T1);
    for (const Case &c : {Case{"stick V = 0", 0., creep, T1},
                          Case{"steady creep", 1e-9, creep, T1},
                          Case{"vel. step", 1e-3, creep, T1},
                          Case{"fast, hot", 5., creep, 900.}})
      for (const std::string form : {"logarithmic", "regularized"})
        {
          const auto   l2    = make(form);
          const double dt    = 0.01;
          const State  state = start(*l2, c.theta, c.T);
          const double l     = c.V * dt;
          double       d = 0, u = 0;
          l2->coefficient(origin, state, l, dt, d);
          const double h  = (l == 0) ? 1e-45 : 1e-6 * l;
          const double fd = (l == 0) ?
                              (l2->coefficient(origin, state, h, dt, u) -
                               l2->coefficient(origin, state, 0, dt, u)) /
                                h :
                              (l2->coefficient(origin, state, l + h, dt, u) -
                               l2->coefficient(origin, state, l - h, dt, u)) /
                                (2 * h);
          // The logarithmic form has no derivative at V = 0.
          const bool skip = (l == 0 && form == "logarithmic");
          std::printf("   %-13s %-11s %s\n",
                      c.name,
                      form.c_str(),
                      skip                         ? "(none at V = 0)" :
                      relative_error(d, fd) < 1e-5 ? "agrees" :
                                                     "DIFFERS");
        }
  }

  std::printf("\n6. Initial state for mu_ini = 0.58 at V_ini = 1e-12 m/s, "
              "573 K\n");
  {
    State state;
    law->initialize_state(origin, 0.58, state);
    double       d  = 0;
    const double mu = law->coefficient(origin, state, 1e-12 * 1e-6, 1e-6, d);
    std::printf("   theta = %.8f, T = %.1f K, mu(V_ini) = %.10f\n",
                state.variables[0],
                state.variables[1],
                mu);
  }

  std::printf("\n7. Extremes\n");
  {
    State  state = start(*law, 0.5, T1), next;
    double d     = 0;
    law->update_state(origin, state, 0, 1e12, 0., next);
    double mu = law->coefficient(origin, state, 0, 1e12, d);
    std::printf("   V = 0 for 1e12 s: theta = %.6f, T = %.1f K, mu = %g, "
                "finite: %s\n",
                next.variables[0],
                next.variables[1],
                mu,
                std::isfinite(d) ? "yes" : "no");
    law->update_state(origin, state, 1000., 1., 1e6, next);
    mu = law->coefficient(origin, state, 1000., 1., d);
    std::printf("   V = 1000 m/s for 1 s: mu = %.6f, T = %.1f K, finite: %s\n",
                mu,
                next.variables[1],
                std::isfinite(mu) && std::isfinite(d) ? "yes" : "no");
  }
}
