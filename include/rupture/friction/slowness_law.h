#ifndef rupture_friction_slowness_law_h
#define rupture_friction_slowness_law_h

#include <rupture/friction/rate_state_family.h>

#include <deal.II/base/function_parser.h>

#include <array>
#include <cmath>

namespace rupture
{
  namespace Friction
  {
    /**
     * The Dieterich-Ruina slowness law with the cut-offs of the review
     * paper's eq. 4.5, and Perrin's regularised form (eq. 4.6), one law:
     *
     *   mu = mu0 + A ln((V0 + V) / (Vinf + V)) + B ln(1 + theta / theta0),
     *   d theta / dt = 1 - theta (V1 + V) / L.
     *
     * With V0 = V1 = 0 it is eq. 4.5, mu0 - A ln(1 + Vinf/V) + ..., which
     * has no value at V = 0 (there it is taken at V = 1e-30 m/s). With
     * V0 > 0 it is Perrin's law: regular at V = 0, with the finite static
     * friction mu0 + A ln(V0 / Vinf) + B ln(1 + theta/theta0), so a point
     * can truly stick; with V1 > 0 the state stays below L / V1 however
     * long the point sticks.
     *
     * At a constant slip rate in a step the state equation is linear and is
     * integrated exactly, for any (V1 + V) dt / L:
     *   theta_new = theta e^(-x) + dt (1 - e^(-x)) / x,  x = (V1 + V) dt/L.
     * The coefficient of a step is mu(V, theta_new(V)), and its derivative
     * with respect to the slip increment includes d theta_new / dV.
     *
     * The initial state is <Initial state> if given, else the one for which
     * the law holds at t = 0 with the fault's initial traction and the
     * <Initial slip rate>.
     *
     * State variables {theta}; parameters {mu0, A, B, L, Vinf, theta0, V0,
     * V1}.
     */
    class SlownessLaw : public RateStateFamily<8>
    {
    public:
      SlownessLaw();

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

      /// mu(V, theta) and its partial derivatives ({mu0, A, B, L, Vinf,
      /// theta0, V0, V1} in @p c).
      double
      friction(const Constants           &c,
               const std::vector<double> &variables,
               const double               V,
               const double               theta,
               double                    &dmu_dV,
               double                    &dmu_dtheta) const override;

      /// theta after a step @p dt at the constant slip rate @p V, and
      /// d theta_new / dV.
      double
      evolve(const Constants           &c,
             const std::vector<double> &variables,
             const double               V,
             const double               dt,
             double                    &dtheta_dV) const override;

      /// d theta / dt = 1 - theta (V1 + V) / L.
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
