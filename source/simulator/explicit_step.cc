#include <rupture/simulator/simulator.h>

namespace rupture
{
  template <int dim>
  void
  Simulator<dim>::prepare_explicit_work()
  {
    // (M (1 + gamma dt alpha) + gamma dt C_abs) a = r is diagonal.
    const double g = time_parameters.gamma * time_step;
    for (VectorType *v : {&explicit_inverse_diagonal,
                          &old_displacement,
                          &stiffness_force,
                          &step_residual,
                          &fault_force})
      v->reinit(locally_owned_dofs, communicator);
    dof_kind.assign(locally_owned_dofs.n_elements(), DofKind::free);
    unsigned int k = 0;
    for (const auto i : locally_owned_dofs)
      {
        double d = lumped_mass(i) * (1 + g * rayleigh_alpha);
        if (has_absorbing)
          d += g * absorbing_damping(i);
        explicit_inverse_diagonal(i) =
          (increment_constraints.is_constrained(i) || d == 0) ? 0. : 1. / d;
        if (hanging_constraints.is_constrained(i))
          dof_kind[k] = DofKind::tied;
        else if (increment_constraints.is_constrained(i))
          dof_kind[k] = DofKind::kinematic;
        ++k;
      }
    explicit_inverse_diagonal.compress(VectorOperation::insert);
    // The split-node force is zero away from the fault's entries, and the
    // step touches only those.
    fault_entries.clear();
    if (fault)
      fault_entries = fault->split_node_entries();
  }



  template <int dim>
  void
  Simulator<dim>::explicit_step()
  {
    TimerOutput::Scope t(timer, "Explicit step");
    const double       gamma = time_parameters.gamma;
    const double       dt    = time_step;
    const VectorType  &load  = current_load(time);
    const unsigned int n     = dof_kind.size();

    // The owned arrays: every update below is one fused pass over them.
    const auto local = [](const VectorType &v) -> double * {
      return const_cast<double *>(v.trilinos_vector()[0]);
    };
    double *const u = local(displacement), *const v = local(velocity),
                  *const a  = local(acceleration),
                  *const u0 = local(old_displacement),
                  *const r  = local(step_residual),
                  *const ff = local(fault_force);
    const double *const  m  = local(lumped_mass);
    const double *const  c_abs =
      has_absorbing ? local(absorbing_damping) : nullptr;
    const double *const f     = local(load);
    const double *const inv_d = local(explicit_inverse_diagonal);

    // Predictors: u = u + dt v + dt^2/2 a, v~ = v + (1 - gamma) dt a.
    for (unsigned int i = 0; i < n; ++i)
      {
        u0[i] = u[i];
        u[i] += dt * v[i] + 0.5 * dt * dt * a[i];
        v[i] += (1 - gamma) * dt * a[i];
      }
    for (const auto &k : kinematic_dofs)
      displacement(k.dof) =
        old_displacement(k.dof) +
        kinematic_velocity(k, time - 0.5 * time_step) * time_step;
    displacement.compress(VectorOperation::insert);
    set_kinematic_velocity(velocity);
    distribute_hanging(displacement);

    // (M (1 + gamma dt alpha) + gamma dt C_abs) a = f - K (u + beta v~)
    //   - alpha M v~ - C_abs v~ - F_fault; the stiffness damping uses the
    //   predictor.
    // Without stiffness damping K u is read where the matrix-free operator
    // left it (no copy).
    const double *ku =
      (rayleigh_beta == 0) ? apply_stiffness_in_place(displacement) : nullptr;
    if (!ku)
      {
        if (rayleigh_beta == 0)
          apply_stiffness(displacement, stiffness_force);
        else
          {
            step_residual = displacement;
            step_residual.add(rayleigh_beta, velocity);
            apply_stiffness(step_residual, stiffness_force);
          }
        ku = local(stiffness_force);
      }
    for (unsigned int i = 0; i < n; ++i)
      r[i] = f[i] - ku[i] - rayleigh_alpha * m[i] * v[i] -
             (c_abs ? c_abs[i] * v[i] : 0.);
    // The fault's force, nonzero only at its entries: r - F_fault there.
    if (fault)
      {
        for (const unsigned int i : fault_entries)
          ff[i] = 0;
        assemble_split_node_force(velocity, step_residual, false, fault_force);
        for (const unsigned int i : fault_entries)
          r[i] -= ff[i];
      }
    for (unsigned int i = 0; i < n; ++i)
      {
        a[i] = r[i] * inv_d[i];
        v[i] += gamma * dt * a[i];
      }
    distribute_hanging(acceleration);
    distribute_hanging(velocity);

    // The energy budget of the step (see update_energy(), of which this is
    // the fused form): with stiffness damping K u and K v are products of
    // their own, without it K u is known.
    if (rayleigh_beta != 0)
      {
        apply_stiffness(velocity, step_residual);
        apply_stiffness(displacement, stiffness_force);
        ku = local(stiffness_force);
      }
    const double *const kv      = (rayleigh_beta != 0) ? r : nullptr;
    double *const       applied = local(applied_force);
    double *const       damping = local(damping_force);
    double *const absorbing = has_absorbing ? local(absorbing_force) : nullptr;
    double *const contact   = local(contact_force);
    // work of the loads, damping, absorbing boundaries, fault; strain and
    // kinetic energy (the fault's work at its entries only, where its
    // force is nonzero, in the same order)
    double sums[6] = {0, 0, 0, 0, 0, 0};
    for (unsigned int i = 0; i < n; ++i)
      {
        if (dof_kind[i] == DofKind::tied)
          continue;
        const double increment = u[i] - u0[i];
        const double c         = rayleigh_alpha * m[i] * v[i] +
                         (kv ? rayleigh_beta * kv[i] : 0.) +
                         (c_abs ? c_abs[i] * v[i] : 0.);
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
            const double fa = c_abs[i] * v[i];
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
                                communicator,
                                ArrayView<double>(sums, 6));
    external_work += 0.5 * sums[0];
    damping_dissipation += 0.5 * sums[1];
    absorbed_energy += 0.5 * sums[2];
    fault_work += 0.5 * sums[3];
    strain_energy  = 0.5 * sums[4];
    kinetic_energy = 0.5 * sums[5];
    if (fault)
      fault->commit(time_step, time);
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
