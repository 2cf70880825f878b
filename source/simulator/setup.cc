// Set-up of the degrees of freedom and of what depends on them: the
// matrices, the matrix-free operator, the multigrid preconditioner and the
// outputs.

#include <rupture/base/utilities.h>
#include <rupture/simulator/simulator.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>
#include <limits>


namespace rupture
{
  template <int dim>
  void
  Simulator<dim>::setup_dofs()
  {
    TimerOutput::Scope t(timer, "Set up DoFs");
    // Ghosted copies exchange by the pattern of the old DoFs.
    ghosts.reset();

    timer.enter_subsection("Set up DoFs: distribute");
    discretization.distribute_dofs();
    timer.leave_subsection();
    // The fault's welded nodes are tied before the constraints close.
    const auto add_fault = [&](AffineConstraints<double> &constraints) {
      TimerOutput::Scope  t(timer, "Set up DoFs: fault");
      std::vector<double> shear_modulus;
      for (unsigned int m = 0; m < materials.n_materials(); ++m)
        shear_modulus.push_back(materials.get(m).mu);
      fault->setup(discretization.dof_handler(),
                   discretization.locally_owned_dofs(),
                   discretization.locally_relevant_dofs(),
                   constraints,
                   shear_modulus,
                   communicator);
    };
    discretization.make_constraints(
      fault ? std::function<void(AffineConstraints<double> &)>(add_fault) :
              std::function<void(AffineConstraints<double> &)>(),
      boundary_conditions);

    using Scheme        = TimeIntegration::Scheme;
    const Scheme scheme = time_parameters.scheme;
    // The matrix-free solver applies the system and the consistent mass
    // through the elastic operator instead.
    const bool matrix_free_system = linear_solver.matrix_free();
    AssertThrow(
      !matrix_free_system || stiffness_matrix_free,
      ExcMessage(
        "<Solver/Preconditioner> = block Jacobi or multigrid stores no "
        "matrix and needs <Discretization/Stiffness "
        "operator> = matrix free."));
    const bool needs_system_matrix =
      (scheme != Scheme::explicit_central_difference ||
       time_parameters.loading_phase) &&
      !matrix_free_system;
    const bool needs_mass_matrix =
      (scheme == Scheme::implicit_newmark && !use_lumped_mass) &&
      !matrix_free_system;

    // The sparsity pattern, only if some matrix is stored (an explicit run
    // with the matrix-free operator stores none).
    DynamicSparsityPattern dsp;
    if (!stiffness_matrix_free || needs_system_matrix || needs_mass_matrix)
      {
        dsp.reinit(discretization.locally_relevant_dofs().size(),
                   discretization.locally_relevant_dofs().size(),
                   discretization.locally_relevant_dofs());
        DoFTools::make_sparsity_pattern(discretization.dof_handler(),
                                        dsp,
                                        discretization.hanging_constraints(),
                                        true);
        if (fault)
          fault->add_sparsity(dsp, discretization.hanging_constraints());
        SparsityTools::distribute_sparsity_pattern(
          dsp,
          discretization.locally_owned_dofs(),
          communicator,
          discretization.locally_relevant_dofs());
      }
    // A scene pays only for what it uses: no mass matrix without inertia or
    // with lumping, no system matrix (hence no solver) in explicit runs.
    if (stiffness_matrix_free)
      {
        stiffness_matrix.clear();
        setup_matrix_free_stiffness();
      }
    else
      stiffness_matrix.reinit(discretization.locally_owned_dofs(),
                              discretization.locally_owned_dofs(),
                              dsp,
                              communicator);
    if (needs_mass_matrix)
      mass_matrix.reinit(discretization.locally_owned_dofs(),
                         discretization.locally_owned_dofs(),
                         dsp,
                         communicator);
    else
      mass_matrix.clear();
    // The preconditioner and the direct solver's factors refer to the old
    // matrix.
    linear_solver.clear();
    if (needs_system_matrix)
      system_matrix.reinit(discretization.locally_owned_dofs(),
                           discretization.locally_owned_dofs(),
                           dsp,
                           communicator);
    else
      system_matrix.clear();

    for (VectorType *v : {&state.displacement,
                          &state.velocity,
                          &state.acceleration,
                          &energy.applied_force,
                          &energy.damping_force,
                          &energy.contact_force,
                          &constant_load})
      v->reinit(discretization.locally_owned_dofs(), communicator);
    if (use_lumped_mass)
      lumped_mass.reinit(discretization.locally_owned_dofs(), communicator);
    if (has_absorbing)
      absorbing_damping.reinit(discretization.locally_owned_dofs(),
                               communicator);
    for (VectorType *v : {&stiffness_diagonal,
                          &consistent_mass_diagonal,
                          &system_diagonal,
                          &free_dofs,
                          &system_work})
      v->clear();
    if (matrix_free_system && (scheme != Scheme::explicit_central_difference ||
                               time_parameters.loading_phase))
      {
        TimerOutput::Scope                         t(timer, "System diagonal");
        LinearAlgebra::distributed::Vector<double> k, m;
        elastic_operator->compute_diagonals(k, m);
        for (VectorType *v :
             {&stiffness_diagonal, &consistent_mass_diagonal, &free_dofs})
          v->reinit(discretization.locally_owned_dofs(), communicator);
        const unsigned int n = k.locally_owned_size();
        std::copy(k.begin(), k.begin() + n, stiffness_diagonal.begin());
        std::copy(m.begin(), m.begin() + n, consistent_mass_diagonal.begin());
        for (const auto i : discretization.locally_owned_dofs())
          free_dofs(i) =
            discretization.increment_constraints().is_constrained(i) ? 0. : 1.;
        free_dofs.compress(VectorOperation::insert);
      }
    multigrid.reset();
    if (linear_solver.multigrid() &&
        (scheme == Scheme::quasi_static || time_parameters.loading_phase ||
         (scheme == Scheme::implicit_newmark &&
          linear_solver.multigrid_in_dynamic_steps())))
      setup_multigrid();
    setup_fault_zone_damping();

    pcout << "   Degrees of freedom: " << discretization.dof_handler().n_dofs()
          << "\n";
    if (fault)
      pcout << "   Fault: " << fault->n_split_nodes() << " split node pairs, "
            << fault->n_welded_nodes() << " welded interface nodes\n";
    TimerOutput::Scope outputs(timer, "Set up DoFs: outputs");
    receivers->setup(discretization.dof_handler(),
                     discretization.locally_owned_dofs());
    // The rigid-body modes are the near null space of the algebraic
    // multigrid: only runs with a system matrix need them.
    null_space.clear();
    if (needs_system_matrix)
      null_space = rigid_body_modes();
    if (fault)
      {
        {
          // The model's top, from which down-dip distances count.
          double top = -std::numeric_limits<double>::max();
          for (const auto &cell :
               discretization.triangulation().active_cell_iterators())
            if (cell->is_locally_owned())
              for (const auto v : cell->vertex_indices())
                top = std::max(top, cell->vertex(v)[dim - 1]);
          top = dealii::Utilities::MPI::max(top, communicator);
          fault_output->setup(*fault, communicator, top);
        }
        if (!fault->uses_split_nodes() && system_matrix.m() > 0)
          linear_solver.set_fault_pairs(fault->dof_pairs(),
                                        discretization.locally_owned_dofs(),
                                        communicator);
      }
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
