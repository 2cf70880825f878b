// Set-up of the mesh (global and regional refinement) and of the degrees of
// freedom.

#include <rupture/base/utilities.h>
#include <rupture/simulator/simulator.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>


namespace rupture
{
  namespace
  {
    /**
     * The memory of the nodes this run has (the sum of MemTotal over the
     * nodes), or 0 if unknown.
     */
    double
    memory_of_nodes(const MPI_Comm communicator, unsigned int &n_nodes)
    {
      MPI_Comm node;
      MPI_Comm_split_type(
        communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
      const bool first = dealii::Utilities::MPI::this_mpi_process(node) == 0;
      MPI_Comm_free(&node);
      double mine = 0;
      if (first)
        {
          std::ifstream in("/proc/meminfo");
          std::string   key;
          double        kilobytes = 0;
          while (in >> key >> kilobytes)
            {
              if (key == "MemTotal:")
                {
                  mine = kilobytes * 1024;
                  break;
                }
              in.ignore(256, '\n');
            }
        }
      n_nodes = dealii::Utilities::MPI::sum(first ? 1u : 0u, communicator);
      return dealii::Utilities::MPI::sum(mine, communicator);
    }
  } // namespace



  template <int dim>
  void
  Simulator<dim>::check_mesh_size(const double       n_coarse,
                                  const std::string &source,
                                  const double       available,
                                  const unsigned int n_nodes) const
  {
    // A lower bound of what a cell costs with everything the run builds on
    // it (about 1.6 kB for Q1 and 6.5 kB for Q2 hexahedra, measured): a
    // mesh that needs more than the nodes have cannot be set up.
    const double bytes_per_cell = 1000;
    const double n_cells =
      n_coarse * std::pow(2., dim * double(n_global_refinements));
    if (available > 0 && n_cells * bytes_per_cell > available)
      {
        std::ostringstream message;
        message << std::setprecision(3) << "The mesh would have about "
                << n_cells << " cells (" << source << " " << n_coarse
                << " coarse cells, refined "
                << "<Discretization/Initial global refinement> = "
                << n_global_refinements << " times), which needs at least "
                << n_cells * bytes_per_cell / 1e9 << " GB, more than the "
                << available / 1e9 << " GB of memory of the " << n_nodes
                << " node(s) this run has. Allowed: a mesh that fits, at "
                   "1 kB per cell or more; give fewer cells or less "
                   "refinement, or run on more nodes.";
        AssertThrow(false, ExcMessage(message.str()));
      }
  }



  template <int dim>
  bool
  Simulator<dim>::flag_fault_alike()
  {
    bool flagged = false;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (!cell->at_boundary(f) && cell->neighbor(f)->has_children())
            for (unsigned int c = 0; c < cell->face(f)->n_children(); ++c)
              {
                const auto child = cell->neighbor_child_on_subface(f, c);
                if (fault->side(child) != fault->side(cell) &&
                    !cell->refine_flag_set())
                  {
                    cell->clear_coarsen_flag();
                    cell->set_refine_flag();
                    flagged = true;
                  }
              }
    return dealii::Utilities::MPI::max(flagged ? 1 : 0, communicator) != 0;
  }



  template <int dim>
  void
  Simulator<dim>::refine_fault_alike()
  {
    // The mesh's 2:1 balance may refine a cell on one side of the fault
    // only: refine its neighbour across until both sides match.
    for (unsigned int pass = 0; pass < 2 * n_region_refinements + 2; ++pass)
      {
        if (!flag_fault_alike())
          return;
        triangulation.execute_coarsening_and_refinement();
      }
  }



