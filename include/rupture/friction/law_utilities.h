#ifndef rupture_friction_law_utilities_h
#define rupture_friction_law_utilities_h

#include <rupture/friction/interface.h>

#include <deal.II/base/function_parser.h>

#include <algorithm>
#include <array>
#include <memory>
#include <string>

namespace rupture
{
  namespace Friction
  {
    /**
     * What the friction laws share beyond the Interface: parameters that
     * are functions of position, evaluated once per point, their checks,
     * and the coefficient of a step for laws of the slip rate.
     */
    namespace LawUtilities
    {
      /**
       * " at the fault point (x)", for messages.
       */
      std::string
      at_point(const Point<3> &x);

      /**
       * Unless @p ok, throw "<Fault/section/entry> is value at the fault
       * point (x), but it must be allowed.".
       */
      void
      require(const bool         ok,
              const std::string &section,
              const std::string &entry,
              const double       value,
              const Point<3>    &x,
              const std::string &allowed);

      /**
       * The law's constants at @p x: the ones initialize_state() cached in
       * @p state.parameters, else its functions of position evaluated (a
       * parsed expression costs far more than the rest of a node's step).
       */
      template <std::size_t n>
      std::array<double, n>
      constants(const std::array<std::unique_ptr<FunctionParser<3>>, n> &f,
                const Point<3>                                          &x,
                const State                                             &state)
      {
        std::array<double, n> c;
        for (std::size_t i = 0; i < n; ++i)
          c[i] = (state.parameters.size() == n) ? state.parameters[i] :
                                                  f[i]->value(x);
        return c;
      }

      /**
       * The process-zone width of a front at rest (Palmer and Rice's
       * estimate as Day et al. (2005) use it): (9 pi / 32) @p shear_modulus
       * @p slip_scale / (@p drop @p pressure), with @p drop the strength
       * drop per unit pressure over @p slip_scale; infinite where nothing
       * weakens (drop or pressure <= 0).
       */
      double
      process_zone_at_rest(const double shear_modulus,
                           const double slip_scale,
                           const double drop,
                           const double pressure);

      /**
       * The slip rate of a step: the slip increment over dt (0 for
       * dt <= 0).
       */
      inline double
      slip_rate(const double slip_increment, const double dt)
      {
        return (dt > 0) ? std::max(slip_increment, 0.) / dt : 0.;
      }

      /**
       * The friction coefficient of a step of a law of the slip rate V and
       * a state s that evolves at the step's constant V: mu(V, s_new(V)),
       * and its derivative with respect to the slip increment,
       * (d mu/dV + d mu/ds d s_new/dV) / dt. @p evolve(V, ds_dV) returns
       * s_new; @p friction(V, s, dmu_dV, dmu_ds) returns mu.
       */
      template <class Evolve, class Friction>
      double
      step_coefficient(const double    slip_increment,
                       const double    dt,
                       const Evolve   &evolve,
                       const Friction &friction,
                       double         &derivative)
      {
        const double V     = slip_rate(slip_increment, dt);
        double       ds_dV = 0, dmu_dV = 0, dmu_ds = 0;
        const double s  = evolve(V, ds_dV);
        const double mu = friction(V, s, dmu_dV, dmu_ds);
        derivative      = (dt > 0) ? (dmu_dV + dmu_ds * ds_dV) / dt : 0.;
        return mu;
      }
    } // namespace LawUtilities
  }   // namespace Friction
} // namespace rupture

#endif
