#include <rupture/friction/law_utilities.h>
#include <rupture/friction/rate_and_state.h>
#include <rupture/friction/state_evolution.h>

#include <algorithm>
#include <cmath>

namespace rupture
{
  namespace Friction
  {
    namespace
    {
      /// The logarithmic form is evaluated at V >= this rate (m/s): it has
      /// no value at V = 0.
      constexpr double minimum_log_rate = 1e-30;

      using Family = RateStateFamily<5>;
      using Range  = Family::Range;

      const std::array<Family::ConstantEntry, 5> entries = {
        {{"Direct effect", Range::positive, "> 0"},
         {"Evolution effect", Range::non_negative, ">= 0"},
         {"Characteristic slip distance", Range::positive, "> 0 (m)"},
         {"Reference friction coefficient", Range::finite, "a finite number"},
         {"Reference slip rate", Range::positive, "> 0 (m/s)"}}};
    } // namespace

    using LawUtilities::at_point;



    RateAndState::RateAndState()
      : RateStateFamily<5>("Rate and state", entries, 2, 1)
    {}



    void
    RateAndState::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Rate and state");
      {
        prm.declare_entry(
          "Formulation",
          "regularized",
          Patterns::Selection("regularized|logarithmic"),
          "regularized: mu = a asinh(V/(2 V0) exp((f0 + b ln(V0 theta/L))/a)), "
          "finite at V = 0 (the SCEC benchmarks); logarithmic: mu = f0 + "
          "a ln(V/V0) + b ln(V0 theta/L) (the review paper's eq. 4.3), taken "
          "at V = 1e-30 m/s where V is smaller.");
        prm.declare_entry(
          "Evolution law",
          "aging",
          Patterns::Selection("aging|slip"),
          "aging (slowness) law: d theta/dt = 1 - V theta/L; slip law: d "
          "theta/dt = -(V theta/L) ln(V theta/L) (eq. 4.3 of the review "
          "paper in the additive state b ln(V0 theta/L)).");
        prm.declare_entry("Direct effect",
                          "0.008",
                          Patterns::Anything(),
                          "a, the direct-effect parameter, as a function of "
                          "x, y, z (m; in 2-D z = 0). > 0.");
        prm.declare_entry("Evolution effect",
                          "0.012",
                          Patterns::Anything(),
                          "b, the evolution-effect parameter, as a function "
                          "of x, y, z. >= 0; b > a is velocity weakening.");
        prm.declare_entry("Characteristic slip distance",
                          "0.02",
                          Patterns::Anything(),
                          "L (m), the slip over which the state evolves, as "
                          "a function of x, y, z. > 0.");
        prm.declare_entry("Reference friction coefficient",
                          "0.6",
                          Patterns::Anything(),
                          "f0, the steady-state friction coefficient at the "
                          "reference slip rate, as a function of x, y, z.");
        prm.declare_entry("Reference slip rate",
                          "1e-6",
                          Patterns::Anything(),
                          "V0 (m/s), the reference slip rate, as a function "
                          "of x, y, z. > 0.");
        prm.declare_entry(
          "Initial state",
          "",
          Patterns::Anything(),
          "theta (s) at t = 0 as a function of x, y, z (> 0). Empty: the "
          "state for which the law holds at t = 0, mu(V_ini, theta) = "
          "|tau_0|/|sigma_0| with the fault's initial traction and the "
          "<Initial slip rate>.");
        prm.declare_entry("Initial slip rate",
                          "1e-12",
                          Patterns::Anything(),
                          "V_ini (m/s), the slip rate that defines the "
                          "initial state when <Initial state> is empty, as a "
                          "function of x, y, z. > 0.");
      }
      prm.leave_subsection();
    }



