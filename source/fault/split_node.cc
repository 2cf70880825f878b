// The traction-at-split-node method of the explicit scheme (Day et al.
// 2005): each step the traction that keeps a node pair together, limited
// by the friction strength, with the two updates for laws of the slip
// rate (time-centred, second order; end of step, first order).

#include <rupture/fault/fault.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rupture
{
  namespace Fault
  {
    namespace
    {
      /**
       * The root in [0, @p upper] of a function that is positive at 0 and
       * not positive at @p upper: Newton from @p upper, safeguarded by
       * bisection (geometric while the bracket spans decades: regularised
       * laws slip at any shear, at rates from 1e-30 m/s up). @p g(V, dg)
       * returns g(V) and sets dg = g'(V); on return @p dg holds g' at the
       * root.
       */
      template <class Function>
      double
      falling_root(const Function &g,
                   double          upper,
                   const double    tolerance,
                   double         &dg)
      {
        double lower = 0;
        double V     = upper;
        double gv    = g(V, dg);
        for (unsigned int it = 0; it < 300 && std::abs(gv) > tolerance; ++it)
          {
            if (gv > 0)
              lower = V;
            else
              upper = V;
            double next = (dg < 0) ? V - gv / dg : -1;
            if (!(next > lower && next < upper))
              next = (upper > 1e3 * std::max(lower, 1e-30)) ?
                       std::sqrt(std::max(lower, 1e-30) * upper) :
                       0.5 * (lower + upper);
            if (upper - lower <= 1e-15 * upper)
              break;
            V  = next;
            gv = g(V, dg);
          }
        return V;
      }



      /**
       * The slip rate is unique only while the impedance exceeds the
       * law's weakening rate: g must fall through its root (@p dg < 0).
       */
      template <int dim>
      void
      check_falling(const double      dg,
                    const double      Z,
                    const double      V,
                    const Point<dim> &location)
      {
        if (dg < 0)
          return;
        std::ostringstream message;
        message << "The slip rate of the fault node at (" << location
                << ") is not unique: the friction law weakens with the "
                   "slip rate faster (d strength / dV = "
                << -dg - Z << " Pa s/m at V = " << V
                << " m/s) than the node's impedance Z = " << Z
                << " Pa s/m resists. Refine the mesh or reduce the time "
                   "step (Z grows as 1/dt), or lower the law's "
                   "weakening with the slip rate (the parameters of "
                   "<Fault/Friction law>).";
        AssertThrow(false, ExcMessage(message.str()));
      }



      /**
       * The shear part of a pair's stick traction: its magnitude s, its
       * direction e (zero where s = 0) and the pair's impedance along e,
       * Z = 1 / (c dt A e.(1/M+ + 1/M-)e) (@p factor = c dt A; zero where
       * the sides' inverse masses along e are), the traction change per
       * unit slip rate over the next step.
       */
      template <int dim>
      struct ShearImpedance
      {
        ShearImpedance(const Tensor<1, dim> &stick_traction,
                       const double          tn,
                       const Tensor<1, dim> &normal,
                       const Tensor<1, dim> &inverse_sum,
                       const double          factor)
        {
          const Tensor<1, dim> shear = stick_traction - tn * normal;
          magnitude                  = shear.norm();
          double inverse             = 0;
          if (magnitude > 0)
            {
              direction = shear / magnitude;
              for (unsigned int d = 0; d < dim; ++d)
                inverse += inverse_sum[d] * direction[d] * direction[d];
            }
          impedance = (inverse > 0) ? 1. / (factor * inverse) : 0.;
        }

        double         magnitude = 0;
        Tensor<1, dim> direction;
        double         impedance = 0;
      };



      /**
       * The shear part of a pair's traction of the last step (its initial
       * traction before the first step).
       */
      template <class Pair>
      auto
      previous_shear(const Pair &pair)
      {
        const auto &T = (pair.trial.traction.norm() > 0) ?
                          pair.trial.traction :
                          pair.initial_traction;
        return T - (T * pair.normal) * pair.normal;
      }
    } // namespace



    template <int dim>
    void
    Fault<dim>::assemble_split_node(const VectorType &u,
                                    const VectorType &v,
                                    const VectorType &residual,
                                    const VectorType &inverse_mass,
                                    const double      dt,
                                    const double      gamma,
                                    VectorType       &force)
    {
      // With the fault traction T = T_0 + dT acting on the minus node (and
      // -T on the plus node), the accelerations of the step are
      //   a- = (R- + A dT) / M-,   a+ = (R+ - A dT) / M+,
      // and the displacement of the next step is u + dt (v + c dt a) with
      // c = gamma + 1/2. The traction that keeps the pair together (no
      // tangential slip over the next step, normal gap closed) is thus
      //   dT = [dv / (c dt) + R+/M+ - R-/M- + (du.n) n / (c dt^2)]
      //        / (A (1/M+ + 1/M-)),
      // with dv = v+ - v- and du = u+ - u-.
      const double            c         = gamma + 0.5;
      const VectorType *const fields[4] = {&u, &v, &residual, &inverse_mass};
      for (unsigned int f = 0; f < 4; ++f)
        pair_dofs.gather(fields[f]->trilinos_vector()[0], pair_values[f]);
      const std::vector<double> &us = pair_values[0], &vs = pair_values[1],
                                &rs = pair_values[2], &ms = pair_values[3];
      std::vector<double> &forces = pair_values[0];
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          NodePair          &pair = pairs[k];
          const unsigned int m0 = 2 * dim * k, p0 = m0 + dim;
          Tensor<1, dim>     du, rate, acceleration, inverse_sum;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const unsigned int m = m0 + d, p = p0 + d;
              du[d]           = us[p] - us[m];
              rate[d]         = vs[p] - vs[m];
              acceleration[d] = rs[p] * ms[p] - rs[m] * ms[m];
              inverse_sum[d]  = ms[p] + ms[m];
            }
          const Tensor<1, dim> &n    = pair.normal;
          const double          gap  = du * n;
          const Tensor<1, dim>  slip = du - gap * n;
          const double increment     = slip_measure(pair, slip - pair.slip);

          ContactResponse<dim> r;
          r.slip_increment = increment;
          r.plastic_slip   = slip;
          // Components whose nodes are both held kinematically get no
          // traction change.
          Tensor<1, dim> T = pair.initial_traction;
          // A forced pair follows the imposed slip instead: its slip over
          // the next step is the imposed one's.
          const bool     forced = pair.forced && forced_slip_active;
          Tensor<1, dim> target;
          if (forced)
            target = imposed_slip(pair, dt) - slip;
          const Tensor<1, dim> stick =
            rate / (c * dt) + acceleration + (gap * n - target) / (c * dt * dt);
          for (unsigned int d = 0; d < dim; ++d)
            if (inverse_sum[d] > 0)
              T[d] += stick[d] / (pair.area * inverse_sum[d]);
          const Point<3> x = to_3d(pair.location);
          const bool     centred =
            centred_split_node && friction_law->depends_on_slip_rate();
          if (centred)
            {
              // The state at the time of this step's traction: evolved
              // from the last one over the slip made since (midpoint rule
              // at that constant rate), with the last traction for laws
              // that heat (corrected in centred_rate_traction()).
              friction_law->update_state(x,
                                         pair.state,
                                         increment,
                                         dt,
                                         traction_measure(pair,
                                                          previous_shear(pair)),
                                         pair.trial_state);
              pair.trial_slip_velocity = (slip - pair.slip) / dt;
            }
          double dm = 0;
          r.friction =
            friction_law->coefficient(x, pair.state, increment, dt, dm);
          r.friction_derivative = dm;
          if (pair.hanging)
            {
              // No traction of its own: that of the pairs it follows
              // (interpolate_hanging_tractions()).
              r.traction      = pair.initial_traction;
              pair.trial      = r;
              pair.trial_slip = slip;
              for (unsigned int d = 0; d < dim; ++d)
                forces[m0 + d] = forces[p0 + d] = 0;
              continue;
            }
          const double tn = T * n;
          if (tn > 0)
            {
              r.status = ContactStatus::open;
              T        = 0;
            }
          else if (forced)
            r.status =
              (increment > 0) ? ContactStatus::slip : ContactStatus::stick;
          else if (anisotropic_friction)
            T = anisotropic_split_traction(
              pair, x, T, tn, inverse_sum, c, dt, slip, centred, r);
          else if (centred)
            T = centred_rate_traction(
              pair, x, T, tn, inverse_sum, c, dt, slip, r);
          else if (friction_law->depends_on_slip_rate())
            T = rate_dependent_traction(pair, x, T, tn, inverse_sum, c, dt, r);
          else
            {
              const Tensor<1, dim> shear    = T - tn * n;
              const double         strength = std::max(
                r.friction * (-tn) + friction_law->cohesion(x, pair.state), 0.);
              if (shear.norm() > strength)
                {
                  r.status = ContactStatus::slip;
                  T        = tn * n + (strength / shear.norm()) * shear;
                }
              else
                r.status = ContactStatus::stick;
            }
          r.traction      = T;
          pair.trial      = r;
          pair.trial_slip = slip;

          // Internal force of the fault: -A dT on the minus node, +A dT on
          // the plus node (as add_internal_force()).
          const Tensor<1, dim> dT = T - pair.initial_traction;
          for (unsigned int d = 0; d < dim; ++d)
            {
              forces[m0 + d] = -pair.area * dT[d];
              forces[p0 + d] = pair.area * dT[d];
            }
        }
      if (any_hanging)
        interpolate_hanging_tractions();
      pair_dofs.scatter_add(forces, force.trilinos_vector()[0]);
    }



    template <int dim>
    void
    Fault<dim>::interpolate_hanging_tractions()
    {
      traction_change = 0;
      for (const auto &pair : pairs)
        if (!pair.hanging)
          for (unsigned int c = 0; c < dim; ++c)
            traction_change(pair.minus[c]) =
              pair.trial.traction[c] - pair.initial_traction[c];
      traction_change.compress(VectorOperation::insert);
      std::vector<double> values;
      hanging_gather.gather(traction_change.trilinos_vector()[0], values);
      std::vector<Tensor<1, dim>> change(pairs.size());
      for (unsigned int i = 0; i < hanging_sources.size(); ++i)
        change[hanging_sources[i].pair][hanging_sources[i].component] +=
          hanging_sources[i].weight * values[i];
      for (unsigned int k = 0; k < pairs.size(); ++k)
        if (pairs[k].hanging)
          {
            NodePair      &pair = pairs[k];
            Tensor<1, dim> T    = pair.initial_traction + change[k];
            const double   tn   = T * pair.normal;
            auto          &r    = pair.trial;
            if (tn > 0)
              {
                r.status = ContactStatus::open;
                T        = 0;
              }
            else
              {
                const double strength =
                  std::max(r.friction * (-tn) +
                             friction_law->cohesion(to_3d(pair.location),
                                                    pair.state),
                           0.);
                r.status = traction_measure(pair, T - tn * pair.normal) >=
                               (1 - 1e-6) * strength ?
                             ContactStatus::slip :
                             ContactStatus::stick;
              }
            r.traction = T;
          }
    }



    template <int dim>
    Tensor<1, dim>
    Fault<dim>::rate_dependent_traction(const NodePair       &pair,
                                        const Point<3>       &x,
                                        const Tensor<1, dim> &stick_traction,
                                        const double          tn,
                                        const Tensor<1, dim> &inverse_sum,
                                        const double          c,
                                        const double          dt,
                                        ContactResponse<dim> &r) const
    {
      // A traction below the stick traction by dtau along the shear
      // direction e lets the pair slip over the next step at the rate
      //   V = c dt A (e . (1/M+ + 1/M-) e) dtau = dtau / Z,
      // so slip rate and traction solve together
      //   g(V) = |T_stick,t| - Z V - (mu(V dt) p + cohesion) = 0,  V >= 0,
      // with the law's coefficient of a step at that slip rate (the state
      // evolved over the step with it). g(0) <= 0 sticks. Newton on V,
      // safeguarded by bisection (geometric while the bracket spans
      // decades: regularised laws slip at any shear, at rates from 1e-30
      // m/s up).
      const ShearImpedance<dim> shear(
        stick_traction, tn, pair.normal, inverse_sum, c * dt * pair.area);
      const double          s = shear.magnitude, Z = shear.impedance;
      const double          p = -tn;
      const Tensor<1, dim> &e = shear.direction;
      // mu is the strength's derivative with respect to the pressure (the
      // friction coefficient), dmu that of mu with the slip increment.
      const auto g = [&](const double V, double &dg, double &mu, double &dmu) {
        double       dS = 0;
        const double S =
          friction_law->strength(x, pair.state, V * dt, dt, p, dS, mu);
        dmu = (p > 0) ? dS / p : 0.;
        dg  = -Z - dS * dt;
        return s - Z * V - S;
      };
      double       dg = 0, mu = 0, dmu = 0;
      const double g0 = g(0, dg, mu, dmu);
      double       V  = 0;
      if (g0 > 0 && Z > 0)
        {
          friction_law->check_uniqueness(x, pair.state, p, Z);
          V = falling_root([&](const double W,
                               double      &d) { return g(W, d, mu, dmu); },
                           s / Z,
                           1e-13 * std::max(s, 1e-300),
                           dg);
          check_falling(dg, Z, V, pair.location);
        }
      else
        g(0, dg, mu, dmu);
      r.friction            = mu;
      r.friction_derivative = dmu;
      r.slip_increment      = V * dt;
      r.status = (V > 0) ? ContactStatus::slip : ContactStatus::stick;
      return tn * pair.normal + (s - Z * V) * e;
    }



    template <int dim>
    Tensor<1, dim>
    Fault<dim>::centred_rate_traction(NodePair             &pair,
                                      const Point<3>       &x,
                                      const Tensor<1, dim> &stick_traction,
                                      const double          tn,
                                      const Tensor<1, dim> &inverse_sum,
                                      const double          c,
                                      const double          dt,
                                      const Tensor<1, dim> &slip,
                                      ContactResponse<dim> &r) const
    {
      // Central differences hold the slip at the times t_k of the
      // tractions and the slip rates at the half steps between them: the
      // rate V- = (s_k - s_k-1) / dt of the step before this traction's
      // time and the rate W of the step after it, which the traction
      // controls: a traction below the stick traction by dtau along the
      // shear direction e gives W = dtau / Z (Z as in
      // rate_dependent_traction()). Friction holds at t_k itself: at the
      // slip rate of that instant, V_k = (V-.e + W) / 2, and with the state
      // evolved up to t_k over the slip of the step before (pair.
      // trial_state, the exact relaxation at that step's constant rate:
      // the midpoint rule). So
      //   g(W) = |T_stick,t| - Z W - S(V_k(W), state_k) = 0,  W >= 0,
      // and g(0) <= 0 sticks: a node whose strength holds does not slip
      // over the next step. Both the time of the rate and of the state are
      // thereby centred on the traction's: second order in dt (Kaneko et
      // al. 2008 reach the same with a predictor-corrector on V_k).
      const ShearImpedance<dim> shear(
        stick_traction, tn, pair.normal, inverse_sum, c * dt * pair.area);
      const double          s = shear.magnitude, Z = shear.impedance;
      const double          p        = -tn;
      const Tensor<1, dim> &e        = shear.direction;
      const Tensor<1, dim>  before   = (slip - pair.slip) / dt;
      const double          v_before = before * e;
      double                mu = 0, dS_dV = 0;
      const auto            g = [&](const double W, double &dg) {
        const double V  = 0.5 * (v_before + W);
        double       dS = 0;
        const double S  = friction_law->strength_at_rate(
          x, pair.trial_state, std::max(V, 0.), p, dS, mu);
        dS_dV = (V > 0) ? dS : 0.;
        dg    = -Z - 0.5 * dS_dV;
        return s - Z * W - S;
      };
      double     W     = 0;
      const auto solve = [&]() {
        double dg = 0;
        W         = 0;
        if (g(0, dg) > 0 && Z > 0)
          {
            // d strength / dV_k against the impedance of V_k, 2 Z.
            friction_law->check_uniqueness(x, pair.trial_state, p, 2 * Z);
            W = falling_root(g, s / Z, 1e-13 * std::max(s, 1e-300), dg);
            check_falling(dg, Z, W, pair.location);
          }
        else
          g(0, dg);
      };
      solve();
      if (friction_law->state_depends_on_traction())
        {
          // The heating of the step before with the mean of its two
          // tractions, then the traction again.
          friction_law->update_state(x,
                                     pair.state,
                                     (slip - pair.slip).norm(),
                                     dt,
                                     0.5 * (previous_shear(pair).norm() +
                                            (s - Z * W)),
                                     pair.trial_state);
          solve();
        }
      r.friction            = mu;
      r.friction_derivative = (p > 0) ? 0.5 * dS_dV / (p * dt) : 0.;
      r.slip_increment      = W * dt;
      r.status = (W > 0) ? ContactStatus::slip : ContactStatus::stick;
      pair.trial_slip_velocity = 0.5 * (before + W * e);
      return tn * pair.normal + (s - Z * W) * e;
    }



    template <int dim>
    Tensor<1, dim>
    Fault<dim>::anisotropic_split_traction(NodePair             &pair,
                                           const Point<3>       &x,
                                           const Tensor<1, dim> &stick_traction,
                                           const double          tn,
                                           const Tensor<1, dim> &inverse_sum,
                                           const double          c,
                                           const double          dt,
                                           const Tensor<1, dim> &slip,
                                           const bool            centred,
                                           ContactResponse<dim> &r) const
    {
      // The traction tau = tau_stick - Z W lets the pair slip at the rate
      // W over the next step (Z the impedance along the stick traction's
      // shear, as rate_dependent_traction() has it), and the sliding rule
      // puts W along the ellipse's normal at tau: the projection of
      // tau_stick onto the ellipse in the stiffness k = Z / dt, with the
      // slip l = |A W| dt the law sees (project_onto_ellipse()). A law of
      // the slip rate meets its strength at the step's end, or centred
      // (centred_rate_traction()) at the time of the traction: at the rate
      // V_k = (b + |A W|) / 2, with b the dual rate of the step before
      // along the sliding direction at the stick traction, (before . s) /
      // |A^-1 s| (before . e with a disc), and the state evolved up to
      // then.
      const EllipseFrame<dim>   frame(friction_ellipse, pair.normal);
      const ShearImpedance<dim> shear(
        stick_traction, tn, pair.normal, inverse_sum, c * dt * pair.area);
      const Tensor<1, dim> s = stick_traction - tn * pair.normal;
      const double         Z = shear.impedance, p = -tn;
      const bool           rate      = friction_law->depends_on_slip_rate();
      const double         k         = (Z > 0) ? Z / dt : 1.;
      const Tensor<1, dim> before    = (slip - pair.slip) / dt;
      const double         s_measure = frame.strength_norm(s);
      const double b_before = (s_measure > 0) ? (before * s) / s_measure : 0.;
      const Friction::State &state = centred ? pair.trial_state : pair.state;
      double                 mu = r.friction, dS_dl = 0;
      const StrengthOfSlip   strength =
        [&](const double l, double &dl, double &dp) -> double {
        if (!rate)
          {
            dl = 0;
            dp = r.friction;
            return std::max(r.friction * p + friction_law->cohesion(x, state),
                            0.);
          }
        if (!centred)
          return friction_law->strength(x, state, l, dt, p, dl, dp);
        const double V  = 0.5 * (b_before + l / dt);
        double       dV = 0;
        const double S =
          friction_law->strength_at_rate(x, state, std::max(V, 0.), p, dV, dp);
        dl = (V > 0) ? 0.5 * dV / dt : 0.;
        return S;
      };
      Tensor<1, dim> tau   = s, du;
      double         l     = 0;
      const auto     solve = [&]() {
        double       dp = 0;
        const double S0 = strength(0., dS_dl, dp);
        mu              = rate ? dp : r.friction;
        tau             = s;
        du              = 0;
        l               = 0;
        if (!(s_measure > S0) || (rate && Z == 0))
          return;
        const double b_min = std::min(frame.b[0], frame.b[dim - 2]);
        if (rate)
          friction_law->check_uniqueness(x,
                                         state,
                                         p,
                                         (centred ? 2 : 1) * Z * b_min);
        const EllipseProjection projection =
          project_onto_ellipse(frame, s, k, strength);
        tau = frame.vector(projection.tau);
        du  = (Z > 0) ? (s - tau) / k : Tensor<1, dim>();
        l   = (Z > 0) ? projection.l : 0.;
        strength(l, dS_dl, dp);
        if (rate)
          {
            mu = dp;
            // The root is unique only where the strength falls slower
            // with l than the projection's stiffness.
            check_falling(projection.slope < 0 ? -1. : -Z * b_min - dS_dl * dt,
                          Z * b_min,
                          l / dt,
                          pair.location);
          }
      };
      solve();
      if (centred && rate && friction_law->state_depends_on_traction())
        {
          // The heating of the step before with the mean of its two
          // tractions (their measure against the strength), then the
          // traction again.
          friction_law->update_state(x,
                                     pair.state,
                                     frame.dual_norm(slip - pair.slip),
                                     dt,
                                     0.5 * (frame.strength_norm(
                                              previous_shear(pair)) +
                                            frame.strength_norm(tau)),
                                     pair.trial_state);
          solve();
        }
      r.friction = mu;
      if (rate)
        {
          r.friction_derivative = (p > 0) ? dS_dl / p : 0.;
          r.slip_increment      = l;
        }
      r.sliding = du / dt;
      r.status  = (du.norm() > 0 || (!rate && tau != s)) ? ContactStatus::slip :
                                                           ContactStatus::stick;
      if (centred)
        pair.trial_slip_velocity = 0.5 * (before + du / dt);
      return tn * pair.normal + tau;
    }



    template <int dim>
    double
    Fault<dim>::slip_measure(const NodePair       &pair,
                             const Tensor<1, dim> &v) const
    {
      return anisotropic_friction ?
               EllipseFrame<dim>(friction_ellipse, pair.normal).dual_norm(v) :
               v.norm();
    }



    template <int dim>
    double
    Fault<dim>::traction_measure(const NodePair       &pair,
                                 const Tensor<1, dim> &t) const
    {
      return anisotropic_friction ?
               EllipseFrame<dim>(friction_ellipse, pair.normal)
                 .strength_norm(t) :
               t.norm();
    }



    template class Fault<2>;
    template class Fault<3>;
  } // namespace Fault
} // namespace rupture
