#include <rupture/fault/anisotropic_contact.h>

#include <deal.II/base/symmetric_tensor.h>

#include <array>
#include <cmath>

namespace rupture
{
  namespace Fault
  {
    namespace
    {
      /// The principal directions e_1 (and e_2 = n x e_1 in 3-D) of the
      /// ellipse in the plane of normal @p n.
      template <int dim>
      std::array<Tensor<1, dim>, dim - 1>
      principal_directions(const FrictionEllipse<dim> &ellipse,
                           const Tensor<1, dim>       &n)
      {
        std::array<Tensor<1, dim>, dim - 1> e;
        Tensor<1, dim> first = ellipse.direction - (ellipse.direction * n) * n;
        if (!(first.norm() > 1e-12 * ellipse.direction.norm()))
          {
            // Any direction in the plane (the caller checks the input).
            first    = 0;
            first[0] = -n[1];
            first[1] = n[0];
            if (first.norm() == 0)
              first[dim - 1] = 1;
            first -= (first * n) * n;
          }
        e[0] = first / first.norm();
        if constexpr (dim == 3)
          e[1] = cross_product_3d(n, e[0]);
        return e;
      }
    } // namespace



    template <int dim>
    Tensor<1, dim>
    inverse_metric(const FrictionEllipse<dim> &ellipse,
                   const Tensor<1, dim>       &n,
                   const Tensor<1, dim>       &v)
    {
      const auto     e    = principal_directions(ellipse, n);
      const double   a[2] = {ellipse.a1, ellipse.a2};
      Tensor<1, dim> result;
      for (unsigned int i = 0; i + 1 < dim; ++i)
        result += (v * e[i]) / a[i] * e[i];
      return result;
    }



