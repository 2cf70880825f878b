// A mesh that follows the rupture (<Mesh refinement>): between two steps
// the cells of the fault are refined where it slips and ahead of its
// front and coarsened behind it, and cells anywhere where the waves are
// poorly resolved (and coarsened after they left); the state moves to the new
// mesh and the operators, the time step and the integrator are set up again.

#include <rupture/adaptivity/fault_refinement.h>
#include <rupture/fault/fault.h>
#include <rupture/simulator/simulator.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace rupture
{
  template <int dim>
  bool
  Simulator<dim>::adapt_mesh(const double       duration,
                             const double       requested_time_step,
                             const unsigned int steps_done)
  {
    TimerOutput::Scope t(timer, "Adapt mesh");
    const double       wall_start = MPI_Wtime();

    timer.enter_subsection("Adapt mesh: criteria");
    // A quasi-static phase has no waves and no front: no P-wave band ahead
    // of the active nodes (only <Extra band>; a P wave's travel over a
    // loading step would cover the whole fault), and nodes at their
    // strength before its first step do not count (the dynamic phase
    // refines where it nucleates).
    const bool quasi_static =
      current_scheme() == TimeIntegration::Scheme::quasi_static;
    fault_refinement->evaluate(
      state.clock.phase_time,
      steps_done == 0 && !quasi_static,
      quasi_static ? 0. : fastest_wave_speed,
      state.time_step,
      current_scheme() == TimeIntegration::Scheme::explicit_central_difference);

    // The wavefield's criterion in dynamic phases (a quasi-static phase's
    // velocity is the loading rate's).
    double largest_indicator = -1;
    if (mesh_refinement.wavefield &&
        current_scheme() != TimeIntegration::Scheme::quasi_static)
      largest_indicator = fault_refinement->evaluate_wavefield(
        discretization.dof_handler(),
        discretization.ghosted_copy(0, state.velocity));

    const double       energy_before = energy.kinetic + energy.strain;
    const unsigned int pairs_before  = fault ? fault->n_split_nodes() : 0;
    unsigned int       n_without     = 0;
    bool               changed       = false;
    // setup_dofs() reports each new mesh: here one line says it all.
    struct Quiet
    {
      ConditionalOStream &out;
      const bool          was = out.is_active();
      ~Quiet()
      {
        out.set_condition(was);
      }
    } quiet{pcout};
    // One level per pass, coarsening in the first only; the state is
    // carried once through the passes' meshes, and only the last mesh is
    // set up. (The DoFs of a pass's mesh are estimated from its cells, for
    // the budget.)
    if (fault_refinement->flag(true, discretization.dof_handler().n_dofs()))
      {
        const auto  &mesh         = discretization.triangulation();
        const double dofs_before  = discretization.dof_handler().n_dofs();
        const double cells_before = mesh.n_global_active_cells();
        unsigned int pass         = 0;
        const auto   next_pass    = [&]() {
          if (fault_refinement->budget_held() ||
              ++pass > mesh_refinement.levels)
            return false;
          TimerOutput::Scope criteria(timer, "Adapt mesh: criteria");
          return fault_refinement->flag(
            false, dofs_before * mesh.n_global_active_cells() / cells_before);
        };
        timer.leave_subsection();
        pcout.set_condition(false);
        {
          TimerOutput::Scope t(timer, "Adapt mesh: transfer");
          n_without += execute_refinement(next_pass);
          // Both cells of every fault face alike (the mesh's balance may
          // have refined one side only, or coarsened one).
          for (unsigned int k = 0; k < 2 * mesh_refinement.levels + 2 &&
                                   discretization.flag_fault_alike();
               ++k)
            n_without += execute_refinement();
        }
        timer.enter_subsection("Adapt mesh: criteria");
        changed = true;
      }
    timer.leave_subsection();
    if (fault_refinement->budget_newly_held())
      {
        pcout << "   The mesh stays below <Mesh refinement/Maximum degrees "
                 "of freedom> = "
              << static_cast<long long>(mesh_refinement.max_dofs)
              << " after step " << state.step
              << ": a level of refinement was not made.\n";
      }
    if (!changed)
      {
        fault_refinement->nothing_changed();
        return false;
      }
    TimerOutput::Scope set_up(timer, "Adapt mesh: set-up");

    // The operators of the new mesh, the time step of the rest of the
    // phase and the integrator, and the forces of the last step that the
    // energy sums' trapezoidal rules take up.
    assemble_physics_matrices(false);
    if (fault)
      fault->set_time(state.time);
    state.clock.start_segment(state.time, steps_done);
    prepare_phase(current_scheme(), requested_time_step, duration, true);
    quiet.out.set_condition(quiet.was);
    settle_on_new_mesh();
    refresh_step_forces();

    count_mesh_change_energy(energy_before);

    fault_refinement->count(MPI_Wtime() - wall_start);
    pcout << "   Mesh adapted after step " << state.step << ": "
          << discretization.triangulation().n_global_active_cells()
          << " cells, " << discretization.dof_handler().n_dofs() << " DoFs, ";
    if (fault)
      pcout << fault->n_split_nodes() << " fault pairs (" << pairs_before
            << " before"
            << (n_without > 0 ? ", " + std::to_string(n_without) +
                                  " without an old pair near" :
                                std::string())
            << "), ";
    pcout << "time step " << std::setprecision(4) << state.time_step << " s";
    if (largest_indicator >= 0)
      pcout << ", largest wavefield indicator " << largest_indicator << " 1/s";
    pcout << "\n";
    return true;
  }



  template <int dim>
  void
  Simulator<dim>::settle_on_new_mesh()
  {
    if (current_scheme() != TimeIntegration::Scheme::implicit_newmark)
      return;
    // Newmark's energy identity holds for an acceleration that is in
    // balance with the forces (M a = f - K u - C v - contact), which the
    // interpolated one is not on the new mesh; a loaded body's
    // displacement is first moved into the new mesh's balance.
    VectorType load(discretization.locally_owned_dofs(), communicator);
    elastic_system.assemble_load(state.time, load);
    if (mesh_refinement.balance && time_parameters.loading_phase &&
        state.clock.in_dynamic_phase)
      balance_after_adaptation();
    energy.contact_force = 0;
    if (fault)
      fault->add_contact_force(discretization.hanging_constraints(),
                               energy.contact_force);
    compute_acceleration(load);
  }



  template <int dim>
  void
  Simulator<dim>::count_mesh_change_energy(const double energy_before)
  {
    // The energy the interpolation (and the balance) added, counted apart
    // so that the budget stays closed.
    VectorType product(discretization.locally_owned_dofs(), communicator);
    elastic_system.apply_stiffness(state.displacement, product);
    discretization.hanging_constraints().set_zero(product);
    energy.strain = 0.5 * (state.displacement * product);
    if (current_scheme() != TimeIntegration::Scheme::quasi_static)
      {
        elastic_system.apply_mass(state.velocity, product);
        discretization.hanging_constraints().set_zero(product);
        energy.kinetic = 0.5 * (state.velocity * product);
      }
    energy.remeshing += energy.kinetic + energy.strain - energy_before;
  }



  template <int dim>
  void
  Simulator<dim>::balance_after_adaptation()
  {
    try
      {
        const unsigned int n = integrator->balance_displacement();
        ++balance_report.adaptations;
        balance_report.iterations += n;
      }
    catch (const Solver::NewtonFailure &failure)
      {
        // The carried state goes on as it is (as without the balance).
        ++balance_report.failures;
        pcout << "   The displacement could not be balanced on the new "
                 "mesh after step "
              << state.step << " (" << failure.reason
              << "): the run goes on with the interpolated one.\n";
      }
    catch (const dealii::ExceptionBase &failure)
      {
        // The linear solver's failures (collective: every process's
        // Krylov iteration is the same) let the run go on alike; others
        // end it.
        const std::string what = failure.what();
        if (what.find("did not converge") == std::string::npos)
          throw;
        ++balance_report.failures;
        pcout << "   The displacement could not be balanced on the new "
                 "mesh after step "
              << state.step
              << " (its linear solve did not converge; <Mesh "
                 "refinement/Balance after adaptation> = false skips it): "
                 "the run goes on with the interpolated one.\n";
      }
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
