#ifndef rupture_friction_state_evolution_h
#define rupture_friction_state_evolution_h

#include <algorithm>
#include <cmath>

namespace rupture
{
  namespace Friction
  {
    /**
     * Exact integration of the linear relaxation d s/dt = r (s_inf - s)
     * over a step dt at a constant rate r >= 0, shared by the
     * rate-and-state laws. With x = r dt the step gives
     *   s_new = s e^(-x) + s_inf (1 - e^(-x)),
     * and for the aging (slowness) law d theta/dt = 1 - r theta, whose
     * s_inf = 1 / r is infinite at r = 0,
     *   theta_new = theta e^(-x) + dt w(x),  w(x) = (1 - e^(-x)) / x.
     * Stable and exact for any x; w(0) = 1 (theta grows by dt).
     */
    namespace StateEvolution
    {
      /**
       * w(x) = (1 - e^-x) / x and its derivative w'(x), accurate for
       * x -> 0.
       */
      inline double
      relaxation_weight(const double x, double &derivative)
      {
        if (x < 1e-4)
          {
            derivative = -0.5 + x / 3. - x * x / 8.;
            return 1. - x / 2. + x * x / 6.;
          }
        const double e = std::exp(-x);
        derivative     = (e * (1. + x) - 1.) / (x * x);
        return -std::expm1(-x) / x;
      }

      /**
       * The aging step theta e^(-x) + dt w(x) with x = r dt, and its
       * derivative with respect to r.
       */
      inline double
      aging_step(const double theta,
                 const double r,
                 const double dt,
                 double      &dtheta_dr)
      {
        const double x       = r * dt;
        double       dweight = 0;
        const double weight  = relaxation_weight(x, dweight);
        const double e       = std::exp(-x);
        dtheta_dr            = (-theta * e + dt * dweight) * dt;
        return theta * e + dt * weight;
      }

      /**
       * ln(sinh(y)) for y > 0, without overflow for large y.
       */
      inline double
      log_sinh(const double y)
      {
        return (y > 20) ? y - std::log(2.) + std::log1p(-std::exp(-2 * y)) :
                          std::log(std::sinh(y));
      }

      /**
       * The regularised rate-and-state friction of the SCEC benchmarks,
       *   mu = a asinh(V / (2 V0) exp(psi / a)),
       * and its partial derivatives, for V >= 0 without overflow (at V = 0:
       * mu = 0 and d mu / dV = a exp(psi / a) / (2 V0), capped at e^700).
       */
      inline double
      regularized_friction(const double a,
                           const double V0,
                           const double V,
                           const double psi,
                           double      &dmu_dV,
                           double      &dmu_dpsi)
      {
        const double psi_over_a = psi / a;
        if (V <= 0)
          {
            dmu_dV =
              a * std::exp(std::min(psi_over_a - std::log(2 * V0), 700.));
            dmu_dpsi = 0;
            return 0;
          }
        const double log_z = std::log(V / (2 * V0)) + psi_over_a;
        if (log_z > 20)
          {
            // asinh(z) = ln(2z) + 1/(4 z^2) + ...
            const double inverse_z2 = std::exp(-2 * log_z);
            dmu_dV                  = a / V * (1 - 0.5 * inverse_z2);
            dmu_dpsi                = 1 - 0.5 * inverse_z2;
            return a * (std::log(2.) + log_z + 0.25 * inverse_z2);
          }
        const double z    = std::exp(log_z);
        const double root = std::sqrt(1 + z * z);
        // d asinh(z) = dz / root; dz/dV = z / V, dz/dpsi = z / a.
        dmu_dV =
          a * std::exp(std::min(psi_over_a - std::log(2 * V0), 700.)) / root;
        dmu_dpsi = z / root;
        return a * std::asinh(z);
      }

      /**
       * The inverse of regularized_friction() in psi: the psi for which
       * a asinh(V / (2 V0) exp(psi / a)) = @p mu at V > 0, mu > 0, i.e.
       * psi = a (ln(2 V0 / V) + ln sinh(mu / a)).
       */
      inline double
      regularized_state(const double a,
                        const double V0,
                        const double V,
                        const double mu)
      {
        return a * (std::log(2 * V0 / V) + log_sinh(mu / a));
      }
    } // namespace StateEvolution
  }   // namespace Friction
} // namespace rupture

#endif
