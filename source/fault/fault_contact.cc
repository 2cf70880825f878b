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
#include <optional>
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
          if (held)
            {
              // Stuck from the accepted plastic slip (a slip imposed to be
              // where it was, in the fault's plane as a return mapping's
              // stick is); the friction coefficient stays as it was.
              const double         friction = pair.trial.friction;
              const Tensor<1, dim> in_plane =
                pair.plastic_slip -
                (pair.plastic_slip * pair.normal) * pair.normal;
              pair.trial          = forced_slip_response<dim>(delta,
                                                     pair.normal,
                                                     pair.initial_traction,
                                                     pair.normal_penalty,
                                                     pair.tangential_penalty,
                                                     in_plane,
                                                     in_plane);
              pair.trial.friction = friction;
            }
          else if (pair.forced && forced_slip_active)
            pair.trial = forced_slip_response<dim>(delta,
                                                   pair.normal,
                                                   pair.initial_traction,
                                                   pair.normal_penalty,
                                                   pair.tangential_penalty,
                                                   pair.plastic_slip,
                                                   imposed_slip(pair, 0));
          else
            {
              // The shear traction of the step's start, for the centred
              // friction only: the initial one and the springs' stretch
              // (slip minus plastic slip) of the last accepted step.
              Tensor<1, dim> old_shear;
              if (centred_penalty)
                old_shear =
                  pair.initial_traction -
                  (pair.initial_traction * pair.normal) * pair.normal +
                  pair.tangential_penalty * (pair.slip - pair.plastic_slip);
              const Tensor<1, dim> *const old =
                centred_penalty ? &old_shear : nullptr;
              pair.trial =
                anisotropic_friction ?
                  anisotropic_return_map<dim>(delta,
                                              pair.normal,
                                              pair.initial_traction,
                                              pair.normal_penalty,
                                              pair.tangential_penalty,
                                              pair.plastic_slip,
                                              pair.state,
                                              *friction_law,
                                              to_3d(pair.location),
                                              dt,
                                              friction_ellipse,
                                              pair.radiation_damping,
                                              old) :
                  return_map<dim>(delta,
                                  pair.normal,
                                  pair.initial_traction,
                                  pair.normal_penalty,
                                  pair.tangential_penalty,
                                  pair.plastic_slip,
                                  pair.state,
                                  *friction_law,
                                  to_3d(pair.location),
                                  dt,
                                  pair.radiation_damping,
                                  old);
            }
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
          const Tensor<1, dim> step_t = step - (step * n) * n;
          // (With anisotropic friction in the coordinates A^-1 tau, where
          // the stick region is the disc of radius S, as it is otherwise.)
          std::optional<EllipseFrame<dim>> frame;
          if (anisotropic_friction)
            frame.emplace(friction_ellipse, n);
          const auto scaled = [&](const Tensor<1, dim> &v) {
            return frame ? frame->inverse_metric(v) : v;
          };
          const Tensor<1, dim> T  = scaled(pair.trial.trial_traction);
          const Tensor<1, dim> D  = scaled(pair.tangential_penalty * step_t);
          const double         D2 = D * D;
          if (D2 == 0)
            continue;
          const Tensor<1, dim> &traction = pair.trial.traction;
          const double strength = scaled(traction - (traction * n) * n).norm();
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
    Fault<dim>::add_contact_force(const AffineConstraints<double> &constraints,
                                  VectorType                      &force) const
    {
      // (A vector of its own: its last operation is an addition on every
      // process, whether it has pairs or not.)
      VectorType f(force.locally_owned_elements(), communicator);
      for (const auto &pair : pairs)
        add_internal_force(pair, constraints, f);
      f.compress(VectorOperation::add);
      force += f;
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
          // The traction the law's heating and the dissipation see: with
          // anisotropic friction the one conjugate to the slip's dual norm,
          // (t . du) / |A du| (|A^-1 t| on the ellipse), so that it times
          // the law's slip is the work t . du (the review paper's eq. 5.2);
          // never negative (the end traction of the centred rule can turn
          // against the slip). Forced and hanging pairs, which slide
          // without the projection, take the slip of the step.
          double traction_size = t.norm();
          if (anisotropic_friction)
            {
              Tensor<1, dim> du = pair.trial.sliding;
              if (du.norm() == 0)
                du = split_node_method ?
                       pair.trial_slip - pair.slip :
                       pair.trial.plastic_slip - pair.plastic_slip;
              const double l = slip_measure(pair, du);
              traction_size  = (l > 0) ? std::max((t * du) / l, 0.) :
                                         traction_measure(pair, t);
            }
          Friction::State updated;
          if (split_node_method && centred_split_node &&
              friction_law->depends_on_slip_rate())
            {
              // The time-centred update evolved the state to this step's
              // time, and its slip velocity is that of this instant.
              updated            = pair.trial_state;
              pair.slip_velocity = pair.trial_slip_velocity;
            }
          else
            {
              friction_law->update_state(to_3d(pair.location),
                                         pair.state,
                                         pair.trial.slip_increment,
                                         dt,
                                         traction_size,
                                         updated);
              pair.slip_velocity = (pair.trial_slip - pair.slip) / dt;
            }
          // (The slip rate the law sees: |A V| with anisotropic friction.)
          updated.slip_rate = slip_measure(pair, pair.slip_velocity);
          // Rupture time: the first time the slip rate exceeds 1 mm/s,
          // linearly interpolated within the step (SCEC convention). With
          // penalty contact the jump also holds the springs' elastic part
          // traction / p_t, which moves whenever a passing wave changes the
          // traction (at TPV3's penalties faster than 1 mm/s, well ahead of
          // the rupture), so there it is the rate of the frictional
          // (plastic) slip; the split nodes have no elastic part.
          // (The Euclidean length of the plastic slip increment: with
          // anisotropic friction slip_increment is the dual norm |A slip|.)
          const double rate =
            split_node_method ?
              pair.slip_velocity.norm() :
              (anisotropic_friction ?
                 (pair.trial.plastic_slip - pair.plastic_slip).norm() / dt :
                 pair.trial.slip_increment / dt);
          if (pair.rupture_time == NodeState<dim>::not_ruptured && rate > 1e-3)
            {
              const double w = (1e-3 - pair.rupture_rate) /
                               std::max(rate - pair.rupture_rate, 1e-300);
              pair.rupture_time =
                time - dynamic_start - dt + std::clamp(w, 0., 1.) * dt;
            }
          pair.rupture_rate = rate;
          frictional_energy +=
            pair.area * traction_size * pair.trial.slip_increment;
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
          const double tn  = r.traction * pair.normal;
          const double k_w = -r.friction_derivative * std::max(-tn, 0.);
          const double p_t = pair.tangential_penalty;
          // (The direction of the slip: with anisotropic friction the
          // sliding rule's, not the traction's.)
          Tensor<1, dim> e =
            anisotropic_friction ? r.sliding : r.traction - tn * pair.normal;
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
