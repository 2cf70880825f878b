#include <rupture/friction/law_utilities.h>
#include <rupture/friction/slowness_law.h>
#include <rupture/friction/state_evolution.h>

#include <algorithm>
#include <cmath>

namespace rupture
{
  namespace Friction
  {
    namespace
    {
      /// Without Perrin's V0 the law has no value at V = 0: it is taken at
      /// V >= this rate (m/s).
      constexpr double minimum_rate = 1e-30;

      using Family = RateStateFamily<8>;
      using Range  = Family::Range;

      const std::array<Family::ConstantEntry, 8> entries = {
        {{"Static friction coefficient", Range::finite, "a finite number"},
         {"Direct effect", Range::non_negative, ">= 0"},
         {"Evolution effect", Range::non_negative, ">= 0"},
         {"Characteristic slip distance", Range::positive, "> 0"},
         {"High-velocity cut-off", Range::positive, "> 0"},
         {"State cut-off", Range::positive, "> 0"},
         {"Low-velocity cut-off", Range::non_negative, ">= 0"},
         {"Healing cut-off", Range::non_negative, ">= 0"}}};
    } // namespace



    SlownessLaw::SlownessLaw()
      : RateStateFamily<8>("Slowness law", entries, 3, 2)
    {}



    void
    SlownessLaw::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Slowness law");
      {
        const std::array<const char *, 8> defaults = {
          "0.6", "0.008", "0.012", "0.02", "1e-6", "1e-3", "0", "0"};
        const std::array<const char *, 8> help = {
          "mu0, the friction coefficient of the law, as a function of x, y, "
          "z (m; in 2-D z = 0).",
          "A, the direct effect, as a function of x, y, z. >= 0.",
          "B, the evolution effect, as a function of x, y, z. >= 0.",
          "L (m), the slip over which the state evolves, as a function of "
          "x, y, z. > 0.",
          "Vinf (m/s), the cut-off of the direct effect at high slip rates, "
          "as a function of x, y, z. > 0.",
          "theta0 (s), the cut-off of the state for short contact times, as "
          "a function of x, y, z. > 0.",
          "Perrin's V0 (m/s), as a function of x, y, z. >= 0. 0 gives the "
          "review paper's eq. 4.5, which has no value at V = 0; > 0 makes "
          "the law regular there (eq. 4.6) with a finite static friction "
          "mu0 + A ln(V0/Vinf) + B ln(1 + theta/theta0).",
          "Perrin's V1 (m/s), as a function of x, y, z. >= 0. With V1 > 0 "
          "the state stays below L/V1."};
        for (unsigned int i = 0; i < 8; ++i)
          prm.declare_entry(entries[i].name,
                            defaults[i],
                            Patterns::Anything(),
                            help[i]);
        prm.declare_entry(
          "Initial state",
          "",
          Patterns::Anything(),
          "theta (s) at t = 0 as a function of x, y, z (>= 0). Empty: the "
          "state for which the law holds at t = 0 with the fault's initial "
          "traction and the <Initial slip rate>.");
        prm.declare_entry("Initial slip rate",
                          "1e-12",
                          Patterns::Anything(),
                          "V_ini (m/s), the slip rate that defines the "
                          "initial state when <Initial state> is empty, as a "
                          "function of x, y, z. >= 0 (> 0 without V0).");
      }
      prm.leave_subsection();
    }



