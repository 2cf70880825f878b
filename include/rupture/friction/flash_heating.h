#ifndef rupture_friction_flash_heating_h
#define rupture_friction_flash_heating_h

#include <rupture/friction/rate_state_family.h>

#include <deal.II/base/function_parser.h>

#include <array>
#include <cmath>

namespace rupture
{
  namespace Friction
  {
    /**
     * Rate-and-state friction with strong rate weakening by flash heating,
     * the law of SCEC TPV103/104 (a slip law whose steady state drops to
     * the weakened friction f_w above the weakening rate V_w):
     *
     *   mu = a asinh(V / (2 V0) exp(psi / a)),
     *   d psi / dt = -(V / L) (psi - psi_ss(V)),
     *   psi_ss = a ln(2 V0 / V sinh(f_ss / a)),
     *   f_ss = f_w + (f_LV - f_w) / (1 + (V / V_w)^8)^(1/8),
     *   f_LV = f0 - (b - a) ln(V / V0).
     *
     * At steady state mu = f_ss. Within a step the slip rate is constant
     * and the state equation, linear in psi, is integrated exactly:
     *   psi_new = psi_ss + (psi - psi_ss) e^(-V dt / L),
     * for any V dt / L; at V = 0 psi stays. The coefficient of a step is
     * mu(V, psi_new(V)), and its derivative includes d psi_new / dV.
     *
     * The initial state is <Initial state> (psi) if given, else the one for
     * which the law holds at t = 0 with the fault's initial traction and the
     * <Initial slip rate>.
     *
     * State variables {psi}; parameters {a, b, L, f0, V0, f_w, V_w}.
     */
    class FlashHeating : public RateStateFamily<7>
    {
    public:
      FlashHeating();

      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      using Interface::initialize_state;

      void
      initialize_state(const Point<3> &x,
                       const double    initial_friction,
                       State          &state) const override;

      bool
      has_state_rate() const override
      {
        return true;
      }

      std::vector<std::string>
      state_names() const override
      {
        return {"psi"};
      }

      std::vector<double>
      state_output(const State &state) const override
      {
        return {state.variables.at(0)};
      }

      /// The steady-state friction f_ss(V) and its derivative ({a, b, L, f0,
      /// V0, f_w, V_w} in @p c).
      static double
      steady_state_friction(const Constants &c,
                            const double     V,
                            double          &derivative);

      /// psi_ss(V) and its derivative.
      static double
      steady_state(const Constants &c, const double V, double &derivative);

      // The law's physics (RateStateFamily).
      /// psi.
      double
      friction_state(const std::vector<double> &variables) const override
      {
        return variables[0];
      }

      /// psi after a step @p dt at the constant slip rate @p V, and
      /// d psi_new / dV.
      double
      evolve(const Constants           &c,
             const std::vector<double> &variables,
             const double               V,
             const double               dt,
             double                    &dpsi_dV) const override;

      /// mu(V, psi) and its partial derivatives.
      double
      friction(const Constants           &c,
               const std::vector<double> &variables,
               const double               V,
               const double               psi,
               double                    &dmu_dV,
               double                    &dmu_dpsi) const override;

      /// d psi / dt = -(V / L) (psi - psi_ss(V)), 0 at V = 0.
      void
      state_rates(const Constants           &c,
                  const std::vector<double> &variables,
                  const double               V,
                  std::vector<double>       &rates) const override;

    private:
      std::unique_ptr<FunctionParser<3>> initial_state;
      std::unique_ptr<FunctionParser<3>> initial_rate;
    };
  } // namespace Friction
} // namespace rupture

#endif
