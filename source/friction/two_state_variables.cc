#include <rupture/friction/law_utilities.h>
#include <rupture/friction/state_evolution.h>
#include <rupture/friction/two_state_variables.h>

#include <algorithm>
#include <cmath>

namespace rupture
{
  namespace Friction
  {
    namespace
    {
      /// ln(V/Vc) has no value at V = 0: it is taken at V >= this rate.
      constexpr double minimum_rate = 1e-30;

      using Family = RateStateFamily<7>;
      using Range  = Family::Range;

      const std::array<Family::ConstantEntry, 7> entries = {
        {{"Static friction coefficient", Range::finite, "a finite number"},
         {"Direct effect", Range::positive, "> 0"},
         {"Evolution effect 1", Range::non_negative, ">= 0"},
         {"Evolution effect 2", Range::non_negative, ">= 0"},
         {"Slip distance 1", Range::positive, "> 0"},
         {"Slip distance 2", Range::positive, "> 0"},
         {"Reference slip rate", Range::positive, "> 0"}}};
    } // namespace



    TwoStateVariables::TwoStateVariables()
      : RateStateFamily<7>("Two state variables", entries, 4, 2)
    {}



    void
    TwoStateVariables::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Two state variables");
      {
        prm.declare_entry("Formulation",
                          "logarithmic",
                          Patterns::Selection("regularized|logarithmic"),
                          "logarithmic: the review paper's eq. 4.4, mu = mu0 "
                          "+ th1 + th2 + A ln(V/Vc), taken at V = 1e-30 m/s "
                          "where V is smaller; regularized: mu = A asinh(V/"
                          "(2 Vc) exp((mu0 + th1 + th2)/A)), finite at "
                          "V = 0.");
        const std::array<const char *, 7> defaults = {
          "0.6", "0.008", "0.006", "0.006", "0.01", "0.1", "1e-6"};
        const std::array<const char *, 7> help = {
          "mu0, the friction coefficient at steady sliding at Vc, as a "
          "function of x, y, z (m; in 2-D z = 0).",
          "A, the direct effect, as a function of x, y, z. > 0.",
          "B1, the evolution effect of the first state variable, as a "
          "function of x, y, z. >= 0.",
          "B2, the evolution effect of the second state variable, as a "
          "function of x, y, z. >= 0.",
          "d1 (m), the slip over which the first state evolves, as a "
          "function of x, y, z. > 0.",
          "d2 (m), the slip over which the second state evolves, as a "
          "function of x, y, z. > 0.",
          "Vc (m/s), the reference slip rate, as a function of x, y, z. > 0."};
        for (unsigned int i = 0; i < 7; ++i)
          prm.declare_entry(entries[i].name,
                            defaults[i],
                            Patterns::Anything(),
                            help[i]);
        for (const std::string i : {"1", "2"})
          prm.declare_entry("Initial state " + i,
                            "",
                            Patterns::Anything(),
                            "th_" + i +
                              " at t = 0 as a function of x, y, z. Empty "
                              "(both): the state for which the law holds "
                              "at t = 0 with the fault's initial traction "
                              "and the <Initial slip rate>, shared in the "
                              "ratio B1 : B2.");
        prm.declare_entry("Initial slip rate",
                          "1e-12",
                          Patterns::Anything(),
                          "V_ini (m/s), the slip rate that defines the "
                          "initial state when the initial states are empty, "
                          "as a function of x, y, z. > 0.");
      }
      prm.leave_subsection();
    }