    void
    RateAndState::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Rate and state");
      {
        formulation = (prm.get("Formulation") == "logarithmic") ?
                        Formulation::logarithmic :
                        Formulation::regularized;
        evolution = (prm.get("Evolution law") == "slip") ? EvolutionLaw::slip :
                                                           EvolutionLaw::aging;
        parse_constants(prm);
        initial_rate = parse_function(prm, "Initial slip rate");
        if (!dealii::Utilities::trim(prm.get("Initial state")).empty())
          initial_state = parse_function(prm, "Initial state");
      }
      prm.leave_subsection();
    }



    void
    RateAndState::initialize_state(const Point<3> &x,
                                   const double    initial_friction,
                                   State          &state) const
    {
      const Constants c            = start_state(x, state);
      const auto [a, b, L, f0, V0] = c;
      const std::string where      = at_point(x);
      const std::string s          = "<Fault/Rate and state/";

      double theta = 0;
      if (initial_state)
        {
          theta = initial_state->value(x);
          require(std::isfinite(theta) && theta > 0,
                  "Initial state",
                  theta,
                  x,
                  "> 0 (s)");
        }
      else
        {
          const double V = initial_rate->value(x);
          require(
            std::isfinite(V) && V > 0, "Initial slip rate", V, x, "> 0 (m/s)");
          AssertThrow(std::isfinite(initial_friction) && initial_friction >= 0,
                      ExcMessage(
                        s +
                        "Initial state> is empty, so the initial state "
                        "is the one for which the law holds at t = 0 "
                        "with the fault's initial traction, but the "
                        "fault is not in compression" +
                        where +
                        " (or the law is used without a fault). Give "
                        "<Fault/Initial traction> with a compressive normal "
                        "component there, or an <Initial state>."));
          // Solve mu(V, theta) = initial_friction for ln(V0 theta / L).
          double log_state = 0;
          if (formulation == Formulation::logarithmic)
            log_state = (initial_friction - f0 - a * std::log(V / V0)) / b;
          else
            {
              // a asinh(V/(2 V0) e^(Psi/a)) = mu, solved for Psi.
              AssertThrow(initial_friction > 0,
                          ExcMessage(s +
                                     "Initial state> is empty, and the "
                                     "fault's initial shear traction "
                                     "is zero" +
                                     where +
                                     ": the regularised law then needs "
                                     "V_ini = 0. Give an <Initial state>."));
              const double psi =
                StateEvolution::regularized_state(a, V0, V, initial_friction);
              log_state = (psi - f0) / b;
            }
          AssertThrow(b > 0 || std::abs(log_state) < 1e300,
                      ExcMessage(s + "Evolution effect> is 0" + where +
                                 ": the initial state cannot follow from "
                                 "the initial traction. Give an <Initial "
                                 "state>."));
          theta = L / V0 * std::exp(log_state);
          AssertThrow(std::isfinite(theta) && theta > 0,
                      ExcMessage(
                        s +
                        "Initial state> is empty, and the state for "
                        "which the law holds at t = 0 with the initial "
                        "traction (|tau|/|sigma| = " +
                        std::to_string(initial_friction) +
                        ") and V_ini = " + std::to_string(V) + " m/s" + where +
                        " is theta = L/V0 exp(" + std::to_string(log_state) +
                        ") s, which is not a finite positive number. Check "
                        "<Fault/Initial traction>, " +
                        s + "Reference friction coefficient> (f0), " + s +
                        "Direct effect> (a), " + s + "Evolution effect> (b), " +
                        s + "Characteristic slip distance> (L) and " + s +
                        "Initial slip rate> (V_ini)."));
        }
      state.variables = {theta};
    }



    double
    RateAndState::evolve(const Constants           &c,
                         const std::vector<double> &variables,
                         const double               V,
                         const double               dt,
                         double                    &dtheta_dV) const
    {
      const double theta = variables[0];
      const double L     = c[2];
      const double x     = V * dt / L;
      if (evolution == EvolutionLaw::aging)
        {
          // theta_new = theta e^-x + dt (1 - e^-x)/x, x = (V / L) dt.
          double       dtheta_dr = 0;
          const double result =
            StateEvolution::aging_step(theta, V / L, dt, dtheta_dr);
          dtheta_dV = dtheta_dr / L;
          return result;
        }
      // Slip law: ln theta_new = ln theta + (e^-x - 1) ln(V theta / L).
      if (V <= 0)
        {
          // The rate of change is -inf at V = 0+ times 0: taken at the
          // smallest rate the logarithm allows.
          const double v0 = minimum_log_rate;
          const double l  = std::log(v0 * theta / L);
          dtheta_dV       = theta * (-(dt / L) * std::exp(-v0 * dt / L) * l +
                               std::expm1(-v0 * dt / L) / v0);
          return theta;
        }
      const double l         = std::log(V * theta / L);
      const double m         = std::expm1(-x);
      const double new_theta = theta * std::exp(m * l);
      dtheta_dV = new_theta * (-(dt / L) * std::exp(-x) * l + m / V);
      return new_theta;
    }



    double
    RateAndState::friction(const Constants &c,
                           const std::vector<double> &,
                           const double V,
                           const double theta,
                           double      &dmu_dV,
                           double      &dmu_dtheta) const
    {
      const auto [a, b, L, f0, V0] = c;
      const double log_state       = std::log(V0 * theta / L);
      if (formulation == Formulation::logarithmic)
        {
          const double v = std::max(V, minimum_log_rate);
          dmu_dV         = (V >= minimum_log_rate) ? a / v : 0.;
          dmu_dtheta     = b / theta;
          return f0 + a * std::log(v / V0) + b * log_state;
        }
      // mu = a asinh(V / (2 V0) e^(Psi/a)), Psi = f0 + b ln(V0 theta / L).
      double       dmu_dpsi = 0;
      const double mu       = StateEvolution::regularized_friction(
        a, V0, V, f0 + b * log_state, dmu_dV, dmu_dpsi);
      dmu_dtheta = dmu_dpsi * b / theta;
      return mu;
    }



    void
    RateAndState::state_rates(const Constants           &c,
                              const std::vector<double> &variables,
                              const double               V,
                              std::vector<double>       &rates) const
    {
      const double L     = c[2];
      const double theta = variables.at(0);
      const double omega = V * theta / L;
      // aging: 1 - V theta / L; slip: -(V theta / L) ln(V theta / L), which
      // tends to 0 as V -> 0.
      rates.assign(1,
                   evolution == EvolutionLaw::aging ?
                     1 - omega :
                     (omega > 0 ? -omega * std::log(omega) : 0.));
    }



    void
    RateAndState::evolve_state(const Point<3>            &x,
                               const Constants           &c,
                               const std::vector<double> &old,
                               const double               V,
                               const double               dt,
                               const double               shear_traction,
                               std::vector<double>       &updated) const
    {
      // The family's update of the one variable, then its check.
      RateStateFamily<5>::evolve_state(
        x, c, old, V, dt, shear_traction, updated);
      AssertThrow(std::isfinite(updated[0]) && updated[0] > 0,
                  ExcMessage(
                    "The rate-and-state state variable theta left "
                    "the positive finite numbers" +
                    at_point(x) + " (theta was " + std::to_string(old[0]) +
                    " s, slip "
                    "rate " +
                    std::to_string(V) + " m/s, L = " + std::to_string(c[2]) +
                    " m, <Fault/Rate and state/Characteristic slip "
                    "distance>)."));
    }

    RUPTURE_REGISTER_FRICTION_LAW(
      RateAndState,
      "rate and state",
      "Dieterich-Ruina rate-and-state friction with one state variable: "
      "aging or slip law, regularised or logarithmic form (the review "
      "paper's eq. 4.3 and 4.5; the SCEC benchmarks TPV101-104).")
  } // namespace Friction
} // namespace rupture
