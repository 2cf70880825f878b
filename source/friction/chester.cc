#include <rupture/friction/chester.h>
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
      /// theta_ss and the logarithmic form have no value at V = 0: they
      /// are taken at V >= this rate (m/s).
      constexpr double minimum_rate = 1e-30;

      using Family = RateStateFamily<11>;
      using Range  = Family::Range;

      const std::array<Family::ConstantEntry, 11> entries = {
        {{"Direct effect", Range::positive, "> 0"},
         {"Evolution effect", Range::non_negative, ">= 0"},
         {"Characteristic slip distance", Range::positive, "> 0"},
         {"Reference friction coefficient", Range::finite, "a finite number"},
         {"Reference slip rate", Range::positive, "> 0"},
         {"Direct activation enthalpy", Range::finite, "a finite number"},
         {"Evolution activation enthalpy", Range::finite, "a finite number"},
         {"Reference temperature", Range::positive, "> 0"},
         {"Reservoir temperature", Range::positive, "> 0"},
         {"Heat capacity per area", Range::positive, "> 0"},
         {"Heat relaxation time", Range::positive, "> 0"}}};
    } // namespace



    Chester::Chester()
      : RateStateFamily<11>("Chester", entries, 2, 1)
    {}



    void
    Chester::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Chester");
      {
        prm.declare_entry(
          "Formulation",
          "regularized",
          Patterns::Selection("regularized|logarithmic"),
          "regularized: mu = A asinh(V / (2 V_c) exp(Psi / A)), finite at "
          "V = 0; logarithmic: the review's eq. 4.7 as written, "
          "mu = Psi + A ln(V / V_c), taken at V >= 1e-30 m/s.");
        const std::array<const char *, 11> defaults = {"0.01",
                                                       "0.015",
                                                       "0.4",
                                                       "0.6",
                                                       "1e-6",
                                                       "1.3e5",
                                                       "1.3e5",
                                                       "573",
                                                       "573",
                                                       "2.7e4",
                                                       "1"};
        const std::array<const char *, 11> help     = {
              "A, the direct effect, as a function of x, y, z (m; in 2-D z = 0). "
                  "> 0.",
              "B, the evolution effect (the weight of the dimensionless state "
                  "theta), as a function of x, y, z. >= 0.",
              "d_c (m), the slip over which theta evolves, as a function of x, y, "
                  "z. > 0.",
              "mu0, the steady-state friction coefficient at V_c and T*, as a "
                  "function of x, y, z.",
              "V_c (m/s), the reference slip rate, as a function of x, y, z. > 0.",
              "Q_A (J/mol), the apparent activation enthalpy of the direct "
                  "effect, as a function of x, y, z.",
              "Q_B (J/mol), the apparent activation enthalpy of the evolution "
                  "effect, as a function of x, y, z.",
              "T* (K), the temperature at which the law is Ruina's, as a "
                  "function of x, y, z. > 0.",
              "T_r (K), the temperature the fault relaxes to, as a function of x, "
                  "y, z. > 0.",
              "H = rho c w (J/(m^2 K)), the heat capacity per unit fault area of "
                  "the shear zone that frictional heating warms (e.g. 2.7e6 J/(m^3 "
                  "K) times a width of 10 mm), as a function of x, y, z. > 0.",
              "t_c (s), the time over which the shear zone's temperature relaxes "
                  "to T_r (about w^2 / thermal diffusivity), as a function of x, y, "
                  "z. > 0."};
        for (unsigned int i = 0; i < 11; ++i)
          prm.declare_entry(entries[i].name,
                            defaults[i],
                            Patterns::Anything(),
                            help[i]);
        prm.declare_entry("Initial temperature",
                          "573",
                          Patterns::Anything(),
                          "T (K) at t = 0, as a function of x, y, z. > 0.");
        prm.declare_entry(
          "Initial state",
          "",
          Patterns::Anything(),
          "theta at t = 0 as a function of x, y, z. Empty: the state for "
          "which the law holds at t = 0 with the fault's initial traction, "
          "the <Initial slip rate> and the <Initial temperature>.");
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
    Chester::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Chester");
      {
        regularized = (prm.get("Formulation") == "regularized");
        parse_constants(prm);
        initial_temperature = parse_function(prm, "Initial temperature");
        initial_rate        = parse_function(prm, "Initial slip rate");
        if (!dealii::Utilities::trim(prm.get("Initial state")).empty())
          initial_state = parse_function(prm, "Initial state");
      }
      prm.leave_subsection();
    }



    double
    Chester::arrhenius(const Constants &c, const double Q, const double T)
    {
      return Q / gas_constant * (1. / T - 1. / c[7]);
    }



    double
    Chester::steady_state(const Constants &c,
                          const double     V,
                          const double     T,
                          double          &derivative)
    {
      const double v = std::max(V, minimum_rate);
      derivative     = (V >= minimum_rate) ? -1. / v : 0.;
      return -std::log(v / c[4]) - arrhenius(c, c[6], T);
    }



    double
    Chester::evolve_at(const Constants &c,
                       const double     theta,
                       const double     V,
                       const double     T,
                       const double     dt,
                       double          &dtheta_dV)
    {
      const double d_c = c[2];
      if (V <= 0)
        {
          // No slip, no evolution; the rate of change with V is the limit
          // V -> 0 at the smallest rate theta_ss allows.
          double       unused = 0;
          const double ss     = steady_state(c, minimum_rate, T, unused);
          dtheta_dV           = (ss - theta - 1.) * dt / d_c;
          return theta;
        }
      const double x   = V * dt / d_c;
      const double e   = std::exp(-x);
      const double w   = -std::expm1(-x); // 1 - e^-x
      double       dss = 0;
      const double ss  = steady_state(c, V, T, dss);
      dtheta_dV        = (ss - theta) * e * dt / d_c + w * dss;
      return theta + (ss - theta) * w;
    }



    double
    Chester::heat(const Constants &c,
                  const double     T,
                  const double     heating,
                  const double     dt)
    {
      const double T_r = c[8], H = c[9], t_c = c[10];
      // T_new = T + (T_inf - T)(1 - e^(-dt/t_c)), T_inf = T_r + q t_c / H.
      const double w = -std::expm1(-dt / t_c);
      return T + (T_r - T) * w + heating / H * t_c * w;
    }



    double
    Chester::evolve(const Constants           &c,
                    const std::vector<double> &variables,
                    const double               V,
                    const double               dt,
                    double                    &dtheta_dV) const
    {
      return evolve_at(c, variables[0], V, variables.at(1), dt, dtheta_dV);
    }



    double
    Chester::friction(const Constants           &c,
                      const std::vector<double> &variables,
                      const double               V,
                      const double               theta,
                      double                    &dmu_dV,
                      double                    &dmu_dtheta) const
    {
      const double T = variables.at(1);
      const double A = c[0], B = c[1], V_c = c[4];
      const double psi = c[3] + A * arrhenius(c, c[5], T) + B * theta;
      if (regularized)
        {
          double       dpsi = 0;
          const double mu =
            StateEvolution::regularized_friction(A, V_c, V, psi, dmu_dV, dpsi);
          dmu_dtheta = dpsi * B;
          return mu;
        }
      const double v = std::max(V, minimum_rate);
      dmu_dV         = (V >= minimum_rate) ? A / v : 0.;
      dmu_dtheta     = B;
      return psi + A * std::log(v / V_c);
    }



    void
    Chester::initialize_state(const Point<3> &x,
                              const double    initial_friction,
                              State          &state) const
    {
      const Constants c = start_state(x, state);

      const double T = initial_temperature->value(x);
      require(
        std::isfinite(T) && T > 0, "Initial temperature", T, x, "> 0 (K)");
      double theta = 0;
      if (initial_state)
        {
          theta = initial_state->value(x);
          require(std::isfinite(theta), "Initial state", theta, x, "finite");
        }
      else
        {
          const double V = initial_rate->value(x);
          require(
            std::isfinite(V) && V > 0, "Initial slip rate", V, x, "> 0 (m/s)");
          AssertThrow(
            std::isfinite(initial_friction) && initial_friction > 0 && c[1] > 0,
            ExcMessage("<Fault/Chester/Initial state> is empty, so the "
                       "initial state is the one for which the law holds at "
                       "t = 0 with the fault's initial traction, but the "
                       "fault is not in compression, carries no shear or has "
                       "no evolution effect (B = 0)" +
                       LawUtilities::at_point(x) +
                       ". Give an <Initial state>."));
          // Psi for which mu(V_ini, Psi) = mu_ini, then theta from Psi.
          const double psi = regularized ?
                               StateEvolution::regularized_state(
                                 c[0], c[4], V, initial_friction) :
                               initial_friction - c[0] * std::log(V / c[4]);
          theta            = (psi - c[3] - c[0] * arrhenius(c, c[5], T)) / c[1];
          require(std::isfinite(theta),
                  "Initial slip rate",
                  V,
                  x,
                  "a rate at which the initial friction is reached with a "
                  "finite state");
        }
      state.variables = {theta, T};
    }



    void
    Chester::evolve_state(const Point<3>            &x,
                          const Constants           &c,
                          const std::vector<double> &old,
                          const double               V,
                          const double               dt,
                          const double               shear_traction,
                          std::vector<double>       &updated) const
    {
      const double T      = old.at(1);
      double       unused = 0;
      const double T_new =
        (dt > 0) ? heat(c, T, std::abs(shear_traction) * V, dt) : T;
      // theta evolves at the step's mean temperature (second order in the
      // coupling, for the split nodes' time-centred update).
      const double theta =
        evolve_at(c, old[0], V, 0.5 * (T + T_new), dt, unused);
      AssertThrow(std::isfinite(theta) && std::isfinite(T_new) && T_new > 0,
                  ExcMessage("The state of Chester's law left the finite "
                             "numbers" +
                             LawUtilities::at_point(x) +
                             " (theta = " + std::to_string(theta) +
                             ", T = " + std::to_string(T_new) +
                             " K). Lower the heating (raise <Fault/Chester/"
                             "Heat capacity per area>) or the time step."));
      updated = {theta, T_new};
    }

    void
    Chester::state_rates(const Constants           &c,
                         const std::vector<double> &variables,
                         const double               V,
                         std::vector<double>       &rates) const
    {
      double unused = 0;
      rates.assign(2, 0.);
      if (V > 0)
        rates[0] = V / c[2] *
                   (steady_state(c, V, variables.at(1), unused) - variables[0]);
    }



    void
    Chester::relax(const Constants     &c,
                   std::vector<double> &variables,
                   const double         heating,
                   const double         dt) const
    {
      const double T = heat(c, variables.at(1), heating, dt);
      AssertThrow(std::isfinite(T) && T > 0,
                  ExcMessage("The temperature of Chester's law left the "
                             "positive numbers (" +
                             std::to_string(T) +
                             " K). Lower the heating (raise <Fault/Chester/"
                             "Heat capacity per area>)."));
      variables[1] = T;
    }



    void
    Chester::relaxation_rates(const Constants           &c,
                              const std::vector<double> &variables,
                              const double               heating,
                              std::vector<double>       &rates) const
    {
      const double T_r = c[8], H = c[9], t_c = c[10];
      rates.assign(2, 0.);
      rates[1] = heating / H - (variables.at(1) - T_r) / t_c;
    }



    RUPTURE_REGISTER_FRICTION_LAW(
      Chester,
      "chester",
      "Chester's temperature-dependent rate-and-state friction (the "
      "review's eq. 4.7-4.8, slip law) with the fault temperature as a "
      "state variable warmed by frictional heating.")
  } // namespace Friction
} // namespace rupture
