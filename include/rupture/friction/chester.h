#ifndef rupture_friction_chester_h
#define rupture_friction_chester_h

#include <rupture/friction/rate_state_family.h>

#include <deal.II/base/function_parser.h>

#include <array>
#include <memory>

namespace rupture
{
  namespace Friction
  {
    /**
     * Chester's temperature-dependent rate-and-state friction (the review
     * paper's eq. 4.7 and 4.8) with Ruina's dimensionless state theta and
     * the fault temperature T (K) as state variables:
     *
     *   mu = mu0 + A [ln(V / V_c) + Q_A / R (1/T - 1/T*)] + B theta,
     *   d theta / dt = -(V / d_c) [theta + ln(V / V_c)
     *                              + Q_B / R (1/T - 1/T*)],
     *
     * with the gas constant R. At T = T* this is Ruina's slip law. The
     * regularised form (default) replaces mu0 + A ln(V/V_c) + ... by
     *   mu = A asinh(V / (2 V_c) exp(Psi / A)),
     *   Psi = mu0 + A Q_A / R (1/T - 1/T*) + B theta,
     * which equals the logarithmic one when V >> V_c exp(-Psi/A) and is 0
     * at V = 0, as in the SCEC benchmarks.
     *
     * The paper gives no equation for T. Here frictional heating tau V
     * warms a shear zone of heat capacity H = rho c w per unit fault area
     * (J/(m^2 K)), which loses heat to a reservoir at T_r with the
     * relaxation time t_c (the idealised heat flow):
     *   dT/dt = tau V / H - (T - T_r) / t_c.
     *
     * Within a step the slip rate V is constant. The state equation is
     * then linear in theta, integrated exactly:
     *   theta_new = theta_ss + (theta - theta_ss) e^(-V dt / d_c),
     * theta_ss = -ln(V / V_c) - Q_B / R (1/T - 1/T*), and the coefficient
     * of the step is mu(V, theta_new(V)) at the temperature at the start of
     * the step. After the step the temperature equation, linear in T with
     * the step's traction and slip rate, is integrated exactly too:
     *   T_new = T_inf + (T - T_inf) e^(-dt / t_c),  T_inf = T_r + tau V t_c /
     * H. The friction thus sees the temperature one step late, which is
     * accurate while a step warms the fault by much less than
     * R T^2 / Q_A, the warming that changes mu by A.
     *
     * State variables {theta, T}; parameters
     * {A, B, d_c, mu0, V_c, Q_A, Q_B, T*, T_r, H, t_c}.
     */
    class Chester : public RateStateFamily<11>
    {
    public:
      Chester();

      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      using Interface::initialize_state;

      void
      initialize_state(const Point<3> &x,
                       const double    initial_friction,
                       State          &state) const override;

      std::vector<std::string>
      state_names() const override
      {
        return {"theta", "temperature"};
      }

      std::vector<double>
      state_output(const State &state) const override
      {
        return state.variables;
      }

      /// The temperature follows the frictional heating.
      bool
      state_depends_on_traction() const override
      {
        return true;
      }

      /// The fault-only solver integrates theta; the temperature relaxes
      /// over t_c and is advanced exactly per step (relax()).
      bool
      has_state_rate() const override
      {
        return true;
      }

      /// The temperature.
      bool
      state_relaxes(const unsigned int v) const override
      {
        return v == 1;
      }

      /// The gas constant R (J/(mol K)).
      static constexpr double gas_constant = 8.314462618;

      /// Q / R (1/T - 1/T*), the temperature term of an enthalpy Q ({A, B,
      /// d_c, mu0, V_c, Q_A, Q_B, T*, T_r, H, t_c} in @p c).
      static double
      arrhenius(const Constants &c, const double Q, const double T);

      /// theta_ss(V, T) and its derivative in V.
      static double
      steady_state(const Constants &c,
                   const double     V,
                   const double     T,
                   double          &derivative);

      /// theta after a step @p dt at the constant slip rate @p V and
      /// temperature @p T, and d theta_new / dV.
      static double
      evolve_at(const Constants &c,
                const double     theta,
                const double     V,
                const double     T,
                const double     dt,
                double          &dtheta_dV);

      /// The temperature after a step @p dt with the frictional heating
      /// @p heating = tau V (W/m^2).
      static double
      heat(const Constants &c,
           const double     T,
           const double     heating,
           const double     dt);

      // The law's physics (RateStateFamily).
      unsigned int
      n_state_variables() const override
      {
        return 2;
      }

      /// theta.
      double
      friction_state(const std::vector<double> &variables) const override
      {
        return variables[0];
      }

      /// theta after a step at the temperature at its start.
      double
      evolve(const Constants           &c,
             const std::vector<double> &variables,
             const double               V,
             const double               dt,
             double                    &dtheta_dV) const override;

      /// mu(V, theta, T) (T the second state variable) and its partial
      /// derivatives in V and theta.
      double
      friction(const Constants           &c,
               const std::vector<double> &variables,
               const double               V,
               const double               theta,
               double                    &dmu_dV,
               double                    &dmu_dtheta) const override;

      /// The temperature warmed by the step's heating, and theta evolved at
      /// the step's mean temperature.
      void
      evolve_state(const Point<3>            &x,
                   const Constants           &c,
                   const std::vector<double> &old,
                   const double               V,
                   const double               dt,
                   const double               shear_traction,
                   std::vector<double>       &updated) const override;

      /// d theta / dt = (V / d_c)(theta_ss(V, T) - theta) (0 at V = 0);
      /// 0 for the temperature, which relax() advances.
      void
      state_rates(const Constants           &c,
                  const std::vector<double> &variables,
                  const double               V,
                  std::vector<double>       &rates) const override;

      /// The temperature after @p dt under the heating @p heating (heat()).
      void
      relax(const Constants     &c,
            std::vector<double> &variables,
            const double         heating,
            const double         dt) const override;

      /// dT/dt = heating / H - (T - T_r) / t_c.
      void
      relaxation_rates(const Constants           &c,
                       const std::vector<double> &variables,
                       const double               heating,
                       std::vector<double>       &rates) const override;

    private:
      bool                               regularized = true;
      std::unique_ptr<FunctionParser<3>> initial_state;
      std::unique_ptr<FunctionParser<3>> initial_rate;
      std::unique_ptr<FunctionParser<3>> initial_temperature;
    };
  } // namespace Friction
} // namespace rupture

#endif
