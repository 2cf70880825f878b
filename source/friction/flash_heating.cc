#include <rupture/friction/flash_heating.h>
#include <rupture/friction/law_utilities.h>
#include <rupture/friction/state_evolution.h>

#include <algorithm>
#include <cmath>

namespace rupture
{
  namespace Friction
  {
    namespace
    {
      /// psi_ss has no value at V = 0: it is taken at V >= this rate (m/s).
      constexpr double minimum_rate = 1e-30;

      using Family = RateStateFamily<7>;
      using Range  = Family::Range;

      const std::array<Family::ConstantEntry, 7> entries = {
        {{"Direct effect", Range::positive, "> 0"},
         {"Evolution effect", Range::non_negative, ">= 0"},
         {"Characteristic slip distance", Range::positive, "> 0"},
         {"Reference friction coefficient", Range::finite, "a finite number"},
         {"Reference slip rate", Range::positive, "> 0"},
         {"Weakened friction coefficient", Range::positive, "> 0"},
         {"Weakening slip rate", Range::positive, "> 0"}}};
    } // namespace



    FlashHeating::FlashHeating()
      : RateStateFamily<7>("Flash heating", entries, 2, 1)
    {}



    void
    FlashHeating::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Flash heating");
      {
        const std::array<const char *, 7> defaults = {
          "0.01", "0.014", "0.4", "0.6", "1e-6", "0.2", "0.1"};
        const std::array<const char *, 7> help = {
          "a, the direct effect, as a function of x, y, z (m; in 2-D "
          "z = 0). > 0.",
          "b, the evolution effect, as a function of x, y, z. >= 0.",
          "L (m), the slip over which the state evolves, as a function of "
          "x, y, z. > 0.",
          "f0, the steady-state friction coefficient at V0, as a function of "
          "x, y, z.",
          "V0 (m/s), the reference slip rate, as a function of x, y, z. > 0.",
          "f_w, the fully weakened friction coefficient, as a function of x, "
          "y, z. > 0.",
          "V_w (m/s), the slip rate above which flash heating weakens the "
          "fault, as a function of x, y, z. > 0."};
        for (unsigned int i = 0; i < 7; ++i)
          prm.declare_entry(entries[i].name,
                            defaults[i],
                            Patterns::Anything(),
                            help[i]);
        prm.declare_entry(
          "Initial state",
          "",
          Patterns::Anything(),
          "psi at t = 0 as a function of x, y, z. Empty: the state for which "
          "the law holds at t = 0 with the fault's initial traction and the "
          "<Initial slip rate>.");
        prm.declare_entry("Initial slip rate",
                          "1e-16",
                          Patterns::Anything(),
                          "V_ini (m/s), the slip rate that defines the "
                          "initial state when <Initial state> is empty, as a "
                          "function of x, y, z. > 0.");
      }
      prm.leave_subsection();
    }