  template <int dim>
  void
  Simulator<dim>::make_mesh()
  {
    TimerOutput::Scope t(timer, "Set up mesh");
    // The size is checked before anything large is built: from the scene's
    // own count if it has one, else from the coarse mesh.
    unsigned int n_nodes   = 0;
    const double available = memory_of_nodes(communicator, n_nodes);
    if (scene->n_coarse_cells() > 0)
      check_mesh_size(scene->n_coarse_cells(),
                      "the scene's <Number of cells> give",
                      available,
                      n_nodes);
    scene->create_coarse_mesh(triangulation);
    // A scene may refine its coarse blocks itself (a box's tree levels):
    // the levels a mesh that follows the rupture never coarsens.
    {
      unsigned int level = std::numeric_limits<unsigned int>::max();
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          level = std::min<unsigned int>(level, cell->level());
      scene_levels = dealii::Utilities::MPI::min(level, communicator);
    }
    check_mesh_size(triangulation.n_global_active_cells(),
                    "the scene's coarse mesh has",
                    available,
                    n_nodes);
    for (const auto &cell : triangulation.active_cell_iterators())
      materials.check_material_id(cell->material_id());
    // A continued run takes the checkpoint's refined mesh (and its
    // partition onto this run's ranks), with the fields attached.
    if (checkpoints.resume)
      triangulation.load(checkpoints.resume_from + "/mesh");
    else
      triangulation.refine_global(n_global_refinements);
    for (unsigned int level = 0;
         level < (checkpoints.resume ? 0 : n_region_refinements);
         ++level)
      {
        std::string bad_centre;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const double value = refinement_region->value(cell->center());
              if (!std::isfinite(value) && bad_centre.empty())
                {
                  std::ostringstream where;
                  where << "(" << cell->center() << ")";
                  bad_centre = where.str();
                }
              if (value > 0)
                cell->set_refine_flag();
              // Both cells of a fault face are refined alike: where the
              // region covers one, the other is flagged too (evaluated
              // here, where that cell may be another process's).
              if (fault && !cell->refine_flag_set())
                for (const auto f : cell->face_indices())
                  if (!cell->at_boundary(f) &&
                      !cell->neighbor(f)->has_children() &&
                      fault->side(cell->neighbor(f)) != fault->side(cell) &&
                      refinement_region->value(cell->neighbor(f)->center()) > 0)
                    cell->set_refine_flag();
            }
        // Every process stops, not only the one that found the value.
        AssertThrow(dealii::Utilities::MPI::max(bad_centre.empty() ? 0 : 1,
                                                communicator) == 0,
                    ExcMessage("<Discretization/Refinement region> is not a "
                               "finite number at the cell centre " +
                               (bad_centre.empty() ? std::string("of a cell "
                                                                 "of another "
                                                                 "process") :
                                                     bad_centre) +
                               ". Allowed are expressions that are finite "
                               "everywhere in the model."));
        triangulation.execute_coarsening_and_refinement();
        if (fault)
          refine_fault_alike();
      }

    std::vector<double> cells_per_material(materials.n_materials(), 0.);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        cells_per_material[cell->material_id()] += 1;
    MPI_Allreduce(MPI_IN_PLACE,
                  cells_per_material.data(),
                  cells_per_material.size(),
                  MPI_DOUBLE,
                  MPI_SUM,
                  communicator);
    pcout << "   Mesh: " << triangulation.n_global_active_cells()
          << " cells (per material id:";
    for (const double n : cells_per_material)
      pcout << " " << static_cast<unsigned long>(n);
    pcout << ")\n" << materials.summary();
  }



  template <int dim>
  void
  Simulator<dim>::setup_dofs()
  {
    TimerOutput::Scope t(timer, "Set up DoFs");
    // Ghosted copies exchange by the pattern of the old DoFs.
    ghosts.reset();

    // One displacement field per side: component s*dim + c is component c
    // on side s, and FE_Nothing gives the other side no DoFs on a cell.
    fe_collection = hp::FECollection<dim>();
    if (!fault)
      fe_collection.push_back(FESystem<dim>(FE_Q<dim>(fe_degree), dim));
    else
      {
        fe_collection.push_back(
          FESystem<dim>(FE_Q<dim>(fe_degree), dim, FE_Nothing<dim>(), dim));
        fe_collection.push_back(
          FESystem<dim>(FE_Nothing<dim>(), dim, FE_Q<dim>(fe_degree), dim));
      }
    timer.enter_subsection("Set up DoFs: distribute");
    dof_handler.reinit(triangulation);
    if (fault)
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          cell->set_active_fe_index(fault->side(cell));
    dof_handler.distribute_dofs(fe_collection);

    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    hanging_constraints.clear();
    hanging_constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_constraints);
    timer.leave_subsection();
    if (fault)
      {
        TimerOutput::Scope  t(timer, "Set up DoFs: fault");
        std::vector<double> shear_modulus;
        for (unsigned int m = 0; m < materials.n_materials(); ++m)
          shear_modulus.push_back(materials.get(m).mu);
        fault->setup(dof_handler,
                     locally_owned_dofs,
                     locally_relevant_dofs,
                     hanging_constraints,
                     shear_modulus,
                     communicator);
      }
    hanging_constraints.close();
    hanging_distributor.reinit(hanging_constraints,
                               locally_owned_dofs,
                               communicator);

