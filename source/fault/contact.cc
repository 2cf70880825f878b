#include <rupture/fault/contact.h>

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>

namespace rupture
{
  namespace Fault
  {
    template <int dim>
    ContactResponse<dim>
    return_map(const Tensor<1, dim>      &delta,
               const Tensor<1, dim>      &n,
               const Tensor<1, dim>      &t0,
               const double               p_n,
               const double               p_t,
               const Tensor<1, dim>      &old_plastic_slip,
               const Friction::State     &old_state,
               const Friction::Interface &law,
               const Point<3>            &x,
               const double               dt,
               const double               radiation_damping,
               const Tensor<1, dim>      *old_shear_traction)
    {
      ContactResponse<dim> r;
      const Tensor<2, dim> nn = outer_product(n, n);
      const Tensor<2, dim> projector =
        Tensor<2, dim>(unit_symmetric_tensor<dim>()) - nn;

      const double         normal_traction = t0 * n + p_n * (delta * n);
      const Tensor<1, dim> delta_t         = projector * delta;
      const Tensor<1, dim> t0_t            = projector * t0;

      double derivative = 0;
      if (normal_traction > 0)
        {
          // Open: no traction. The plastic slip follows the relative
          // displacement, so that the spring is unstretched on closing.
          r.status         = ContactStatus::open;
          r.traction       = 0;
          r.tangent        = 0;
          r.plastic_slip   = delta_t + t0_t / p_t;
          r.slip_increment = (r.plastic_slip - old_plastic_slip).norm();
          r.friction =
            law.coefficient(x, old_state, r.slip_increment, dt, derivative);
          return r;
        }

      const double         pressure = -normal_traction;
      const Tensor<1, dim> trial =
        t0_t + p_t * (delta_t - projector * old_plastic_slip);
      const double trial_norm = trial.norm();
      r.trial_traction        = trial;

      // Centred in time (a law of the slip rate, a step from a known
      // traction T_n): the mean of the tractions at the step's start and
      // end along the slip, (T_n e + tau) / 2, meets the strength at the
      // step's mean slip rate l / dt with the state evolved over half the
      // step, so that tau = 2 (S_mid(l) + eta l / dt) - T_n e: the
      // implicit midpoint rule, second order in time. Otherwise the
      // strength of the state at the step's end meets the end's traction
      // (first order).
      const bool centred =
        old_shear_traction && trial_norm > 0 && law.depends_on_slip_rate();
      const double old_along =
        centred ? (*old_shear_traction) * trial / trial_norm : 0.;

      // The strength S(l) after a slip increment l, with its derivatives
      // dS/dl and mu = dS/d pressure (the friction coefficient for laws of
      // one; twice the mid-step coefficient when centred).
      // The quasi-dynamic radiation damping adds eta l / dt.
      const auto strength = [&](const double l, double &dS, double &mu) {
        if (centred)
          {
            const double S_mid =
              law.strength(x, old_state, 0.5 * l, 0.5 * dt, pressure, dS, mu);
            dS += 2 * radiation_damping / dt;
            mu *= 2;
            return 2 * (S_mid + radiation_damping * l / dt) - old_along;
          }
        const double S = law.strength(x, old_state, l, dt, pressure, dS, mu);
        if (radiation_damping == 0)
          return S;
        dS += radiation_damping / dt;
        return S + radiation_damping * l / dt;
      };
      double       mu = 0, dS = 0;
      const double S = strength(0., dS, mu);
      // Weakening at the start of the slip steeper than the penalty: g
      // below grows with the slip there, so the root lies beyond the
      // weakening and the traction drops to the residual strength at once.
      const bool snaps = (-dS >= p_t);
      // A point exactly at its strength (as after a converged slip step)
      // sticks: unloading must start from the stiff branch.
      if (trial_norm <= S * (1 + 1e-10))
        {
          r.status       = ContactStatus::stick;
          r.traction     = normal_traction * n + trial;
          r.tangent      = p_n * nn + p_t * projector;
          r.plastic_slip = old_plastic_slip;
          r.friction     = centred ? 0.5 * mu : mu;
          return r;
        }
      // The penalty is the node's impedance to slip: per unit slip rate
      // p_t dt (the law may know that its weakening can exceed it); half
      // of it against the mid-step strength when centred.
      law.check_uniqueness(x,
                           old_state,
                           pressure,
                           (centred ? 0.5 : 1.) * p_t * dt + radiation_damping);

      // Slip: find the slip increment l in (0, |T_trial|/p_t] with
      // g(l) = |T_trial| - p_t l - S(l) = 0, by Newton's method
      // safeguarded with bisection (g(0) > 0 >= g(upper)).
      const auto g = [&](const double l, double &dg) {
        double       dSl = 0, m = 0;
        const double Sl = strength(l, dSl, m);
        dg              = -p_t - dSl;
        return trial_norm - p_t * l - Sl;
      };
      double lower = 0, upper = trial_norm / p_t, l = 0;
      // (Centred, the traction may reverse within the step: the root then
      // lies beyond the increment that frees the spring.)
      for (unsigned int it = 0; centred && it < 200; ++it)
        {
          double dg;
          if (g(upper, dg) <= 0)
            break;
          lower = upper;
          upper *= 2;
        }
      l = lower;
      for (unsigned int it = 0; it < 100; ++it)
        {
          double       dg;
          const double value = g(l, dg);
          if (std::abs(value) <= 1e-14 * trial_norm)
            break;
          if (value > 0)
            lower = l;
          else
            upper = l;
          double next = (dg < 0) ? l - value / dg : 0.5 * (lower + upper);
          if (!(next > lower && next < upper))
            next = 0.5 * (lower + upper);
          l = next;
          if (upper - lower <= 1e-15 * trial_norm / p_t)
            break;
        }

      strength(l, dS, mu);
      const double         tau = trial_norm - p_t * l;
      const Tensor<1, dim> e   = trial / trial_norm;
      const double         k   = -dS;
      derivative               = (pressure > 0) ? dS / pressure : 0.;

      r.status              = ContactStatus::slip;
      r.slip_increment      = l;
      r.friction            = centred ? 0.5 * mu : mu;
      r.friction_derivative = derivative;
      r.traction            = normal_traction * n + tau * e;
      r.plastic_slip        = old_plastic_slip + l * e;

      // Consistent tangent:
      //   D = p_n n n + tau p_t / |T_trial| (I - e e - n n)
      //       + e (x) (-k e - mu p_n n) / (1 - k / p_t),
      // with k = -dS/dl the weakening slope and mu = dS/d|T_n|.
      const double denominator = 1 - k / p_t;
      r.unstable_softening     = (denominator <= 0) || snaps;
      const Tensor<2, dim> ee  = outer_product(e, e);
      r.tangent = p_n * nn + (tau * p_t / trial_norm) * (projector - ee);
      if (denominator > 0)
        r.tangent += outer_product(e, -k * e - mu * p_n * n) / denominator;
      else
        r.tangent += outer_product(e, -mu * p_n * n);
      return r;
    }



