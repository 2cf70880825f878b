#ifndef rupture_friction_two_state_variables_h
#define rupture_friction_two_state_variables_h

#include <rupture/friction/rate_state_family.h>

#include <deal.II/base/function_parser.h>

#include <array>
#include <cmath>

namespace rupture
{
  namespace Friction
  {
    /**
     * Ruina's rate-and-state law with two state variables (the review
     * paper's eq. 4.4, with a weakening constant B_i and a length d_i for
     * each variable, as the paper's text says; its equation prints one B):
     *
     *   mu = mu0 + th1 + th2 + A ln(V / Vc)               (logarithmic),
     *   mu = A asinh(V / (2 Vc) exp((mu0 + th1 + th2)/A))  (regularised),
     *   d th_i / dt = -(V / d_i) (th_i + B_i ln(V / Vc)),  i = 1, 2.
     *
     * Each th_i is a slip law in additive form: at steady state
     * th_i = -B_i ln(V/Vc) and mu = mu0 + (A - B1 - B2) ln(V/Vc). Within a
     * step the slip rate is constant and each equation, linear in th_i, is
     * integrated exactly: th_i,new = th_i,ss + (th_i - th_i,ss) e^(-V dt/d_i),
     * for any V dt / d_i; at V = 0 the states stay. The logarithmic form has
     * no value at V = 0 and is taken at V = 1e-30 m/s there.
     *
     * The initial state is <Initial state 1> and <Initial state 2> if given,
     * else the state for which the law holds at t = 0 with the fault's
     * initial traction and the <Initial slip rate>, shared between th_1 and
     * th_2 in the ratio B1 : B2, as at steady state.
     *
     * State variables {th1, th2}; parameters {mu0, A, B1, B2, d1, d2, Vc}.
     */
    class TwoStateVariables : public RateStateFamily<7>
    {
    public:
      TwoStateVariables();

      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      using Interface::initialize_state;

      void
      initialize_state(const Point<3> &x,
                       const double    initial_friction,
                       State          &state) const override;

      /// The shorter of d1 and d2.
      double
      slip_scale(const Point<3> &x, const State &state) const override;

      /// The shorter of the two states' zones.
      double
      process_zone_width(const Point<3> &x,
                         const State    &state,
                         const double    pressure,
                         const double    shear_modulus) const override;

      bool
      has_state_rate() const override
      {
        return true;
      }

      std::vector<std::string>
      state_names() const override
      {
        return {"theta_1", "theta_2"};
      }

      std::vector<double>
      state_output(const State &state) const override
      {
        return {state.variables.at(0), state.variables.at(1)};
      }

      // The law's physics (RateStateFamily).
      unsigned int
      n_state_variables() const override
      {
        return 2;
      }

      /// th1 + th2, through which the states enter the friction.
      double
      friction_state(const std::vector<double> &variables) const override
      {
        return variables[0] + variables[1];
      }

      /// th1 + th2 after a step @p dt at the constant slip rate @p V, and
      /// its derivative with respect to V.
      double
      evolve(const Constants           &c,
             const std::vector<double> &variables,
             const double               V,
             const double               dt,
             double                    &ds_dV) const override;

      /// mu(V, th1 + th2) and its partial derivatives ({mu0, A, B1, B2,
      /// d1, d2, Vc} in @p c).
      double
      friction(const Constants           &c,
               const std::vector<double> &variables,
               const double               V,
               const double               th_sum,
               double                    &dmu_dV,
               double                    &dmu_dth) const override;

      /// Both states after the step.
      void
      evolve_state(const Point<3>            &x,
                   const Constants           &c,
                   const std::vector<double> &old,
                   const double               V,
                   const double               dt,
                   const double               shear_traction,
                   std::vector<double>       &updated) const override;

      /// d th_i / dt = -(V / d_i) (th_i + B_i ln(V / Vc)), 0 at V = 0.
      void
      state_rates(const Constants           &c,
                  const std::vector<double> &variables,
                  const double               V,
                  std::vector<double>       &rates) const override;

    private:
      /// th_i after a step @p dt at the constant slip rate @p V, and
      /// d th_i,new / dV.
      static double
      evolve_one(const Constants   &c,
                 const unsigned int i,
                 const double       th,
                 const double       V,
                 const double       dt,
                 double            &dth_dV);

      bool                                              logarithmic = false;
      std::array<std::unique_ptr<FunctionParser<3>>, 2> initial_state;
      std::unique_ptr<FunctionParser<3>>                initial_rate;
    };
  } // namespace Friction
} // namespace rupture

#endif
