// The rate-and-state family in the slip rate (Friction::RateStateFamily):
// for every law of the family and slip rates from 0 to 1 m/s,
// - the rates of change of the state variables (state_rate(), which the
//   boundary-integral method integrates) against the change update_state()
//   makes over a short step, by Richardson extrapolation of two steps;
// - the coefficient at a rate with the state held (coefficient_at_rate(),
//   the split nodes' friction) against the coefficient of a vanishing step
//   (coefficient(), the penalty return map's);
// - Chester's law: theta's rate (its temperature relaxes by itself over
//   t_c and is left to relax_state(), which gives the temperature that the
//   volume method's step reaches under the same heating; at T = T_r
//   without heating it stays, and its rate is 0).

#include <rupture/friction/interface.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

using namespace dealii;
using rupture::Friction::State;

namespace
{
  std::unique_ptr<rupture::Friction::Interface>
  make(const std::string                        &law,
       const std::string                        &section,
       const std::map<std::string, std::string> &settings)
  {
    ParameterHandler prm;
    prm.enter_subsection("Fault");
    rupture::Friction::declare_parameters(prm);
    prm.set("Friction law", law);
    prm.enter_subsection(section);
    for (const auto &[entry, value] : settings)
      prm.set(entry, value);
    prm.leave_subsection();
    auto result = rupture::Friction::create(prm);
    prm.leave_subsection();
    return result;
  }

  const Point<3> origin(0, 0, -7500);

  // The state variables after a step dt at the slip rate V.
  std::vector<double>
  after(const rupture::Friction::Interface &law,
        const State                        &state,
        const double                        V,
        const double                        dt)
  {
    State updated;
    law.update_state(origin, state, V * dt, dt, 0., updated);
    return updated.variables;
  }

  void
  check(const std::string                  &name,
        const rupture::Friction::Interface &law,
        const double                        initial_friction)
  {
    State state;
    law.initialize_state(origin, initial_friction, state);
    const double L = law.slip_scale(origin, state);
    std::printf("%s (L = %g m, %zu state variables)\n",
                name.c_str(),
                L,
                state.variables.size());
    for (const double V : {0., 1e-12, 1e-9, 1e-6, 1e-3, 1.})
      {
        std::vector<double> rates;
        law.state_rate(origin, state, V, rates);
        // A step short against the state's time scale L / V (1 s at V = 0).
        const double h  = (V > 0) ? 1e-6 * L / V : 1.;
        const auto   a  = after(law, state, V, h);
        const auto   b  = after(law, state, V, 0.5 * h);
        bool         ok = rates.size() == state.variables.size();
        std::printf("   V = %-7g rates", V);
        for (unsigned int i = 0; ok && i < rates.size(); ++i)
          {
            const double s  = state.variables[i];
            const double fd = 2 * (b[i] - s) / (0.5 * h) - (a[i] - s) / h;
            // The natural scale of a rate: |s| V / L (1 where the state
            // grows by the time at rest).
            const double scale =
              std::max({std::abs(rates[i]), std::abs(s) * V / L, 1e-300});
            ok = ok && std::abs(fd - rates[i]) <= 1e-6 * scale;
            std::printf(" %.6e", rates[i]);
          }
        // The coefficient of a vanishing step tends to the one at the rate
        // with the state held.
        // (Vanishing against the state's time scales: L / V and the time
        // over which the rates change the state by itself.)
        double d_step = 0, d_rate = 0;
        double dt = (V > 0) ? 1e-9 * L / V : 1e-9;
        for (unsigned int i = 0; i < rates.size(); ++i)
          if (rates[i] != 0 && state.variables[i] != 0)
            dt = std::min(dt, 1e-9 * std::abs(state.variables[i] / rates[i]));
        const double mu_step =
          law.coefficient(origin, state, V * dt, dt, d_step);
        const double mu_rate =
          law.coefficient_at_rate(origin, state, V, d_rate);
        const bool same_mu = std::abs(mu_step - mu_rate) <= 1e-9;
        std::printf(", against the steps: %s; mu = %.8f (%s)\n",
                    ok ? "agree" : "DIFFER",
                    mu_rate,
                    same_mu ? "the step's" : "NOT THE STEP'S");
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const std::map<std::string, std::string> none;
  check("rate and state, aging, regularized",
        *make("rate and state", "Rate and state", none),
        0.6);
  check("rate and state, slip law, logarithmic",
        *make("rate and state",
              "Rate and state",
              {{"Evolution law", "slip"}, {"Formulation", "logarithmic"}}),
        0.6);
  check("slowness law", *make("slowness law", "Slowness law", none), 0.6);
  check("slowness law, Perrin's V0 and V1",
        *make("slowness law",
              "Slowness law",
              {{"Low-velocity cut-off", "1e-9"}, {"Healing cut-off", "1e-10"}}),
        0.6);
  check("flash heating", *make("flash heating", "Flash heating", none), 0.6);
  check("two state variables",
        *make("two state variables", "Two state variables", none),
        0.6);
  check("two state variables, regularized",
        *make("two state variables",
              "Two state variables",
              {{"Formulation", "regularized"}}),
        0.6);

  check("chester", *make("chester", "Chester", none), 0.6);
  check("chester, logarithmic",
        *make("chester", "Chester", {{"Formulation", "logarithmic"}}),
        0.6);

  // relax_state() against the step of update_state() under a traction
  // (from 600 K, a 1 MPa traction, slip rates from rest to 1 m/s, steps
  // short and long against t_c = 1 s).
  const auto chester =
    make("chester", "Chester", {{"Initial temperature", "600"}});
  std::printf("chester: state_relaxes() = %s, %s\n",
              chester->state_relaxes(0) ? "true" : "false",
              chester->state_relaxes(1) ? "true" : "false");
  State state;
  chester->initialize_state(origin, 0.6, state);
  double worst = 0, worst_rate = 0;
  bool   theta_kept = true;
  for (const double V : {0., 1e-6, 1e-3, 1.})
    for (const double dt : {1e-3, 1., 1e3})
      {
        State stepped, relaxed = state;
        chester->update_state(origin, state, V * dt, dt, 1e6, stepped);
        chester->relax_state(origin, relaxed, 1e6 * V, dt);
        worst      = std::max(worst,
                         std::abs(relaxed.variables[1] - stepped.variables[1]) /
                           stepped.variables[1]);
        theta_kept = theta_kept && relaxed.variables[0] == state.variables[0];
        // relaxation_rate() against relax_state() over short steps
        // (Richardson of two).
        std::vector<double> rates;
        chester->relaxation_rate(origin, state, 1e6 * V, rates);
        const double h = 1e-6;
        State        a = state, b = state;
        chester->relax_state(origin, a, 1e6 * V, h);
        chester->relax_state(origin, b, 1e6 * V, 0.5 * h);
        const double T = state.variables[1];
        const double fd =
          2 * (b.variables[1] - T) / (0.5 * h) - (a.variables[1] - T) / h;
        worst_rate =
          std::max(worst_rate,
                   std::abs(fd - rates[1]) / std::max(std::abs(rates[1]), 1.) +
                     std::abs(rates[0]));
      }
  std::printf("   relax_state(): the temperature within 1e-14 of the step's: "
              "%s; theta left as it was: %s; relaxation_rate() against "
              "its short steps within 1e-6 (theta's 0): %s\n",
              worst < 1e-14 ? "yes" : "no",
              theta_kept ? "yes" : "no",
              worst_rate < 1e-6 ? "yes" : "no");
}
