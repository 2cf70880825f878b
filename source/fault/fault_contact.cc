// The fault's contact and split-node tractions, their tangent and the pair
// blocks of the block-Jacobi preconditioner.

#include <rupture/base/utilities.h>
#include <rupture/fault/fault.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace rupture
{
  namespace Fault
  {
    template <int dim>
    void
    Fault<dim>::assemble(const VectorType                &u,
                         const double                     dt,
                         const AffineConstraints<double> &force_constraints,
                         VectorType                      &force,
                         const AffineConstraints<double> &tangent_constraints,
                         TrilinosWrappers::SparseMatrix  *tangent,
                         const double                     sign)
    {
      std::vector<types::global_dof_index> dofs(2 * dim);
      FullMatrix<double>                   local_tangent(2 * dim, 2 * dim);
      for (auto &pair : pairs)
        {
          Tensor<1, dim> delta;
          for (unsigned int c = 0; c < dim; ++c)
            {
              delta[c]      = u(pair.plus[c]) - u(pair.minus[c]);
              dofs[c]       = pair.minus[c];
              dofs[dim + c] = pair.plus[c];
            }
          if (pair.forced && forced_slip_active)
            pair.trial = forced_slip_response<dim>(delta,
                                                   pair.normal,
                                                   pair.initial_traction,
                                                   pair.normal_penalty,
                                                   pair.tangential_penalty,
                                                   pair.plastic_slip,
                                                   imposed_slip(pair, 0));
          else
            pair.trial = return_map<dim>(delta,
                                         pair.normal,
                                         pair.initial_traction,
                                         pair.normal_penalty,
                                         pair.tangential_penalty,
                                         pair.plastic_slip,
                                         pair.state,
                                         *friction_law,
                                         to_3d(pair.location),
                                         dt);
          pair.trial_slip = delta - (delta * pair.normal) * pair.normal;
          contact_blocks.blocks[&pair - pairs.data()] =
            pair.area * pair.trial.tangent;

          add_internal_force(pair, force_constraints, force);

          if (tangent)
            {
              pair_tangent_block(pair, sign, local_tangent);
              tangent_constraints.distribute_local_to_global(local_tangent,
                                                             dofs,
                                                             *tangent);
            }
        }
      force.compress(VectorOperation::add);
      if (tangent)
        tangent->compress(VectorOperation::add);
    }



    template <int dim>
    unsigned int
    Fault<dim>::limit_stick_crossings(
      const VectorType                &increment,
      const AffineConstraints<double> &constraints,
      VectorType                      &correction) const
    {
      unsigned int                         n_limited = 0;
      std::vector<types::global_dof_index> dofs(2 * dim);
      Vector<double>                       local(2 * dim);
      for (const auto &pair : pairs)
        {
          if (pair.trial.status != ContactStatus::slip ||
              (pair.forced && forced_slip_active))
            continue;
          // Tangential trial traction now and along the update,
          // T(s) = T + s D, and the strength now (the traction that slip
          // returned the trial to).
          const Tensor<1, dim> &n = pair.normal;
          Tensor<1, dim>        step;
          for (unsigned int c = 0; c < dim; ++c)
            step[c] = increment(pair.plus[c]) - increment(pair.minus[c]);
          const Tensor<1, dim>  step_t = step - (step * n) * n;
          const Tensor<1, dim> &T      = pair.trial.trial_traction;
          const Tensor<1, dim>  D      = pair.tangential_penalty * step_t;
          const double          D2     = D * D;
          if (D2 == 0)
            continue;
          const Tensor<1, dim> &traction = pair.trial.traction;
          const double strength = (traction - (traction * n) * n).norm();
          // The update's closest approach to zero traction, and whether it
          // lies in the stick region while the full update ends in slip.
          const double s_min   = std::min(std::max(-(T * D) / D2, 0.), 1.);
          const double closest = (T + s_min * D).norm();
          if (s_min >= 1 || (T + D).norm() <= strength || closest >= strength)
            continue;
          // Stop 5 % of the chord into the stick region (a tenth of the way
          // from where the update enters it to its middle): the node's
          // traction changes little, and the next iteration starts from
          // stick, whose penalty tangent is exact there.
          const double s = std::max(s_min - 0.9 *
                                              std::sqrt(strength * strength -
                                                        closest * closest) /
                                              std::sqrt(D2),
                                    0.);
          // Keep the mean of the pair, scale its tangential jump by s.
          const Tensor<1, dim> change = 0.5 * (1 - s) * step_t;
          for (unsigned int c = 0; c < dim; ++c)
            {
              dofs[c]        = pair.minus[c];
              dofs[dim + c]  = pair.plus[c];
              local[c]       = change[c];
              local[dim + c] = -change[c];
            }
          constraints.distribute_local_to_global(local, dofs, correction);
          ++n_limited;
        }
      correction.compress(VectorOperation::add);
      return dealii::Utilities::MPI::sum(n_limited, communicator);
    }



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
          const Tensor<1, dim> &n         = pair.normal;
          const double          gap       = du * n;
          const Tensor<1, dim>  slip      = du - gap * n;
          const double          increment = (slip - pair.slip).norm();

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
          const Point<3> x  = to_3d(pair.location);
          double         dm = 0;
          r.friction =
            friction_law->coefficient(x, pair.state, increment, dt, dm);
          r.friction_derivative = dm;
          const double tn       = T * n;
          if (tn > 0)
            {
              r.status = ContactStatus::open;
              T        = 0;
            }
          else if (forced)
            r.status =
              (increment > 0) ? ContactStatus::slip : ContactStatus::stick;
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
      pair_dofs.scatter_add(forces, force.trilinos_vector()[0]);
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
      const Tensor<1, dim> shear = stick_traction - tn * pair.normal;
      const double         s     = shear.norm();
      const double         p     = -tn;
      Tensor<1, dim>       e;
      double               inverse = 0;
      if (s > 0)
        {
          e = shear / s;
          for (unsigned int d = 0; d < dim; ++d)
            inverse += inverse_sum[d] * e[d] * e[d];
        }
      const double Z = (inverse > 0) ? 1. / (c * dt * pair.area * inverse) : 0.;
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
          double lower = 0, upper = s / Z;
          V                = upper;
          double       gv  = g(V, dg, mu, dmu);
          const double tol = 1e-13 * std::max(s, 1e-300);
          for (unsigned int it = 0; it < 300 && std::abs(gv) > tol; ++it)
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
              gv = g(V, dg, mu, dmu);
            }
          // The slip rate is unique only while the impedance exceeds the
          // law's weakening rate: g must fall through its root.
          if (dg >= 0)
            {
              std::ostringstream message;
              message << "The slip rate of the fault node at (" << pair.location
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
    void
    Fault<dim>::add_internal_force(const NodePair                  &pair,
                                   const AffineConstraints<double> &constraints,
                                   VectorType                      &force) const
    {
      // Internal force of the fault: -A dT on the minus node, +A dT on the
      // plus node, with dT the traction change carried by the displacement.
      std::vector<types::global_dof_index> dofs(2 * dim);
      Vector<double>                       local_force(2 * dim);
      const Tensor<1, dim> dT = pair.trial.traction - pair.initial_traction;
      for (unsigned int d = 0; d < dim; ++d)
        {
          dofs[d]              = pair.minus[d];
          dofs[dim + d]        = pair.plus[d];
          local_force(d)       = -pair.area * dT[d];
          local_force(dim + d) = pair.area * dT[d];
        }
      constraints.distribute_local_to_global(local_force, dofs, force);
    }



    template <int dim>
    void
    Fault<dim>::commit(const double dt, const double time)
    {
      for (auto &pair : pairs)
        {
          const Tensor<1, dim> t =
            pair.trial.traction -
            (pair.trial.traction * pair.normal) * pair.normal;
          Friction::State updated;
          friction_law->update_state(to_3d(pair.location),
                                     pair.state,
                                     pair.trial.slip_increment,
                                     dt,
                                     t.norm(),
                                     updated);
          pair.slip_velocity = (pair.trial_slip - pair.slip) / dt;
          updated.slip_rate  = pair.slip_velocity.norm();
          // Rupture time: the first time the slip rate exceeds 1 mm/s,
          // linearly interpolated within the step (SCEC convention). With
          // penalty contact the jump also holds the springs' elastic part
          // traction / p_t, which moves whenever a passing wave changes the
          // traction (at TPV3's penalties faster than 1 mm/s, well ahead of
          // the rupture), so there it is the rate of the frictional
          // (plastic) slip; the split nodes have no elastic part.
          const double rate = split_node_method ?
                                updated.slip_rate :
                                pair.trial.slip_increment / dt;
          if (pair.rupture_time < 0 && rate > 1e-3)
            {
              const double w = (1e-3 - pair.rupture_rate) /
                               std::max(rate - pair.rupture_rate, 1e-300);
              pair.rupture_time =
                time - dynamic_start - dt + std::clamp(w, 0., 1.) * dt;
            }
          pair.rupture_rate = rate;
          frictional_energy += pair.area * t.norm() * pair.trial.slip_increment;
          pair.state        = updated;
          pair.plastic_slip = pair.trial.plastic_slip;
          pair.slip         = pair.trial_slip;
        }
    }



    template <int dim>
    unsigned int
    Fault<dim>::n_steeper_than_body(const VectorType &effective_diagonal) const
    {
      std::vector<double> &diagonal = pair_values[0];
      pair_dofs.gather(effective_diagonal.trilinos_vector()[0], diagonal);
      unsigned int n = 0;
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          const NodePair             &pair = pairs[k];
          const ContactResponse<dim> &r    = pair.trial;
          if (pair.forced || r.status != ContactStatus::slip ||
              r.friction_derivative >= 0)
            continue;
          const double   tn  = r.traction * pair.normal;
          const double   k_w = -r.friction_derivative * std::max(-tn, 0.);
          const double   p_t = pair.tangential_penalty;
          Tensor<1, dim> e   = r.traction - tn * pair.normal;
          if (e.norm() == 0 || k_w == 0)
            continue;
          e /= e.norm();
          // Where the weakening is steeper than the penalty the node's
          // traction snaps to its residual strength instead (counted by
          // Statistics::unstable_softening).
          if (k_w >= p_t)
            continue;
          const double softening = k_w * p_t / (p_t - k_w) * pair.area;
          // The stiffness of each side along e.
          const auto side = [&](const unsigned int first) {
            double d = 0;
            for (unsigned int c = 0; c < dim; ++c)
              d += e[c] * e[c] * diagonal[first + c];
            return d;
          };
          const double minus = side(2 * dim * k),
                       plus  = side(2 * dim * k + dim);
          if (minus > 0 && plus > 0 &&
              softening > minus * plus / (minus + plus))
            ++n;
        }
      return dealii::Utilities::MPI::sum(n, communicator);
    }



    template <int dim>
    void
    Fault<dim>::apply_tangent(const VectorType &x, VectorType &y) const
    {
      contact_blocks.apply(x.trilinos_vector()[0], y.trilinos_vector()[0]);
    }



    template <int dim>
    void
    Fault<dim>::pair_tangent_block(const NodePair     &pair,
                                   const double        factor,
                                   FullMatrix<double> &block)
    {
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          {
            const double d    = factor * pair.area * pair.trial.tangent[i][j];
            block(i, j)       = d;
            block(i, dim + j) = -d;
            block(dim + i, j) = -d;
            block(dim + i, dim + j) = d;
          }
    }



    template <int dim>
    void
    Fault<dim>::prepare_pair_preconditioner(const VectorType &diagonal,
                                            const VectorType &free)
    {
      contact_blocks.prepare(diagonal.trilinos_vector()[0],
                             free.trilinos_vector()[0]);
    }



    template <int dim>
    void
    Fault<dim>::precondition_pairs(const VectorType &r, VectorType &z) const
    {
      contact_blocks.precondition(r.trilinos_vector()[0],
                                  z.trilinos_vector()[0]);
    }



    template class Fault<2>;
    template class Fault<3>;
  } // namespace Fault
} // namespace rupture