    template <int dim>
    ContactResponse<dim>
    forced_slip_response(const Tensor<1, dim> &delta,
                         const Tensor<1, dim> &n,
                         const Tensor<1, dim> &t0,
                         const double          p_n,
                         const double          p_t,
                         const Tensor<1, dim> &old_plastic_slip,
                         const Tensor<1, dim> &imposed_slip)
    {
      ContactResponse<dim> r;
      const Tensor<2, dim> nn = outer_product(n, n);
      const Tensor<2, dim> projector =
        Tensor<2, dim>(unit_symmetric_tensor<dim>()) - nn;
      const double normal_traction = t0 * n + p_n * (delta * n);
      r.plastic_slip               = imposed_slip;
      r.slip_increment             = (imposed_slip - old_plastic_slip).norm();
      r.status =
        (r.slip_increment > 0) ? ContactStatus::slip : ContactStatus::stick;
      if (normal_traction > 0)
        {
          r.status   = ContactStatus::open;
          r.traction = 0;
          r.tangent  = 0;
          return r;
        }
      r.traction = normal_traction * n + projector * t0 +
                   p_t * (projector * delta - imposed_slip);
      r.tangent = p_n * nn + p_t * projector;
      return r;
    }



    template ContactResponse<2>
    forced_slip_response(const Tensor<1, 2> &,
                         const Tensor<1, 2> &,
                         const Tensor<1, 2> &,
                         const double,
                         const double,
                         const Tensor<1, 2> &,
                         const Tensor<1, 2> &);
    template ContactResponse<3>
    forced_slip_response(const Tensor<1, 3> &,
                         const Tensor<1, 3> &,
                         const Tensor<1, 3> &,
                         const double,
                         const double,
                         const Tensor<1, 3> &,
                         const Tensor<1, 3> &);
    template ContactResponse<2>
    return_map(const Tensor<1, 2> &,
               const Tensor<1, 2> &,
               const Tensor<1, 2> &,
               const double,
               const double,
               const Tensor<1, 2> &,
               const Friction::State &,
               const Friction::Interface &,
               const Point<3> &,
               const double,
               const double,
               const Tensor<1, 2> *);
    template ContactResponse<3>
    return_map(const Tensor<1, 3> &,
               const Tensor<1, 3> &,
               const Tensor<1, 3> &,
               const double,
               const double,
               const Tensor<1, 3> &,
               const Friction::State &,
               const Friction::Interface &,
               const Point<3> &,
               const double,
               const double,
               const Tensor<1, 3> *);
  } // namespace Fault
} // namespace rupture
