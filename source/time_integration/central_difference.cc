#include <rupture/fault/fault.h>
#include <rupture/time_integration/central_difference.h>

#include <cmath>
#include <sstream>
#include <string>

namespace rupture
{
  namespace TimeIntegration
  {
    template <int dim>
    Scheme
    CentralDifference<dim>::scheme() const
    {
      return Scheme::explicit_central_difference;
    }



    template <int dim>
    void
    CentralDifference<dim>::prepare()
    {
      Context<dim>     &s                 = this->context;
      const IndexSet   &owned_dofs        = s.kinematics.owned_dofs();
      const VectorType &lumped_mass       = s.system.lumped_mass();
      const VectorType *absorbing_damping = s.system.absorbing_damping();
      const double      rayleigh_alpha    = s.system.rayleigh_alpha();
      const AffineConstraints<double> &hanging_constraints =
        s.kinematics.hanging_constraints();
      const AffineConstraints<double> &increment_constraints =
        s.kinematics.increment_constraints();
      // (M (1 + gamma dt alpha) + gamma dt C_abs) a = r is diagonal.
      const double g = s.time_parameters.gamma * s.state.time_step;
      for (VectorType *v : {&inverse_diagonal,
                            &old_displacement,
                            &stiffness_force,
                            &residual,
                            &fault_force,
                            &zone_force,
                            &coupling_force})
        v->reinit(owned_dofs, s.kinematics.communicator());
      dof_kind.assign(owned_dofs.n_elements(), DofKind::free);
      unsigned int k = 0;
      std::string  bad_entry;
      const auto   text = [](const double x) {
        std::ostringstream o;
        o << x;
        return o.str();
      };
      for (const auto i : owned_dofs)
        {
          double d = lumped_mass(i) * (1 + g * rayleigh_alpha);
          if (absorbing_damping)
            d += g * (*absorbing_damping)(i);
          inverse_diagonal(i) =
            (increment_constraints.is_constrained(i) || d == 0) ? 0. : 1. / d;
          if (bad_entry.empty() && !(std::isfinite(inverse_diagonal(i)) &&
                                     std::abs(inverse_diagonal(i)) < 1e100))
            bad_entry =
              " (first at DoF " + std::to_string(i) + ": lumped mass " +
              text(lumped_mass(i)) +
              (absorbing_damping ?
                 ", absorbing damping " + text((*absorbing_damping)(i)) :
                 std::string()) +
              (hanging_constraints.is_constrained(i) ? ", a hanging node" :
                                                       "") +
              ")";
          if (hanging_constraints.is_constrained(i))
            dof_kind[k] = DofKind::tied;
          else if (increment_constraints.is_constrained(i))
            dof_kind[k] = DofKind::kinematic;
          ++k;
        }
      inverse_diagonal.compress(VectorOperation::insert);
      const std::string bad =
        Utilities::MPI::max(bad_entry.empty() ? 0 : 1,
                            s.kinematics.communicator()) == 0 ?
          std::string() :
          (bad_entry.empty() ? std::string(" (on another rank)") : bad_entry);
      AssertThrow(bad.empty() && std::isfinite(inverse_diagonal.l2_norm()) &&
                    std::isfinite(1 + g * rayleigh_alpha),
                  ExcMessage("The diagonal M (1 + gamma dt alpha) + gamma dt "
                             "C_absorbing of the explicit step is not finite" +
                             bad + " with <Damping/Rayleigh alpha> = " +
                             std::to_string(rayleigh_alpha) +
                             " 1/s and the time step " +
                             std::to_string(s.state.time_step) +
                             " s. Allowed: a finite product of the two (a few "
                             "percent of critical damping is alpha ~ 0.1-1 "
                             "1/s)."));
      // The split-node force is zero away from the fault's entries, and the
      // step touches only those.
      fault_entries.clear();
      if (s.fault)
        fault_entries = s.fault->split_node_entries();
      absorbing_blocks = Operators::NodeBlockInverse();
      if (const Operators::NodeCoupling *coupling =
            s.system.absorbing_coupling())
        absorbing_blocks =
          coupling->invert_blocks(inverse_diagonal.trilinos_vector()[0],
                                  g,
                                  fault_entries);
    }



