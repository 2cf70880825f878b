#ifndef rupture_friction_rate_and_state_h
#define rupture_friction_rate_and_state_h

#include <rupture/friction/rate_state_family.h>

#include <deal.II/base/function_parser.h>

#include <array>
#include <cmath>

namespace rupture
{
  namespace Friction
  {
    /**
     * Dieterich-Ruina rate-and-state friction with one state variable theta
     * (s), in the form of the SCEC benchmarks, with a (direct effect),
     * b (evolution effect), L (characteristic slip distance), the reference
     * friction coefficient f0 at the reference slip rate V0:
     *
     * - logarithmic form (the review paper's eq. 4.3):
     *     mu = f0 + a ln(V / V0) + b ln(V0 theta / L),
     *   which has no value at V = 0 (there it is taken at V = 1e-30 m/s);
     * - regularised form (the SCEC benchmarks TPV101-104), finite and 0 at
     *   V = 0 and equal to the logarithmic one when V >> V0 exp(-Psi/a):
     *     mu = a asinh(V / (2 V0) exp(Psi / a)),  Psi = f0 + b ln(V0 theta/L).
     *
     * Two evolution laws for theta:
     * - aging (slowness) law: d theta/dt = 1 - V theta / L (the review's
     *   eq. 4.5 and 4.6 carry the same law);
     * - slip law: d theta/dt = -(V theta / L) ln(V theta / L). With the
     *   additive state vartheta = b ln(V0 theta / L) this is exactly the
     *   review's eq. 4.3: d vartheta/dt = -(V/L)(vartheta + b ln(V/V0)).
     *
     * Within a step of length dt the slip rate V = (slip increment)/dt is
     * constant, and both laws are integrated exactly over the step: with
     * x = V dt / L,
     *   aging: theta_new = theta e^(-x) + dt (1 - e^(-x)) / x,
     *   slip:  ln theta_new = ln theta + (e^(-x) - 1) ln(V theta / L).
     * This holds for any V dt / L (the forward-Euler update is unstable for
     * dt > 2 L / V), for V -> 0 (aging: theta grows by dt; slip: theta
     * stays) and for very large V (theta -> L / V). The friction
     * coefficient of a step is mu(V, theta_new(V)), fully implicit, and its
     * derivative with respect to the slip increment includes
     * d theta_new / dV: the consistent tangent of the contact return
     * mapping.
     *
     * The initial state is <Initial state> if given, else the one for which
     * the law holds at t = 0: mu(V_ini, theta) = |tau_0| / |sigma_0| with
     * the fault's initial shear and normal traction and <Initial slip rate>
     * V_ini.
     *
     * The state variables of a point are {theta}; its parameters
     * {a, b, L, f0, V0}.
     */
    class RateAndState : public RateStateFamily<5>
    {
    public:
      enum class Formulation
      {
        regularized,
        logarithmic
      };
      enum class EvolutionLaw
      {
        aging,
        slip
      };

      RateAndState();

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

      bool
      state_interpolates_in_logarithm(const unsigned int i) const override
      {
        return i == 0;
      }

      std::vector<std::string>
      state_names() const override
      {
        return {"log10_theta"};
      }

      std::vector<double>
      state_output(const State &state) const override
      {
        return {std::log10(state.variables.at(0))};
      }

      // The law's physics (RateStateFamily).
      /// theta.
      double
      friction_state(const std::vector<double> &variables) const override
      {
        return variables[0];
      }

      /// theta after the step (see the class documentation).
      double
      evolve(const Constants           &c,
             const std::vector<double> &variables,
             const double               V,
             const double               dt,
             double                    &dtheta_dV) const override;

      /// mu(V, theta).
      double
      friction(const Constants           &c,
               const std::vector<double> &variables,
               const double               V,
               const double               theta,
               double                    &dmu_dV,
               double                    &dmu_dtheta) const override;

      /// theta after the step, which must stay finite and positive.
      void
      evolve_state(const Point<3>            &x,
                   const Constants           &c,
                   const std::vector<double> &old,
                   const double               V,
                   const double               dt,
                   const double               shear_traction,
                   std::vector<double>       &updated) const override;

      /// d theta / dt of the aging or the slip law.
      void
      state_rates(const Constants           &c,
                  const std::vector<double> &variables,
                  const double               V,
                  std::vector<double>       &rates) const override;

    private:
      Formulation                        formulation = Formulation::regularized;
      EvolutionLaw                       evolution   = EvolutionLaw::aging;
      std::unique_ptr<FunctionParser<3>> initial_state;
      std::unique_ptr<FunctionParser<3>> initial_rate;
    };
  } // namespace Friction
} // namespace rupture

#endif
