#include <rupture/base/utilities.h>
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

      const std::array<const char *, 5> names = {
        "Direct effect",
        "Evolution effect",
        "Characteristic slip distance",
        "Reference friction coefficient",
        "Reference slip rate"};
    } // namespace

    using LawUtilities::at_point;



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
        const std::string s = "Fault/Rate and state/";
        formulation         = (prm.get("Formulation") == "logarithmic") ?
                                Formulation::logarithmic :
                                Formulation::regularized;
        evolution = (prm.get("Evolution law") == "slip") ? EvolutionLaw::slip :
                                                           EvolutionLaw::aging;
        const auto parse = [&](const std::string &entry) {
          return Utilities::parse_function<3>(prm.get(entry),
                                              1,
                                              s + entry,
                                              "x,y,z");
        };
        for (unsigned int i = 0; i < 5; ++i)
          functions[i] = parse(names[i]);
        initial_rate = parse("Initial slip rate");
        if (!dealii::Utilities::trim(prm.get("Initial state")).empty())
          initial_state = parse("Initial state");
      }
      prm.leave_subsection();
    }



    void
    RateAndState::initialize_state(const Point<3> &x,
                                   const double    initial_friction,
                                   State          &state) const
    {
      state             = State();
      const Constants c = LawUtilities::constants(functions, x, state);
      const auto [a, b, L, f0, V0] = c;
      const std::string where      = at_point(x);
      const std::string s          = "<Fault/Rate and state/";
      const auto        require    = [&](const bool         ok,
                               const std::string &entry,
                               const double       value,
                               const std::string &allowed) {
        LawUtilities::require(ok, "Rate and state", entry, value, x, allowed);
      };
      require(std::isfinite(a) && a > 0, names[0], a, "> 0");
      require(std::isfinite(b) && b >= 0, names[1], b, ">= 0");
      require(std::isfinite(L) && L > 0, names[2], L, "> 0 (m)");
      require(std::isfinite(f0), names[3], f0, "a finite number");
      require(std::isfinite(V0) && V0 > 0, names[4], V0, "> 0 (m/s)");
      state.parameters = {a, b, L, f0, V0};

      double theta = 0;
      if (initial_state)
        {
          theta = initial_state->value(x);
          require(std::isfinite(theta) && theta > 0,
                  "Initial state",
                  theta,
                  "> 0 (s)");
        }
      else
        {
          const double V = initial_rate->value(x);
          require(std::isfinite(V) && V > 0,
                  "Initial slip rate",
                  V,
                  "> 0 (m/s)");
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
    RateAndState::evolve(const Constants &c,
                         const double     theta,
                         const double     V,
                         const double     dt,
                         double          &dtheta_dV) const
    {
      const double L = c[2];
      const double x = V * dt / L;
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
                           const double     V,
                           const double     theta,
                           double          &dmu_dV,
                           double          &dmu_dtheta) const
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



    double
    RateAndState::coefficient(const Point<3> &x,
                              const State    &old,
                              const double    slip_increment,
                              const double    dt,
                              double         &derivative) const
    {
      const Constants c = LawUtilities::constants(functions, x, old);
      AssertThrow(old.variables.size() == 1,
                  ExcMessage("The rate-and-state law was used at a point "
                             "whose state was not initialised" +
                             at_point(x) + "."));
      return LawUtilities::step_coefficient(
        slip_increment,
        dt,
        [&](const double V, double &dtheta_dV) {
          return evolve(c, old.variables[0], V, dt, dtheta_dV);
        },
        [&](const double V, const double theta, double &dV, double &dtheta) {
          return friction(c, V, theta, dV, dtheta);
        },
        derivative);
    }



    double
    RateAndState::coefficient_at_rate(const Point<3> &x,
                                      const State    &state,
                                      const double    V,
                                      double         &derivative) const
    {
      const Constants c      = LawUtilities::constants(functions, x, state);
      double          unused = 0;
      return friction(c, V, state.variables.at(0), derivative, unused);
    }



    double
    RateAndState::slip_scale(const Point<3> &x, const State &state) const
    {
      return LawUtilities::constants(functions, x, state)[2];
    }



    void
    RateAndState::state_rate(const Point<3>      &x,
                             const State         &state,
                             const double         V,
                             std::vector<double> &rates) const
    {
      const double L     = LawUtilities::constants(functions, x, state)[2];
      const double theta = state.variables.at(0);
      const double omega = V * theta / L;
      // aging: 1 - V theta / L; slip: -(V theta / L) ln(V theta / L), which
      // tends to 0 as V -> 0.
      rates.assign(1,
                   evolution == EvolutionLaw::aging ?
                     1 - omega :
                     (omega > 0 ? -omega * std::log(omega) : 0.));
    }



    double
    RateAndState::process_zone_width(const Point<3> &x,
                                     const State    &state,
                                     const double    pressure,
                                     const double    shear_modulus) const
    {
      // The constants' slip scale and strength drop (see the header).
      return LawUtilities::process_zone_of_constants(
        functions, x, state, pressure, shear_modulus, 2, 1);
    }



    double
    RateAndState::cohesion(const Point<3> &, const State &) const
    {
      return 0;
    }



    void
    RateAndState::update_state(const Point<3> &x,
                               const State    &old,
                               const double    slip_increment,
                               const double    dt,
                               const double    shear_traction,
                               State          &updated) const
    {
      Interface::update_state(
        x, old, slip_increment, dt, shear_traction, updated);
      const Constants c      = LawUtilities::constants(functions, x, old);
      const double    V      = LawUtilities::slip_rate(slip_increment, dt);
      double          unused = 0;
      updated.variables      = {evolve(c, old.variables[0], V, dt, unused)};
      AssertThrow(std::isfinite(updated.variables[0]) &&
                    updated.variables[0] > 0,
                  ExcMessage("The rate-and-state state variable theta left "
                             "the positive finite numbers" +
                             at_point(x) + " (theta was " +
                             std::to_string(old.variables[0]) +
                             " s, slip "
                             "rate " +
                             std::to_string(V) +
                             " m/s, L = " + std::to_string(c[2]) +
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