    void
    SlownessLaw::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Slowness law");
      {
        parse_constants(prm);
        initial_rate = parse_function(prm, "Initial slip rate");
        if (!dealii::Utilities::trim(prm.get("Initial state")).empty())
          initial_state = parse_function(prm, "Initial state");
      }
      prm.leave_subsection();
    }



    double
    SlownessLaw::friction(const Constants &c,
                          const std::vector<double> &,
                          const double V,
                          const double theta,
                          double      &dmu_dV,
                          double      &dmu_dtheta) const
    {
      const auto [mu0, A, B, L, Vinf, theta0, V0, V1] = c;
      (void)L;
      (void)V1;
      const double v = (V0 > 0) ? std::max(V, 0.) : std::max(V, minimum_rate);
      dmu_dV         = (V0 > 0 || V >= minimum_rate) ?
                         A * (1. / (V0 + v) - 1. / (Vinf + v)) :
                         0.;
      dmu_dtheta     = B / (theta0 + theta);
      return mu0 + A * std::log((V0 + v) / (Vinf + v)) +
             B * std::log1p(theta / theta0);
    }



    double
    SlownessLaw::evolve(const Constants           &c,
                        const std::vector<double> &variables,
                        const double               V,
                        const double               dt,
                        double                    &dtheta_dV) const
    {
      const double theta     = variables[0];
      const double L         = c[3];
      const double V1        = c[7];
      double       dtheta_dr = 0;
      const double result =
        StateEvolution::aging_step(theta, (V1 + V) / L, dt, dtheta_dr);
      dtheta_dV = dtheta_dr / L;
      return result;
    }



    void
    SlownessLaw::initialize_state(const Point<3> &x,
                                  const double    initial_friction,
                                  State          &state) const
    {
      const Constants   c  = start_state(x, state);
      const std::string at = LawUtilities::at_point(x);

      double theta = 0;
      if (initial_state)
        {
          theta = initial_state->value(x);
          require(std::isfinite(theta) && theta >= 0,
                  "Initial state",
                  theta,
                  x,
                  ">= 0 (s)");
        }
      else
        {
          const double V = initial_rate->value(x);
          require(std::isfinite(V) && (V > 0 || (V == 0 && c[6] > 0)),
                  "Initial slip rate",
                  V,
                  x,
                  (c[6] > 0) ? ">= 0 (m/s)" : "> 0 (m/s) without V0");
          AssertThrow(std::isfinite(initial_friction),
                      ExcMessage(
                        "<Fault/Slowness law/Initial state> is empty, so the "
                        "initial state is the one for which the law holds at "
                        "t = 0 with the fault's initial traction, but the "
                        "fault is not in compression" +
                        at + ". Give an <Initial state>."));
          // B ln(1 + theta/theta0) = mu_ini - mu(V, theta = 0).
          double       unused_V = 0, unused_theta = 0;
          const double rest =
            initial_friction - friction(c, {}, V, 0., unused_V, unused_theta);
          const double B      = c[2];
          const double theta0 = c[5];
          theta               = (B > 0) ? theta0 * std::expm1(rest / B) : 0.;
          AssertThrow(std::isfinite(theta) && theta >= 0 &&
                        (B > 0 || std::abs(rest) < 1e-12),
                      ExcMessage(
                        "<Fault/Slowness law/Initial state> is empty, but no "
                        "state theta >= 0 makes the law hold at t = 0" +
                        at +
                        ": the initial traction gives |tau|/|sigma| "
                        "= " +
                        std::to_string(initial_friction) +
                        ", below the law's value at theta = 0 or beyond its "
                        "range for V_ini = " +
                        std::to_string(V) +
                        " m/s. Check the traction, mu0, A, B and V_ini, or "
                        "give an <Initial state>."));
        }
      state.variables = {theta};
    }



    void
    SlownessLaw::state_rates(const Constants           &c,
                             const std::vector<double> &variables,
                             const double               V,
                             std::vector<double>       &rates) const
    {
      const double L = c[3], V1 = c[7];
      rates.assign(1, 1 - variables.at(0) * (V1 + std::max(V, 0.)) / L);
    }

    RUPTURE_REGISTER_FRICTION_LAW(
      SlownessLaw,
      "slowness law",
      "The Dieterich-Ruina slowness law with cut-offs (the review paper's "
      "eq. 4.5) and Perrin's regularised form (eq. 4.6, with V0, V1 > 0).")
  } // namespace Friction
} // namespace rupture
