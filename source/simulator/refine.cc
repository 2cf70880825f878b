// A new mesh during a run (refined and coarsened as flagged) and a
// continued run on a finer mesh (--refine): the fields and the fault's state
// are carried over (Discretization::refine()), and everything that depends
// on the mesh is set up again (setup_dofs()).

#include <rupture/adaptivity/fault_refinement.h>
#include <rupture/fault/fault.h>
#include <rupture/simulator/simulator.h>

#include <algorithm>
#include <iomanip>

namespace rupture
{
  template <int dim>
  unsigned int
  Simulator<dim>::execute_refinement(const std::function<bool()> &reflag,
                                     const bool                   carry_forces)
  {
    if (fault_refinement)
      fault_refinement->mesh_changed();
    // The motion and the fault's state, with ghost entries, attached to
    // the mesh. (The forces of the energy sums belong to their mesh: the
    // callers compute them anew, refresh_step_forces().)
    timer.enter_subsection("Refinement: attach");
    const std::vector<VectorType *> fields =
      carry_forces ? checkpoint_fields() :
                     std::vector<VectorType *>{&state.displacement,
                                               &state.velocity,
                                               &state.acceleration};
    std::vector<VectorType> carried;
    for (VectorType *f : fields)
      carried.push_back(*f);
    if (fault)
      for (auto &f : fault->state_fields(discretization.locally_owned_dofs()))
        carried.push_back(std::move(f));
    // A field is one function of the mesh only if its constrained DoFs
    // follow their constraints: a hanging DoF that becomes a regular one is
    // then the same from its old and its new cells. (The fault's pairs that
    // existed before keep their own state by location, hanging ones
    // included.)
    for (auto &c : carried)
      discretization.distribute_hanging(c);
    timer.leave_subsection();
    discretization.refine(
      carried,
      fault ? 2 * mesh_refinement.levels + 2 : 0,
      reflag,
      [this]() { setup_dofs(); },
      timer);
    for (unsigned int k = 0; k < fields.size(); ++k)
      {
        // (On the new partition: setup_dofs() does not reinit every field,
        // and Trilinos' assignment needs alike maps.)
        fields[k]->reinit(discretization.locally_owned_dofs(), communicator);
        *fields[k] = carried[k];
        discretization.distribute_hanging(*fields[k]);
      }
    if (!fault)
      return 0;
    return fault->interpolate_new_pairs(
      std::vector<VectorType>(carried.begin() + fields.size(), carried.end()));
  }



  template <int dim>
  void
  Simulator<dim>::refine_continued_run()
  {
    TimerOutput::Scope t(timer, "Refine continued run");
    // (check_checkpoint_parameters() has refused a phase of the explicit
    // scheme, whose stable step would change with the mesh.)
    const unsigned int n_pairs_before = fault ? fault->n_split_nodes() : 0;
    unsigned int       n_without      = 0;
    // Every level at once: the state is carried through the meshes
    // between, and only the last is set up.
    const auto refine_all = [this]() {
      for (const auto &cell :
           discretization.triangulation().active_cell_iterators())
        if (cell->is_locally_owned())
          cell->set_refine_flag();
    };
    if (checkpoints.refinements > 0)
      {
        unsigned int level = 1;
        refine_all();
        n_without += execute_refinement([&]() {
          if (level++ >= checkpoints.refinements)
            return false;
          refine_all();
          return true;
        });
      }
    // The operators of the finer mesh, the phase's integrator (set up
    // again by run_continued()), and the forces of the last step that the
    // energy sums' trapezoidal rules take up: nodal forces belong to their
    // mesh and are computed anew from the carried state, not carried.
    assemble_physics_matrices();
    if (fault)
      fault->set_time(state.time);
    refresh_step_forces();
    pcout << "   The checkpoint's mesh refined " << checkpoints.refinements
          << (checkpoints.refinements == 1 ? " time" : " times") << ": "
          << discretization.triangulation().n_global_active_cells()
          << " cells, " << discretization.dof_handler().n_dofs() << " DoFs";
    if (fault)
      pcout << ", " << fault->n_split_nodes()
            << " fault pairs (the checkpoint's " << n_pairs_before
            << " keep their state, the others' is interpolated along the "
               "fault"
            << (n_without > 0 ? "; " + std::to_string(n_without) +
                                  " had no pair near and start anew" :
                                std::string())
            << ")";
    pcout << "\n";
  }



  template <int dim>
  void
  Simulator<dim>::repartition_continued_run()
  {
    TimerOutput::Scope t(timer, "Repartition continued run");
    using D             = Discretization::Discretization<dim>;
    const double weight = discretization.fault_weight();
    const double before =
      D::weighted_balance(discretization.partition(), weight);
    // No cell flagged: p4est partitions the same mesh with the weights
    // (each cell its own), which on the ranks the checkpoint was written
    // on is the partition of the uninterrupted run. The energy sums'
    // forces of the last step go with the motion: on the same mesh they
    // stay the step's own (computed anew they would differ by the Newton
    // residual of an implicit or quasi-static step).
    execute_refinement({}, true);
    // As refine_continued_run(): the operators and the first phase's
    // integrator (run_continued() sets up a later one).
    assemble_physics_matrices();
    if (fault)
      fault->set_time(state.time);
    pcout << "   Partitioned again with <Discretization/Fault cell weight> = "
          << weight << ": the largest rank's weight " << std::setprecision(3)
          << before << " -> "
          << D::weighted_balance(discretization.partition(), weight)
          << " of the mean\n"
          << std::setprecision(4);
  }



  template <int dim>
  void
  Simulator<dim>::refresh_step_forces()
  {
    // As initialize_state() computes them, for the state as it is.
    using Scheme            = TimeIntegration::Scheme;
    const bool quasi_static = current_scheme() == Scheme::quasi_static;
    VectorType load(discretization.locally_owned_dofs(), communicator);
    elastic_system.assemble_load(state.time, load);
    // The fault's force of its carried tractions: a new return mapping
    // would change the pairs' trial states, from which the loading phase
    // tells whether friction weakens.
    energy.contact_force = 0;
    if (fault)
      fault->add_contact_force(discretization.hanging_constraints(),
                               energy.contact_force);
    VectorType ku(load), ma(load);
    elastic_system.apply_stiffness(state.displacement, ku);
    elastic_system.damping_force(state.velocity, energy.damping_force);
    ma = 0;
    if (!quasi_static)
      elastic_system.apply_mass(state.acceleration, ma);
    set_applied_force(load, ku, ma);
    if (elastic_system.has_absorbing())
      {
        energy.absorbing_force.reinit(load);
        elastic_system.absorbing_force(state.velocity, energy.absorbing_force);
      }
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