    void
    FlashHeating::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Flash heating");
      {
        parse_constants(prm);
        initial_rate = parse_function(prm, "Initial slip rate");
        if (!dealii::Utilities::trim(prm.get("Initial state")).empty())
          initial_state = parse_function(prm, "Initial state");
      }
      prm.leave_subsection();
    }



    double
    FlashHeating::steady_state_friction(const Constants &c,
                                        const double     V,
                                        double          &derivative)
    {
      const auto [a, b, L, f0, V0, fw, Vw] = c;
      (void)L;
      const double v    = std::max(V, minimum_rate);
      const double f_lv = f0 - (b - a) * std::log(v / V0);
      const double r    = v / Vw;
      // g = (1 + r^8)^(-1/8), g' = -r^7 / Vw (1 + r^8)^(-9/8).
      double g, dg;
      if (r > 1e30)
        {
          g  = 1 / r;
          dg = -1 / (r * v);
        }
      else
        {
          const double r8 = std::pow(r, 8);
          g               = std::pow(1 + r8, -0.125);
          dg              = -std::pow(r, 7) / Vw * std::pow(1 + r8, -1.125);
        }
      derivative =
        (V >= minimum_rate) ? -(b - a) / v * g + (f_lv - fw) * dg : 0.;
      return fw + (f_lv - fw) * g;
    }



    double
    FlashHeating::steady_state(const Constants &c,
                               const double     V,
                               double          &derivative)
    {
      const double a  = c[0];
      const double V0 = c[4];
      const double v  = std::max(V, minimum_rate);
      double       df = 0;
      // f_ss > 0 for f_w > 0: psi_ss = a (ln(2 V0 / V) + ln sinh(f_ss/a)).
      const double f = std::max(steady_state_friction(c, v, df), 1e-300);
      const double y = f / a;
      // d ln sinh(y) / dy = coth(y).
      const double coth = (y > 20) ? 1. : 1. / std::tanh(y);
      derivative        = (V >= minimum_rate) ? a * (-1 / v) + coth * df : 0.;
      return a * (std::log(2 * V0 / v) + StateEvolution::log_sinh(y));
    }



    double
    FlashHeating::evolve(const Constants           &c,
                         const std::vector<double> &variables,
                         const double               V,
                         const double               dt,
                         double                    &dpsi_dV) const
    {
      const double psi = variables[0];
      if (V <= 0)
        {
          // The state does not evolve without slip; its rate of change
          // with V is taken at the smallest rate psi_ss allows.
          double       dss = 0;
          const double ss  = steady_state(c, minimum_rate, dss);
          dpsi_dV          = (ss - psi) * dt / c[2];
          return psi;
        }
      const double L   = c[2];
      const double x   = V * dt / L;
      const double e   = std::exp(-x);
      double       dss = 0;
      const double ss  = steady_state(c, V, dss);
      // psi_new = psi e^-x + psi_ss (1 - e^-x).
      dpsi_dV = (ss - psi) * e * dt / L - std::expm1(-x) * dss;
      return psi * e - ss * std::expm1(-x);
    }



    double
    FlashHeating::friction(const Constants &c,
                           const std::vector<double> &,
                           const double V,
                           const double psi,
                           double      &dmu_dV,
                           double      &dmu_dpsi) const
    {
      return StateEvolution::regularized_friction(
        c[0], c[4], V, psi, dmu_dV, dmu_dpsi);
    }



    void
    FlashHeating::initialize_state(const Point<3> &x,
                                   const double    initial_friction,
                                   State          &state) const
    {
      const Constants   c  = start_state(x, state);
      const std::string at = LawUtilities::at_point(x);

      double psi = 0;
      if (initial_state)
        {
          psi = initial_state->value(x);
          require(std::isfinite(psi), "Initial state", psi, x, "finite");
        }
      else
        {
          const double V = initial_rate->value(x);
          require(
            std::isfinite(V) && V > 0, "Initial slip rate", V, x, "> 0 (m/s)");
          AssertThrow(std::isfinite(initial_friction) && initial_friction > 0,
                      ExcMessage(
                        "<Fault/Flash heating/Initial state> is empty, so "
                        "the initial state is the one for which the law "
                        "holds at t = 0 with the fault's initial traction, "
                        "but the fault is not in compression or carries no "
                        "shear" +
                        at + ". Give an <Initial state>."));
          // a asinh(V / (2 V0) e^(psi/a)) = mu_ini.
          psi =
            StateEvolution::regularized_state(c[0], c[4], V, initial_friction);
        }
      state.variables = {psi};
    }



    void
    FlashHeating::state_rates(const Constants           &c,
                              const std::vector<double> &variables,
                              const double               V,
                              std::vector<double>       &rates) const
    {
      // No slip, no evolution (psi_ss has no value at V = 0).
      if (V <= 0)
        {
          rates.assign(1, 0.);
          return;
        }
      double       unused = 0;
      const double ss     = steady_state(c, V, unused);
      rates.assign(1, -V / c[2] * (variables.at(0) - ss));
    }

    RUPTURE_REGISTER_FRICTION_LAW(
      FlashHeating,
      "flash heating",
      "Rate-and-state slip law with strong rate weakening by flash heating "
      "(SCEC TPV103/104), regularised form.")
  } // namespace Friction
} // namespace rupture