    template <int dim>
    void
    CentralDifference<dim>::step()
    {
      Context<dim>      &s = this->context;
      TimerOutput::Scope t(s.timer, "Explicit step");
      const double       gamma = s.time_parameters.gamma;
      const double       dt    = s.state.time_step;
      const double       alpha = s.system.rayleigh_alpha();
      const double       beta  = s.system.rayleigh_beta();
      const double       eta   = s.system.fault_zone_viscosity();
      const VectorType  &load  = s.system.load(s.state.time);
      const unsigned int n     = dof_kind.size();

      // The owned arrays: every update below is one fused pass over them.
      const auto local = [](const VectorType &v) -> double * {
        return const_cast<double *>(v.trilinos_vector()[0]);
      };
      double *const        u  = local(s.state.displacement),
                    *const v  = local(s.state.velocity),
                    *const a  = local(s.state.acceleration),
                    *const u0 = local(old_displacement),
                    *const r = local(residual), *const ff = local(fault_force);
      const double *const m                 = local(s.system.lumped_mass());
      const VectorType   *absorbing_damping = s.system.absorbing_damping();
      const double *const c_abs =
        absorbing_damping ? local(*absorbing_damping) : nullptr;
      const Operators::NodeCoupling *coupling = s.system.absorbing_coupling();
      const double *const            f        = local(load);
      const double *const            inv_d    = local(inverse_diagonal);

      // Predictors: u = u + dt v + dt^2/2 a, v~ = v + (1 - gamma) dt a.
      for (unsigned int i = 0; i < n; ++i)
        {
          u0[i] = u[i];
          u[i] += dt * v[i] + 0.5 * dt * dt * a[i];
          v[i] += (1 - gamma) * dt * a[i];
        }
      s.kinematics.impose_kinematic_motion(old_displacement,
                                           s.state.displacement,
                                           s.state.time,
                                           dt);
      s.kinematics.set_kinematic_velocity(s.state.velocity, s.state.time);
      s.kinematics.distribute_hanging(s.state.displacement);

      // (M (1 + gamma dt alpha) + gamma dt C_abs) a = f - K (u + beta v~)
      //   - eta K_zone v~ - alpha M v~ - C_abs v~ - F_fault; the stiffness
      //   damping uses the predictor.
      // Without stiffness damping K u is read where the matrix-free
      // operator left it (no copy).
      const double *ku =
        (beta == 0) ? s.system.apply_stiffness_in_place(s.state.displacement) :
                      nullptr;
      if (!ku)
        {
          if (beta == 0)
            s.system.apply_stiffness(s.state.displacement, stiffness_force);
          else
            {
              residual = s.state.displacement;
              residual.add(beta, s.state.velocity);
              s.system.apply_stiffness(residual, stiffness_force);
            }
          ku = local(stiffness_force);
        }
      for (unsigned int i = 0; i < n; ++i)
        r[i] =
          f[i] - ku[i] - alpha * m[i] * v[i] - (c_abs ? c_abs[i] * v[i] : 0.);
      if (coupling)
        coupling->vmult_add(-1., v, r);
      if (eta != 0)
        s.system.add_fault_zone_force(-eta, s.state.velocity, residual);
      // The fault's force, nonzero only at its entries: r - F_fault there.
      if (s.fault)
        {
          for (const unsigned int i : fault_entries)
            ff[i] = 0;
          {
            TimerOutput::Scope t(s.timer, "Fault split nodes");
            s.fault->assemble_split_node(s.state.displacement,
                                         s.state.velocity,
                                         residual,
                                         inverse_diagonal,
                                         dt,
                                         gamma,
                                         fault_force);
          }
          for (const unsigned int i : fault_entries)
            r[i] -= ff[i];
        }
      if (absorbing_blocks.size() == 0)
        for (unsigned int i = 0; i < n; ++i)
          {
            a[i] = r[i] * inv_d[i];
            v[i] += gamma * dt * a[i];
          }
      else
        {
          // The nodes whose dashpots couple their components solve their
          // blocks.
          for (unsigned int i = 0; i < n; ++i)
            a[i] = r[i] * inv_d[i];
          absorbing_blocks.solve(r, a);
          for (unsigned int i = 0; i < n; ++i)
            v[i] += gamma * dt * a[i];
        }
      s.kinematics.distribute_hanging(s.state.acceleration);
      s.kinematics.distribute_hanging(s.state.velocity);

      // The energy budget of the step (see Interface::accept_step(), of
      // which this is the fused form): with stiffness damping K u and K v
      // are products of their own, without it K u is known.
      if (beta != 0)
        {
          s.system.apply_stiffness(s.state.velocity, residual);
          s.system.apply_stiffness(s.state.displacement, stiffness_force);
          ku = local(stiffness_force);
        }
      const double *const kv   = (beta != 0) ? r : nullptr;
      const double       *zone = nullptr;
      if (eta != 0)
        {
          zone_force = 0;
          s.system.add_fault_zone_force(eta, s.state.velocity, zone_force);
          zone = local(zone_force);
        }
      double *const applied = local(s.energy.applied_force);
      double *const damping = local(s.energy.damping_force);
      double *const absorbing =
        absorbing_damping ? local(s.energy.absorbing_force) : nullptr;
      double *const contact = local(s.energy.contact_force);
      double *const coupled = coupling ? local(coupling_force) : nullptr;
      if (coupling)
        {
          coupling_force = 0;
          coupling->vmult_add(1., v, coupled);
        }
      // work of the loads, damping, absorbing boundaries, fault; strain and
      // kinetic energy (the fault's work at its entries only, where its
      // force is nonzero, in the same order)
      double sums[6] = {0, 0, 0, 0, 0, 0};
      for (unsigned int i = 0; i < n; ++i)
        {
          if (dof_kind[i] == DofKind::tied)
            continue;
          const double increment = u[i] - u0[i];
          const double c = alpha * m[i] * v[i] + (kv ? beta * kv[i] : 0.) +
                           (zone ? zone[i] : 0.) +
                           (c_abs ? c_abs[i] * v[i] : 0.) +
                           (coupled ? coupled[i] : 0.);
          // Loads on free DoFs, reactions on kinematically held ones.
          const double force = (dof_kind[i] == DofKind::kinematic) ?
                                 ku[i] + m[i] * a[i] + c + ff[i] :
                                 f[i];
          sums[0] += (force + applied[i]) * increment;
          applied[i] = force;
          sums[1] += (c + damping[i]) * increment;
          damping[i] = c;
          if (absorbing)
            {
              const double fa = c_abs[i] * v[i] + (coupled ? coupled[i] : 0.);
              sums[2] += (fa + absorbing[i]) * increment;
              absorbing[i] = fa;
            }
          sums[4] += u[i] * ku[i];
          sums[5] += m[i] * v[i] * v[i];
        }
      for (const unsigned int i : fault_entries)
        if (dof_kind[i] != DofKind::tied)
          {
            sums[3] += (ff[i] + contact[i]) * (u[i] - u0[i]);
            contact[i] = ff[i];
          }
      dealii::Utilities::MPI::sum(ArrayView<const double>(sums, 6),
                                  s.kinematics.communicator(),
                                  ArrayView<double>(sums, 6));
      s.energy.external_work += 0.5 * sums[0];
      s.energy.damping_dissipation += 0.5 * sums[1];
      s.energy.absorbed += 0.5 * sums[2];
      s.energy.fault_work += 0.5 * sums[3];
      s.energy.strain  = 0.5 * sums[4];
      s.energy.kinetic = 0.5 * sums[5];
      if (s.fault)
        s.fault->commit(dt, s.state.time);
    }



    template class CentralDifference<2>;
    template class CentralDifference<3>;
  } // namespace TimeIntegration
} // namespace rupture
