#include <rupture/fault/anisotropic_contact.h>

#include <deal.II/base/symmetric_tensor.h>

#include <array>
#include <cmath>

namespace rupture
{
  namespace Fault
  {
    template <int dim>
    EllipseFrame<dim>::EllipseFrame(const FrictionEllipse<dim> &ellipse,
                                    const Tensor<1, dim>       &n)
    {
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
      a = {{ellipse.a1, ellipse.a2}};
      for (unsigned int i = 0; i < 2; ++i)
        b[i] = 1. / (a[i] * a[i]);
    }



    template <int dim>
    std::array<double, 2>
    EllipseFrame<dim>::components(const Tensor<1, dim> &v) const
    {
      std::array<double, 2> c = {{0, 0}};
      for (unsigned int i = 0; i < n_directions; ++i)
        c[i] = v * e[i];
      return c;
    }



    template <int dim>
    Tensor<1, dim>
    EllipseFrame<dim>::vector(const std::array<double, 2> &c) const
    {
      Tensor<1, dim> v;
      for (unsigned int i = 0; i < n_directions; ++i)
        v += c[i] * e[i];
      return v;
    }



    template <int dim>
    double
    EllipseFrame<dim>::strength_norm(const Tensor<1, dim> &v) const
    {
      double sum = 0;
      for (unsigned int i = 0; i < n_directions; ++i)
        sum += b[i] * std::pow(v * e[i], 2);
      return std::sqrt(sum);
    }



    template <int dim>
    double
    EllipseFrame<dim>::dual_norm(const Tensor<1, dim> &v) const
    {
      double sum = 0;
      for (unsigned int i = 0; i < n_directions; ++i)
        sum += std::pow(a[i] * (v * e[i]), 2);
      return std::sqrt(sum);
    }



    template <int dim>
    Tensor<1, dim>
    EllipseFrame<dim>::sliding_direction(const Tensor<1, dim> &v) const
    {
      Tensor<1, dim> result;
      for (unsigned int i = 0; i < n_directions; ++i)
        result += b[i] * (v * e[i]) * e[i];
      return result;
    }



    template <int dim>
    Tensor<1, dim>
    EllipseFrame<dim>::inverse_metric(const Tensor<1, dim> &v) const
    {
      Tensor<1, dim> result;
      for (unsigned int i = 0; i < n_directions; ++i)
        result += (v * e[i]) / a[i] * e[i];
      return result;
    }



    template <int dim>
    EllipseProjection
    project_onto_ellipse(const EllipseFrame<dim> &frame,
                         const Tensor<1, dim>    &trial,
                         const double             k,
                         const StrengthOfSlip    &strength)
    {
      constexpr unsigned int      nt      = dim - 1;
      const auto                 &b       = frame.b;
      const std::array<double, 2> trial_i = frame.components(trial);
      // tau(c) = (I + c A^-2)^-1 trial, N(c) = |A^-1 tau(c)| and the slip
      // l(c) = |A du| = c N(c) / k.
      const auto state_of = [&](const double c, std::array<double, 2> &tau) {
        double sum = 0;
        for (unsigned int i = 0; i < nt; ++i)
          {
            tau[i] = trial_i[i] / (1 + c * b[i]);
            sum += b[i] * tau[i] * tau[i];
          }
        return std::sqrt(sum);
      };
      std::array<double, 2> tau;
      const double          N0 = state_of(0., tau);
      // h(c) = N(c) - S(l(c)): positive at c = 0, decreasing while the
      // law weakens slower than k; bracket its root, then Newton
      // safeguarded by bisection.
      const auto h = [&](const double c, double &dh) {
        std::array<double, 2> t;
        const double          N  = state_of(c, t);
        double                dN = 0;
        for (unsigned int i = 0; i < nt; ++i)
          dN -= b[i] * b[i] * t[i] * t[i] / (1 + c * b[i]);
        dN               = (N > 0) ? dN / N : 0.;
        const double l   = c * N / k;
        double       dSl = 0, dSp = 0;
        const double S = strength(l, dSl, dSp);
        dh             = dN - dSl * (N + c * dN) / k;
        return N - S;
      };
      double lower = 0, upper = 1, dh = 0;
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
      EllipseProjection result;
      h(c, result.slope);
      result.c = c;
      result.N = state_of(c, result.tau);
      result.l = c * result.N / k;
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
                           const FrictionEllipse<dim> &ellipse,
                           const double                eta,
                           const Tensor<1, dim>       *old_shear_traction)
    {
      constexpr unsigned int nt = dim - 1;
      ContactResponse<dim>   r;
      const Tensor<2, dim>   nn = outer_product(n, n);
      const Tensor<2, dim>   projector =
        Tensor<2, dim>(unit_symmetric_tensor<dim>()) - nn;
      const EllipseFrame<dim> frame(ellipse, n);
      const auto             &e = frame.e;
      const auto             &b = frame.b;

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
          r.slip_increment = frame.dual_norm(r.plastic_slip - old_plastic_slip);
          r.friction =
            law.coefficient(x, old_state, r.slip_increment, dt, derivative);
          return r;
        }

