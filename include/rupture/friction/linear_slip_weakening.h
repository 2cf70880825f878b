#ifndef rupture_friction_linear_slip_weakening_h
#define rupture_friction_linear_slip_weakening_h

#include <rupture/friction/interface.h>

#include <deal.II/base/function_parser.h>

namespace rupture
{
  namespace Friction
  {
    /**
     * Linear slip weakening (the GeoFEM paper's eq. 2 and 6): the friction
     * coefficient falls from mu_0 to mu_d as the slip path length s grows
     * to L_d, and stays at mu_d beyond:
     *   mu(s) = mu_0 - (mu_0 - mu_d) s / L_d  for s < L_d,  mu_d otherwise.
     * mu_0, mu_d, L_d and the cohesion are functions of position.
     *
     * Forced nucleation (the paper's weak patch "where a quick reduction of
     * the friction coefficient is enforced at the beginning of dynamic
     * analysis"): inside the forced-weakening region mu also falls linearly
     * in time from mu_0 at the start of the dynamic phase to mu_d after the
     * forced-weakening time, and the smaller of the two applies.
     */
    class LinearSlipWeakening : public Interface
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

      double
      coefficient(const Point<3> &x,
                  const State    &old,
                  const double    slip_increment,
                  const double    dt,
                  double         &derivative) const override;

      double
      cohesion(const Point<3> &x, const State &state) const override;

      double
      process_zone_width(const Point<3> &x,
                         const State    &state,
                         const double    pressure,
                         const double    shear_modulus) const override;

      bool
      has_process_zone_width() const override
      {
        return true;
      }

      bool
      can_weaken(const Point<3> &x, const State &state) const override;

      void
      set_time(const double time) override;

      void
      start_dynamic_phase(const double time) override;

      void
      enable_weakening(const bool enable) override;

    private:
      /// mu_0, mu_d, L_d, cohesion and the forced-region flag at @p x:
      /// from the state's cached parameters once initialize_state() has
      /// stored them there, else evaluated.
      std::array<double, 5>
      point_parameters(const Point<3> &x, const State &state) const;

      std::unique_ptr<FunctionParser<3>> static_coefficient;
      std::unique_ptr<FunctionParser<3>> dynamic_coefficient;
      std::unique_ptr<FunctionParser<3>> weakening_distance;
      std::unique_ptr<FunctionParser<3>> cohesion_function;
      std::unique_ptr<FunctionParser<3>> forced_region;
      double                             forced_time;

      /// The time at the end of the step being solved, the start of the
      /// dynamic phase (for forced nucleation) and whether weakening is on.
      double current_time      = 0;
      double dynamic_start     = 0;
      bool   weakening_enabled = true;
    };
  } // namespace Friction
} // namespace rupture

#endif
