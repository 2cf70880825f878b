#include <rupture/base/utilities.h>
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

      const std::array<const char *, 8> names = {"Static friction coefficient",
                                                 "Direct effect",
                                                 "Evolution effect",
                                                 "Characteristic slip distance",
                                                 "High-velocity cut-off",
                                                 "State cut-off",
                                                 "Low-velocity cut-off",
                                                 "Healing cut-off"};
    } // namespace



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
          prm.declare_entry(names[i],
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
        const auto parse = [&](const std::string &entry) {
          return Utilities::parse_function<3>(prm.get(entry),
                                              1,
                                              "Fault/Slowness law/" + entry,
                                              "x,y,z");
        };
        for (unsigned int i = 0; i < 8; ++i)
          functions[i] = parse(names[i]);
        initial_rate = parse("Initial slip rate");
        if (!dealii::Utilities::trim(prm.get("Initial state")).empty())
          initial_state = parse("Initial state");
      }
      prm.leave_subsection();
    }



    double
    SlownessLaw::friction(const Constants &c,
                          const double     V,
                          const double     theta,
                          double          &dmu_dV,
                          double          &dmu_dtheta)
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
    SlownessLaw::evolve(const Constants &c,
                        const double     theta,
                        const double     V,
                        const double     dt,
                        double          &dtheta_dV)
    {
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
      state                     = State();
      const Constants   c       = LawUtilities::constants(functions, x, state);
      const std::string at      = LawUtilities::at_point(x);
      const auto        require = [&](const bool         ok,
                               const std::string &entry,
                               const double       value,
                               const std::string &allowed) {
        LawUtilities::require(ok, "Slowness law", entry, value, x, allowed);
      };
      require(std::isfinite(c[0]), names[0], c[0], "a finite number");
      for (const unsigned int i : {1u, 2u, 6u, 7u})
        require(std::isfinite(c[i]) && c[i] >= 0, names[i], c[i], ">= 0");
      for (const unsigned int i : {3u, 4u, 5u})
        require(std::isfinite(c[i]) && c[i] > 0, names[i], c[i], "> 0");
      state.parameters.assign(c.begin(), c.end());

      double theta = 0;
      if (initial_state)
        {
          theta = initial_state->value(x);
          require(std::isfinite(theta) && theta >= 0,
                  "Initial state",
                  theta,
                  ">= 0 (s)");
        }
      else
        {
          const double V = initial_rate->value(x);
          require(std::isfinite(V) && (V > 0 || (V == 0 && c[6] > 0)),
                  "Initial slip rate",
                  V,
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
            initial_friction - friction(c, V, 0., unused_V, unused_theta);
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



    double
    SlownessLaw::coefficient(const Point<3> &x,
                             const State    &old,
                             const double    slip_increment,
                             const double    dt,
                             double         &derivative) const
    {
      const Constants c = LawUtilities::constants(functions, x, old);
      return LawUtilities::step_coefficient(
        slip_increment,
        dt,
        [&](const double V, double &ds_dV) {
          return evolve(c, old.variables.at(0), V, dt, ds_dV);
        },
        [&](const double V, const double s, double &dmu_dV, double &dmu_ds) {
          return friction(c, V, s, dmu_dV, dmu_ds);
        },
        derivative);
    }



    double
    SlownessLaw::coefficient_at_rate(const Point<3> &x,
                                     const State    &state,
                                     const double    V,
                                     double         &derivative) const
    {
      const Constants c      = LawUtilities::constants(functions, x, state);
      double          unused = 0;
      return friction(c, V, state.variables.at(0), derivative, unused);
    }



    double
    SlownessLaw::slip_scale(const Point<3> &x, const State &state) const
    {
      return LawUtilities::constants(functions, x, state)[3];
    }



    double
    SlownessLaw::process_zone_width(const Point<3> &x,
                                    const State    &state,
                                    const double    pressure,
                                    const double    shear_modulus) const
    {
      // The constants' slip scale and strength drop (see the header).
      return LawUtilities::process_zone_of_constants(
        functions, x, state, pressure, shear_modulus, 3, 2);
    }



    double
    SlownessLaw::cohesion(const Point<3> &, const State &) const
    {
      return 0;
    }



    void
    SlownessLaw::update_state(const Point<3> &x,
                              const State    &old,
                              const double    slip_increment,
                              const double    dt,
                              const double    shear_traction,
                              State          &updated) const
    {
      Interface::update_state(
        x, old, slip_increment, dt, shear_traction, updated);
      const Constants c      = LawUtilities::constants(functions, x, old);
      double          unused = 0;
      updated.variables      = {evolve(c,
                                  old.variables.at(0),
                                  LawUtilities::slip_rate(slip_increment, dt),
                                  dt,
                                  unused)};
    }

    RUPTURE_REGISTER_FRICTION_LAW(
      SlownessLaw,
      "slowness law",
      "The Dieterich-Ruina slowness law with cut-offs (the review paper's "
      "eq. 4.5) and Perrin's regularised form (eq. 4.6, with V0, V1 > 0).")
  } // namespace Friction
} // namespace rupture