    // Kinematic boundary conditions: collect the constrained DoFs of each
    // named boundary (first condition wins where boundaries meet).
    increment_constraints.clear();
    increment_constraints.reinit(locally_relevant_dofs);
    kinematic_dofs.clear();
    for (const auto &bc : boundary_conditions.kinematic)
      for_each_support_point(
        [&](const auto &cell) {
          if (cell->is_artificial())
            return false;
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == bc.id)
              return true;
          return false;
        },
        [&](const auto                                 &cell,
            const std::vector<types::global_dof_index> &dofs,
            const std::vector<Point<dim>>              &points) {
          const auto &fe = cell->get_fe();
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == bc.id)
              for (unsigned int i = 0; i < dofs.size(); ++i)
                {
                  if (!fe.has_support_on_face(i, f))
                    continue;
                  const unsigned int c =
                    fe.system_to_component_index(i).first % dim;
                  const auto dof = dofs[i];
                  if (!bc.components[c] ||
                      increment_constraints.is_constrained(dof) ||
                      hanging_constraints.is_constrained(dof))
                    continue;
                  increment_constraints.add_line(dof);
                  if (locally_owned_dofs.is_element(dof))
                    kinematic_dofs.push_back(
                      {dof, c, points[i], bc.velocity.get()});
                }
        });
    increment_constraints.merge(
      hanging_constraints,
      AffineConstraints<double>::MergeConflictBehavior::left_object_wins);
    increment_constraints.close();

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
        dsp.reinit(locally_relevant_dofs.size(),
                   locally_relevant_dofs.size(),
                   locally_relevant_dofs);
        DoFTools::make_sparsity_pattern(dof_handler,
                                        dsp,
                                        hanging_constraints,
                                        true);
        if (fault)
          fault->add_sparsity(dsp, hanging_constraints);
        SparsityTools::distribute_sparsity_pattern(dsp,
                                                   locally_owned_dofs,
                                                   communicator,
                                                   locally_relevant_dofs);
      }
    // A scene pays only for what it uses: no mass matrix without inertia or
    // with lumping, no system matrix (hence no solver) in explicit runs.
    if (stiffness_matrix_free)
      {
        stiffness_matrix.clear();
        setup_matrix_free_stiffness();
      }
    else
      stiffness_matrix.reinit(locally_owned_dofs,
                              locally_owned_dofs,
                              dsp,
                              communicator);
    if (needs_mass_matrix)
      mass_matrix.reinit(locally_owned_dofs,
                         locally_owned_dofs,
                         dsp,
                         communicator);
    else
      mass_matrix.clear();
    // The preconditioner and the direct solver's factors refer to the old
    // matrix.
    linear_solver.clear();
    if (needs_system_matrix)
      system_matrix.reinit(locally_owned_dofs,
                           locally_owned_dofs,
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
      v->reinit(locally_owned_dofs, communicator);
    if (use_lumped_mass)
      lumped_mass.reinit(locally_owned_dofs, communicator);
    if (has_absorbing)
      absorbing_damping.reinit(locally_owned_dofs, communicator);
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
          v->reinit(locally_owned_dofs, communicator);
        const unsigned int n = k.locally_owned_size();
        std::copy(k.begin(), k.begin() + n, stiffness_diagonal.begin());
        std::copy(m.begin(), m.begin() + n, consistent_mass_diagonal.begin());
        for (const auto i : locally_owned_dofs)
          free_dofs(i) = increment_constraints.is_constrained(i) ? 0. : 1.;
        free_dofs.compress(VectorOperation::insert);
      }
    multigrid.reset();
    if (linear_solver.multigrid() &&
        (scheme == Scheme::quasi_static || time_parameters.loading_phase ||
         (scheme == Scheme::implicit_newmark &&
          linear_solver.multigrid_in_dynamic_steps())))
      setup_multigrid();
    setup_fault_zone_damping();

    pcout << "   Degrees of freedom: " << dof_handler.n_dofs() << "\n";
    if (fault)
      pcout << "   Fault: " << fault->n_split_nodes() << " split node pairs, "
            << fault->n_welded_nodes() << " welded interface nodes\n";
    TimerOutput::Scope outputs(timer, "Set up DoFs: outputs");
    receivers->setup(dof_handler, locally_owned_dofs);
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
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned())
              for (const auto v : cell->vertex_indices())
                top = std::max(top, cell->vertex(v)[dim - 1]);
          top = dealii::Utilities::MPI::max(top, communicator);
          fault_output->setup(*fault, communicator, top);
        }
        if (!fault->uses_split_nodes() && system_matrix.m() > 0)
          linear_solver.set_fault_pairs(fault->dof_pairs(),
                                        locally_owned_dofs,
                                        communicator);
      }
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
