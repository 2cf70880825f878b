#ifndef rupture_friction_cochard_madariaga_h
#define rupture_friction_cochard_madariaga_h

#include <rupture/friction/interface.h>

#include <deal.II/base/function_parser.h>

#include <array>

namespace rupture
{
  namespace Friction
  {
    /**
     * Cochard and Madariaga's rate weakening (the review paper's eq. 5.9):
     * the strength does not depend on the normal traction and falls with
     * the slip rate V,
     *
     *   strength = tau_r + sigma_0 V0 / (V0 + V),
     *
     * from tau_r + sigma_0 at rest to the residual strength tau_r at high
     * slip rates; sigma_0 is the largest traction drop and V0 the slip
     * rate that sets how fast it is reached (the paper has tau_r = 0). The
     * law has no state: V is the slip increment of the step over dt.
     *
     * The strength falls at most at d strength / dV = -sigma_0 / V0 (at
     * V = 0), so a node of impedance Z (Pa s/m: the traction change per
     * unit slip rate of the discrete problem) has a unique slip rate only
     * while sigma_0 / V0 < Z. check_uniqueness() throws where that fails.
     *
     * Parameters of a point {sigma_0, V0, tau_r}.
     */
    class CochardMadariaga : public Interface
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      using Interface::initialize_state;

      void
      initialize_state(const Point<3> &x,
                       const double    initial_friction,
                       State          &state) const override;

      /**
       * 0: the strength is not a coefficient times the pressure.
       */
      double
      coefficient(const Point<3> &x,
                  const State    &old,
                  const double    slip_increment,
                  const double    dt,
                  double         &derivative) const override;

      double
      cohesion(const Point<3> &x, const State &state) const override;

      double
      strength(const Point<3> &x,
               const State    &old,
               const double    slip_increment,
               const double    dt,
               const double    pressure,
               double         &derivative_increment,
               double         &derivative_pressure) const override;

      double
      strength_at_rate(const Point<3> &x,
                       const State    &state,
                       const double    V,
                       const double    pressure,
                       double         &derivative_rate,
                       double         &derivative_pressure) const override;

      void
      check_uniqueness(const Point<3> &x,
                       const State    &old,
                       const double    pressure,
                       const double    impedance) const override;

      bool
      depends_on_slip_rate() const override
      {
        return true;
      }

      /// {sigma_0, V0, tau_r}.
      using Constants = std::array<double, 3>;

      /// The strength at the slip rate @p V and its derivative in V.
      static double
      strength_of_rate(const Constants &c, const double V, double &derivative);

    private:
      std::array<std::unique_ptr<FunctionParser<3>>, 3> functions;
    };
  } // namespace Friction
} // namespace rupture

#endif