    template <int dim>
    ContactResponse<dim>
    anisotropic_return_map(const Tensor<1, dim>       &delta,
                           const Tensor<1, dim>       &n,
                           const Tensor<1, dim>       &t0,
                           const double                p_n,
                           const double                p_t,
                           const Tensor<1, dim>       &old_plastic_slip,
                           const Friction::State      &old_state,
                           const Friction::Interface  &law,
                           const Point<3>             &x,
                           const double                dt,
                           const FrictionEllipse<dim> &ellipse)
    {
      constexpr unsigned int nt = dim - 1;
      ContactResponse<dim>   r;
      const Tensor<2, dim>   nn = outer_product(n, n);
      const Tensor<2, dim>   projector =
        Tensor<2, dim>(unit_symmetric_tensor<dim>()) - nn;
      const auto   e    = principal_directions(ellipse, n);
      const double a[2] = {ellipse.a1, ellipse.a2};
      // b_i = 1 / a_i^2: A^-2 in the principal basis.
      double b[2];
      for (unsigned int i = 0; i < nt; ++i)
        b[i] = 1. / (a[i] * a[i]);
      // |A v| of a tangential vector v.
      const auto dual_norm = [&](const Tensor<1, dim> &v) {
        double sum = 0;
        for (unsigned int i = 0; i < nt; ++i)
          sum += std::pow(a[i] * (v * e[i]), 2);
        return std::sqrt(sum);
      };

      const double         normal_traction = t0 * n + p_n * (delta * n);
      const Tensor<1, dim> delta_t         = projector * delta;
      const Tensor<1, dim> t0_t            = projector * t0;
      double               derivative      = 0;
      if (normal_traction > 0)
        {
          r.status         = ContactStatus::open;
          r.traction       = 0;
          r.tangent        = 0;
          r.plastic_slip   = delta_t + t0_t / p_t;
          r.slip_increment = dual_norm(r.plastic_slip - old_plastic_slip);
          r.friction =
            law.coefficient(x, old_state, r.slip_increment, dt, derivative);
          return r;
        }

      const double         pressure = -normal_traction;
      const Tensor<1, dim> trial =
        t0_t + p_t * (delta_t - projector * old_plastic_slip);
      r.trial_traction = trial;
      // The trial traction's principal components.
      double trial_i[2] = {0, 0};
      for (unsigned int i = 0; i < nt; ++i)
        trial_i[i] = trial * e[i];

      // tau(c) = (I + c A^-2)^-1 trial, N(c) = |A^-1 tau(c)| and the slip
      // increment l(c) = |A delta u_p| = c N(c) / p_t.
      const auto state_of = [&](const double c, double tau[2], double &N) {
        double sum = 0;
        for (unsigned int i = 0; i < nt; ++i)
          {
            tau[i] = trial_i[i] / (1 + c * b[i]);
            sum += b[i] * tau[i] * tau[i];
          }
        N = std::sqrt(sum);
      };
      double       tau[2], N0;
      double       dS = 0, mu = 0;
      const double S0 = law.strength(x, old_state, 0., dt, pressure, dS, mu);
      // Weakening at the start of the slip steeper than the penalty: the
      // traction drops to the residual strength at once (snap-back).
      const bool snaps = (-dS >= p_t);
      state_of(0., tau, N0);
      if (N0 <= S0 * (1 + 1e-10))
        {
          r.status       = ContactStatus::stick;
          r.traction     = normal_traction * n + trial;
          r.tangent      = p_n * nn + p_t * projector;
          r.plastic_slip = old_plastic_slip;
          r.friction     = mu;
          return r;
        }

      // h(c) = N(c) - S(l(c)): positive at c = 0, decreasing; bracket its
      // root, then Newton safeguarded by bisection.
      const auto h = [&](const double c, double &dh) {
        double t[2], N;
        state_of(c, t, N);
        double dN = 0;
        for (unsigned int i = 0; i < nt; ++i)
          dN -= b[i] * b[i] * t[i] * t[i] / (1 + c * b[i]);
        dN             = (N > 0) ? dN / N : 0.;
        const double l = c * N / p_t;
        double       dSl, m;
        const double S = law.strength(x, old_state, l, dt, pressure, dSl, m);
        dh             = dN - dSl * (N + c * dN) / p_t;
        return N - S;
      };
      double lower = 0, upper = 1, dh;
      // (c is dimensionless: c b_i = 1 halves the trial component.)
      for (unsigned int it = 0; it < 200 && h(upper, dh) > 0; ++it)
        {
          lower = upper;
          upper *= 4;
        }
      double c = 0.5 * (lower + upper);
      for (unsigned int it = 0; it < 200; ++it)
        {
          const double value = h(c, dh);
          if (std::abs(value) <= 1e-14 * N0)
            break;
          if (value > 0)
            lower = c;
          else
            upper = c;
          double next = (dh < 0) ? c - value / dh : 0.5 * (lower + upper);
          if (!(next > lower && next < upper))
            next = 0.5 * (lower + upper);
          c = next;
          if (upper - lower <= 1e-15 * upper)
            break;
        }

      double N;
      state_of(c, tau, N);
      const double   l = c * N / p_t;
      const double   S = law.strength(x, old_state, l, dt, pressure, dS, mu);
      Tensor<1, dim> shear, slip;
      for (unsigned int i = 0; i < nt; ++i)
        {
          shear += tau[i] * e[i];
          slip += (trial_i[i] - tau[i]) / p_t * e[i];
        }
      r.status              = ContactStatus::slip;
      r.slip_increment      = l;
      r.friction            = mu;
      r.friction_derivative = (pressure > 0) ? dS / pressure : 0.;
      r.traction            = normal_traction * n + shear;
      r.plastic_slip        = old_plastic_slip + slip;

      // Consistent tangent. Unknowns tau (principal components) and l:
      //   (I + c A^-2) tau = trial,  c = p_t l / S(l, p),
      //   |A^-1 tau| = S(l, p),  p = -(t0.n + p_n delta.n).
      // With M = I + c A^-2, w = A^-2 tau / N, m = M^-1 A^-2 tau,
      //   dc = alpha dl + beta dp,  alpha = p_t (1 - l S_l / S) / S,
      //   beta = -p_t l S_p / S^2,
      //   dl = (w.M^-1 dtrial - (w.m beta + S_p) dp) / (S_l + w.m alpha),
      //   dtau = M^-1 dtrial - m (alpha dl + beta dp),
      // dtrial = p_t P ddelta, dp = -p_n n.ddelta.
      r.tangent = p_n * nn;
      if (!(S > 0) || !(N > 0))
        {
          // No strength left: the shear traction stays zero.
          r.unstable_softening = snaps || (-dS >= p_t);
          return r;
        }
      const double   S_l = dS, S_p = mu;
      const double   alpha = p_t * (1 - l * S_l / S) / S;
      const double   beta  = -p_t * l * S_p / (S * S);
      double         w[2], m[2], Minv[2], wm = 0;
      Tensor<1, dim> w_Minv_dtrial; // w.M^-1 dtrial / ddelta
      for (unsigned int i = 0; i < nt; ++i)
        {
          Minv[i] = 1. / (1 + c * b[i]);
          w[i]    = b[i] * tau[i] / N;
          m[i]    = Minv[i] * b[i] * tau[i];
          wm += w[i] * m[i];
          w_Minv_dtrial += w[i] * Minv[i] * p_t * e[i];
        }
      const double denominator = S_l + wm * alpha;
      const bool   steep       = !(denominator > 0);
      r.unstable_softening     = steep || snaps;
      // dl / ddelta (dp / ddelta = -p_n n).
      // (Weakening steeper than the penalty: the slope S_l is left out
      // throughout, as return_map() does, which keeps the tangent's
      // sliding part from softening; with a ratio of 1 this is
      // return_map()'s tangent.)
      const double         alpha_used = steep ? p_t / S : alpha;
      const Tensor<1, dim> dl = (w_Minv_dtrial + (wm * beta + S_p) * p_n * n) /
                                (steep ? wm * alpha_used : denominator);
      for (unsigned int i = 0; i < nt; ++i)
        {
          // dtau_i / ddelta
          const Tensor<1, dim> dtau =
            Minv[i] * p_t * e[i] - m[i] * (alpha_used * dl - beta * p_n * n);
          r.tangent += outer_product(e[i], dtau);
        }
      return r;
    }



    template Tensor<1, 2>
    inverse_metric(const FrictionEllipse<2> &,
                   const Tensor<1, 2> &,
                   const Tensor<1, 2> &);
    template Tensor<1, 3>
    inverse_metric(const FrictionEllipse<3> &,
                   const Tensor<1, 3> &,
                   const Tensor<1, 3> &);
    template ContactResponse<2>
    anisotropic_return_map(const Tensor<1, 2> &,
                           const Tensor<1, 2> &,
                           const Tensor<1, 2> &,
                           const double,
                           const double,
                           const Tensor<1, 2> &,
                           const Friction::State &,
                           const Friction::Interface &,
                           const Point<3> &,
                           const double,
                           const FrictionEllipse<2> &);
    template ContactResponse<3>
    anisotropic_return_map(const Tensor<1, 3> &,
                           const Tensor<1, 3> &,
                           const Tensor<1, 3> &,
                           const double,
                           const double,
                           const Tensor<1, 3> &,
                           const Friction::State &,
                           const Friction::Interface &,
                           const Point<3> &,
                           const double,
                           const FrictionEllipse<3> &);
  } // namespace Fault
} // namespace rupture