      const double         pressure = -normal_traction;
      const Tensor<1, dim> trial =
        t0_t + p_t * (delta_t - projector * old_plastic_slip);
      r.trial_traction = trial;
      // The traction projected (the friction's part of the traction, the
      // mean of the step's when centred) and the stiffness k of the
      // projection: tau_f = projected - k du.
      const bool   centred = old_shear_traction && law.depends_on_slip_rate();
      const double q       = centred ? 0.5 : 1.;
      const double k       = q * p_t + eta / dt;
      const Tensor<1, dim> projected =
        centred ? 0.5 * (projector * (*old_shear_traction) + trial) : trial;
      // The strength of a slip l: at the step's end, or at the middle of
      // the step (half the slip over half the step: the mean rate).
      const StrengthOfSlip strength =
        [&](const double l, double &dS_dl, double &dS_dp) {
          if (centred)
            {
              const double S = law.strength(
                x, old_state, 0.5 * l, 0.5 * dt, pressure, dS_dl, dS_dp);
              dS_dl *= 0.5;
              return S;
            }
          return law.strength(x, old_state, l, dt, pressure, dS_dl, dS_dp);
        };
      double       dS = 0, mu = 0;
      const double S0 = strength(0., dS, mu);
      // Weakening at the start of the slip steeper than the projection's
      // stiffness: the traction drops to the residual strength at once
      // (snap-back).
      const bool snaps = (-dS >= k * std::min(b[0], b[nt - 1]));
      if (frame.strength_norm(projected) <= S0 * (1 + 1e-10))
        {
          r.status       = ContactStatus::stick;
          r.traction     = normal_traction * n + trial;
          r.tangent      = p_n * nn + p_t * projector;
          r.plastic_slip = old_plastic_slip;
          r.friction     = mu;
          return r;
        }
      // The penalty (with the damping) is the node's impedance to slip per
      // unit rate; in the dual norm the weakest direction's b_i of it.
      law.check_uniqueness(x,
                           old_state,
                           pressure,
                           k * dt * std::min(b[0], b[nt - 1]));

      const EllipseProjection p =
        project_onto_ellipse(frame, projected, k, strength);
      const double         c = p.c, l = p.l, N = p.N;
      const double         S  = strength(l, dS, mu);
      const Tensor<1, dim> du = (projected - frame.vector(p.tau)) / k;
      r.status                = ContactStatus::slip;
      r.slip_increment        = l;
      r.friction              = mu;
      // (The end traction's slope with l, as return_map() gives it: with
      // the damping, and twice the mean's when centred.)
      r.friction_derivative =
        (pressure > 0) ? (dS + (eta > 0 ? eta / dt : 0.)) / (q * pressure) : 0.;
      r.traction     = normal_traction * n + trial - p_t * du;
      r.plastic_slip = old_plastic_slip + du;
      r.sliding      = du / dt;