    void
    TwoStateVariables::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Two state variables");
      {
        logarithmic = (prm.get("Formulation") == "logarithmic");
        parse_constants(prm);
        initial_rate = parse_function(prm, "Initial slip rate");
        const bool
          first  = !dealii::Utilities::trim(prm.get("Initial state 1")).empty(),
          second = !dealii::Utilities::trim(prm.get("Initial state 2")).empty();
        AssertThrow(first == second,
                    ExcMessage("<Fault/Two state variables/Initial state 1> "
                               "and <Initial state 2> must both be given or "
                               "both be empty."));
        if (first)
          {
            initial_state[0] = parse_function(prm, "Initial state 1");
            initial_state[1] = parse_function(prm, "Initial state 2");
          }
      }
      prm.leave_subsection();
    }



    double
    TwoStateVariables::evolve_one(const Constants   &c,
                                  const unsigned int i,
                                  const double       th,
                                  const double       V,
                                  const double       dt,
                                  double            &dth_dV)
    {
      const double B  = c[2 + i];
      const double d  = c[4 + i];
      const double Vc = c[6];
      // th_new = th e^-x + th_ss (1 - e^-x), th_ss = -B ln(V/Vc), x = V dt/d;
      // (1 - e^-x) / V = (dt/d) w(x).
      const double v       = std::max(V, minimum_rate);
      const double x       = v * dt / d;
      const double e       = std::exp(-x);
      double       dweight = 0;
      const double weight  = StateEvolution::relaxation_weight(x, dweight);
      const double ss      = -B * std::log(v / Vc);
      dth_dV               = (dt / d) * ((ss - th) * e - B * weight);
      if (V <= 0)
        return th;
      return th * e - ss * std::expm1(-x);
    }



    double
    TwoStateVariables::friction(const Constants &c,
                                const std::vector<double> &,
                                const double V,
                                const double th_sum,
                                double      &dmu_dV,
                                double      &dmu_dth) const
    {
      const double mu0 = c[0], A = c[1], Vc = c[6];
      if (logarithmic)
        {
          const double v = std::max(V, minimum_rate);
          dmu_dV         = (V >= minimum_rate) ? A / v : 0.;
          dmu_dth        = 1;
          return mu0 + th_sum + A * std::log(v / Vc);
        }
      return StateEvolution::regularized_friction(
        A, Vc, V, mu0 + th_sum, dmu_dV, dmu_dth);
    }



    void
    TwoStateVariables::initialize_state(const Point<3> &x,
                                        const double    initial_friction,
                                        State          &state) const
    {
      const Constants   c  = start_state(x, state);
      const std::string at = LawUtilities::at_point(x);

      if (initial_state[0])
        {
          state.variables = {initial_state[0]->value(x),
                             initial_state[1]->value(x)};
          for (unsigned int i = 0; i < 2; ++i)
            require(std::isfinite(state.variables[i]),
                    "Initial state " + std::to_string(i + 1),
                    state.variables[i],
                    x,
                    "finite");
          return;
        }
      const double V = initial_rate->value(x);
      require(
        std::isfinite(V) && V > 0, "Initial slip rate", V, x, "> 0 (m/s)");
      AssertThrow(std::isfinite(initial_friction) && initial_friction > 0,
                  ExcMessage("<Fault/Two state variables/Initial state 1> and "
                             "<Initial state 2> are empty, so the initial "
                             "state is the one for which the law holds at "
                             "t = 0 with the fault's initial traction, but "
                             "the fault is not in compression or carries no "
                             "shear" +
                             at + ". Give the initial states."));
      const double mu0 = c[0], A = c[1], Vc = c[6];
      // th1 + th2 from mu(V_ini, th1 + th2) = initial friction.
      const double sum =
        logarithmic ?
          initial_friction - mu0 - A * std::log(V / Vc) :
          StateEvolution::regularized_state(A, Vc, V, initial_friction) - mu0;
      const double B1 = c[2], B2 = c[3];
      const double share = (B1 + B2 > 0) ? B1 / (B1 + B2) : 0.5;
      state.variables    = {share * sum, (1 - share) * sum};
    }



    double
    TwoStateVariables::evolve(const Constants           &c,
                              const std::vector<double> &variables,
                              const double               V,
                              const double               dt,
                              double                    &ds_dV) const
    {
      // mu depends on the states through their sum.
      double       d1 = 0, d2 = 0;
      const double sum = evolve_one(c, 0, variables.at(0), V, dt, d1) +
                         evolve_one(c, 1, variables.at(1), V, dt, d2);
      ds_dV = d1 + d2;
      return sum;
    }



    void
    TwoStateVariables::evolve_state(const Point<3> &,
                                    const Constants           &c,
                                    const std::vector<double> &old,
                                    const double               V,
                                    const double               dt,
                                    const double,
                                    std::vector<double> &updated) const
    {
      double unused = 0;
      updated       = {evolve_one(c, 0, old.at(0), V, dt, unused),
                       evolve_one(c, 1, old.at(1), V, dt, unused)};
    }



    void
    TwoStateVariables::state_rates(const Constants           &c,
                                   const std::vector<double> &variables,
                                   const double               V,
                                   std::vector<double>       &rates) const
    {
      rates.assign(2, 0.);
      if (V <= 0)
        return;
      for (unsigned int i = 0; i < 2; ++i)
        rates[i] =
          -V / c[4 + i] * (variables.at(i) + c[2 + i] * std::log(V / c[6]));
    }



    double
    TwoStateVariables::slip_scale(const Point<3> &x, const State &state) const
    {
      const Constants c = constants(x, state);
      return std::min(c[4], c[5]);
    }



    double
    TwoStateVariables::process_zone_width(const Point<3> &x,
                                          const State    &state,
                                          const double    pressure,
                                          const double    shear_modulus) const
    {
      const Constants c = constants(x, state);
      return std::min(
        LawUtilities::process_zone_at_rest(shear_modulus, c[4], c[2], pressure),
        LawUtilities::process_zone_at_rest(
          shear_modulus, c[5], c[3], pressure));
    }

    RUPTURE_REGISTER_FRICTION_LAW(
      TwoStateVariables,
      "two state variables",
      "Ruina's rate-and-state law with two state variables (the review "
      "paper's eq. 4.4), logarithmic or regularised.")
  } // namespace Friction
} // namespace rupture