      // Consistent tangent. Unknowns tau (principal components of the
      // friction's traction) and l:
      //   (I + c A^-2) tau = projected,  c = k l / S(l, p),
      //   |A^-1 tau| = S(l, p),  p = -(t0.n + p_n delta.n),
      // and T_t = trial - p_t du with du = (projected - tau) / k. With
      // M = I + c A^-2, w = A^-2 tau / N, m = M^-1 A^-2 tau,
      //   dc = alpha dl + beta dp,  alpha = k (1 - l S_l / S) / S,
      //   beta = -k l S_p / S^2,
      //   dl = (w.M^-1 dprojected - (w.m beta + S_p) dp)
      //        / (S_l + w.m alpha),
      //   dtau = M^-1 dprojected - m (alpha dl + beta dp),
      // dprojected = q p_t P ddelta, dp = -p_n n.ddelta, and
      //   dT_t = p_t P ddelta - (p_t / k) (dprojected - dtau).
      r.tangent = p_n * nn;
      if (!(S > 0) || !(N > 0))
        {
          // No strength left: the friction's shear traction stays zero,
          // T_t = trial - (p_t / k) projected, but it grows with the
          // pressure along tau_f / S = A^2 projected / |A projected| (the
          // limit of the projection), as return_map() keeps the term
          // -mu p_n e (x) n.
          r.unstable_softening =
            snaps || (-dS >= k * std::min(b[0], b[nt - 1]));
          r.tangent += (p_t - p_t * q * p_t / k) * projector;
          const double a_projected = frame.dual_norm(projected);
          if (a_projected > 0)
            {
              Tensor<1, dim> u;
              for (unsigned int i = 0; i < nt; ++i)
                u += frame.a[i] * frame.a[i] * (projected * e[i]) * e[i];
              r.tangent -=
                (p_t / k) * mu * p_n / a_projected * outer_product(u, n);
            }
          return r;
        }
      const double          S_l = dS, S_p = mu;
      const double          alpha = k * (1 - l * S_l / S) / S;
      const double          beta  = -k * l * S_p / (S * S);
      std::array<double, 2> w, m, Minv;
      double                wm = 0;
      Tensor<1, dim>        w_Minv_dprojected; // w.M^-1 dprojected / ddelta
      for (unsigned int i = 0; i < nt; ++i)
        {
          Minv[i] = 1. / (1 + c * b[i]);
          w[i]    = b[i] * p.tau[i] / N;
          m[i]    = Minv[i] * b[i] * p.tau[i];
          wm += w[i] * m[i];
          w_Minv_dprojected += w[i] * Minv[i] * q * p_t * e[i];
        }
      const double denominator = S_l + wm * alpha;
      const bool   steep       = !(denominator > 0);
      r.unstable_softening     = steep || snaps;
      // dl / ddelta (dp / ddelta = -p_n n).
      // (Weakening steeper than the penalty: the slope S_l is left out
      // throughout, as return_map() does, which keeps the tangent's
      // sliding part from softening; with a ratio of 1 this is
      // return_map()'s tangent.)
      const double         alpha_used = steep ? k / S : alpha;
      const Tensor<1, dim> dl =
        (w_Minv_dprojected + (wm * beta + S_p) * p_n * n) /
        (steep ? wm * alpha_used : denominator);
      for (unsigned int i = 0; i < nt; ++i)
        {
          // dtau_i / ddelta, then dT_i / ddelta.
          const Tensor<1, dim> dtau = Minv[i] * q * p_t * e[i] -
                                      m[i] * (alpha_used * dl - beta * p_n * n);
          r.tangent +=
            outer_product(e[i],
                          p_t * e[i] - (p_t / k) * (q * p_t * e[i] - dtau));
        }
      return r;
    }



    template struct EllipseFrame<2>;
    template struct EllipseFrame<3>;
    template EllipseProjection
    project_onto_ellipse(const EllipseFrame<2> &,
                         const Tensor<1, 2> &,
                         const double,
                         const StrengthOfSlip &);
    template EllipseProjection
    project_onto_ellipse(const EllipseFrame<3> &,
                         const Tensor<1, 3> &,
                         const double,
                         const StrengthOfSlip &);
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
                           const FrictionEllipse<2> &,
                           const double,
                           const Tensor<1, 2> *);
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
                           const FrictionEllipse<3> &,
                           const double,
                           const Tensor<1, 3> *);
  } // namespace Fault
} // namespace rupture
