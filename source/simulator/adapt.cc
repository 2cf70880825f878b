// A mesh that follows the rupture (<Mesh refinement>): between two steps
// the cells of the fault are refined where it slips and ahead of its
// front and coarsened behind it; the state moves to the new mesh and the
// operators, the time step and the integrator are set up again.

#include <rupture/adaptivity/front_criterion.h>
#include <rupture/fault/fault.h>
#include <rupture/simulator/simulator.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>

namespace rupture
{
  template <int dim>
  unsigned int
  Simulator<dim>::base_level(
    const typename Triangulation<dim>::cell_iterator &cell) const
  {
    // As make_mesh() refines: the scene's own levels and the global
    // refinements, then one level more
    // for each ancestor (or the cell itself) whose centre lies in the
    // static refinement region, up to its number of levels.
    unsigned int level = scene_levels + n_global_refinements;
    for (unsigned int k = 0; k < n_region_refinements; ++k)
      {
        if (level > static_cast<unsigned int>(cell->level()))
          break;
        auto ancestor = cell;
        while (static_cast<unsigned int>(ancestor->level()) > level)
          ancestor = ancestor->parent();
        if (!(refinement_region->value(ancestor->center()) > 0))
          break;
        ++level;
      }
    return level;
  }



  template <int dim>
  std::pair<unsigned int, unsigned int>
  Simulator<dim>::fault_levels() const
  {
    if (fault_levels_now)
      return *fault_levels_now;
    unsigned int finest_now = 0, finest_then = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && fault->side(cell) == 0)
        for (const auto f : cell->face_indices())
          if (!cell->at_boundary(f) &&
              fault->side(cell->neighbor(f)) != fault->side(cell))
            {
              finest_now  = std::max<unsigned int>(finest_now, cell->level());
              finest_then = std::max(finest_then,
                                     base_level(cell) + mesh_refinement.levels);
            }
    finest_now       = dealii::Utilities::MPI::max(finest_now, communicator);
    finest_then      = dealii::Utilities::MPI::max(finest_then, communicator);
    fault_levels_now = std::make_pair(finest_now, finest_then);
    return *fault_levels_now;
  }



  template <int dim>
  bool
  Simulator<dim>::front_outside_fine_cells() const
  {
    const auto [finest_now, finest_then] = fault_levels();
    if (finest_now >= finest_then)
      return false;
    const bool active =
      !fault
         ->active_locations(mesh_refinement.slip_rate_threshold,
                            state.clock.phase_time,
                            mesh_refinement.coarsening_delay,
                            false)
         .empty();
    return dealii::Utilities::MPI::max(active ? 1 : 0, communicator) == 1;
  }



  template <int dim>
  bool
  Simulator<dim>::adapt_mesh(const double       duration,
                             const double       requested_time_step,
                             const unsigned int steps_done)
  {
    TimerOutput::Scope t(timer, "Adapt mesh");
    const double       wall_start = MPI_Wtime();
    using Adaptivity::Decision;

    timer.enter_subsection("Adapt mesh: criteria");
    // The band ahead of the front: as far as a P wave travels until the
    // next adaptation. The explicit step follows the finest cell: while
    // the fault's cells lack levels that this adaptation adds, the steps
    // to come are shorter by as many halvings.
    double p_wave_speed = 0;
    for (unsigned int m = 0; m < materials.n_materials(); ++m)
      p_wave_speed = std::max(p_wave_speed, materials.get(m).p_wave_speed());
    const auto [finest_now, finest_then] = fault_levels();
    const double coming_step =
      (current_scheme() ==
         TimeIntegration::Scheme::explicit_central_difference &&
       finest_then > finest_now) ?
        std::ldexp(state.time_step,
                   -static_cast<int>(finest_then - finest_now)) :
        state.time_step;
    const double band = p_wave_speed * mesh_refinement.interval * coming_step +
                        mesh_refinement.extra_band;
    // The active nodes of the whole fault, on every process: both cells
    // of a fault face decide alike from them.
    std::vector<Point<dim>> active;
    {
      std::vector<double> mine;
      for (const auto &p :
           fault->active_locations(mesh_refinement.slip_rate_threshold,
                                   state.clock.phase_time,
                                   mesh_refinement.coarsening_delay,
                                   steps_done == 0))
        for (unsigned int d = 0; d < dim; ++d)
          mine.push_back(p[d]);
      for (const auto &from :
           dealii::Utilities::MPI::all_gather(communicator, mine))
        for (unsigned int i = 0; i + dim <= from.size(); i += dim)
          {
            Point<dim> p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = from[i + d];
            active.push_back(p);
          }
    }
    const Adaptivity::FrontCriterion<dim> criterion(active, band);

    const double       energy_before = energy.kinetic + energy.strain;
    const unsigned int pairs_before  = fault->n_split_nodes();
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
    // One level per pass; coarsening in the first only.
    for (unsigned int pass = 0; pass <= mesh_refinement.levels; ++pass)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const unsigned int level = cell->level();
              const unsigned int base  = base_level(cell);
              // A cell of the fault is judged at its fault faces, a cell
              // away from it at its centre (only coarsened).
              bool     at_fault = false;
              Decision decision = Decision::coarsen;
              for (const auto f : cell->face_indices())
                if (!cell->at_boundary(f) &&
                    !cell->neighbor(f)->has_children() &&
                    fault->side(cell->neighbor(f)) != fault->side(cell))
                  {
                    at_fault = true;
                    const Decision of =
                      criterion.decide(cell->face(f)->center(),
                                       cell->face(f)->diameter(),
                                       level,
                                       base,
                                       base + mesh_refinement.levels);
                    if (of == Decision::refine ||
                        (of == Decision::keep && decision != Decision::refine))
                      decision = of;
                  }
              if (!at_fault)
                decision = criterion.decide(
                  cell->center(), cell->diameter(), level, base, base);
              if (decision == Decision::refine)
                cell->set_refine_flag();
              else if (decision == Decision::coarsen && pass == 0)
                cell->set_coarsen_flag();
            }
        // Coarsening flags of incomplete families go.
        triangulation.prepare_coarsening_and_refinement();
        bool flagged = false;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() &&
              (cell->refine_flag_set() || cell->coarsen_flag_set()))
            flagged = true;
        if (dealii::Utilities::MPI::max(flagged ? 1 : 0, communicator) == 0)
          break;
        timer.leave_subsection();
        pcout.set_condition(false);
        {
          TimerOutput::Scope t(timer, "Adapt mesh: transfer");
          n_without += execute_refinement();
          // Both cells of every fault face alike (the mesh's balance may
          // have refined one side only, or coarsened one).
          for (unsigned int k = 0;
               k < 2 * mesh_refinement.levels + 2 && flag_fault_alike();
               ++k)
            n_without += execute_refinement();
        }
        timer.enter_subsection("Adapt mesh: criteria");
        changed = true;
      }
    timer.leave_subsection();
    if (!changed)
      return false;
    TimerOutput::Scope set_up(timer, "Adapt mesh: set-up");

    // The operators of the new mesh, the time step of the rest of the
    // phase and the integrator, and the forces of the last step that the
    // energy sums' trapezoidal rules take up.
    assemble_physics_matrices(false);
    fault->set_time(state.time);
    state.clock.start_segment(state.time, steps_done);
    prepare_phase(current_scheme(), requested_time_step, duration, true);
    if (current_scheme() == TimeIntegration::Scheme::implicit_newmark)
      {
        // Newmark's energy identity holds for an acceleration that is in
        // balance with the forces (M a = f - K u - C v - contact), which
        // the interpolated one is not on the new mesh.
        VectorType load(locally_owned_dofs, communicator);
        assemble_load_vector(state.time, load);
        energy.contact_force = 0;
        fault->add_contact_force(hanging_constraints, energy.contact_force);
        compute_acceleration(load);
      }
    refresh_step_forces();
    quiet.out.set_condition(quiet.was);

    // The energy the interpolation added, counted apart so that the
    // budget stays closed.
    VectorType product(locally_owned_dofs, communicator);
    apply_stiffness(state.displacement, product);
    hanging_constraints.set_zero(product);
    energy.strain = 0.5 * (state.displacement * product);
    if (current_scheme() != TimeIntegration::Scheme::quasi_static)
      {
        apply_mass(state.velocity, product);
        hanging_constraints.set_zero(product);
        energy.kinetic = 0.5 * (state.velocity * product);
      }
    energy.remeshing += energy.kinetic + energy.strain - energy_before;

    ++n_adaptations;
    adaptation_seconds += MPI_Wtime() - wall_start;
    pcout << "   Mesh adapted after step " << state.step << ": "
          << triangulation.n_global_active_cells() << " cells, "
          << dof_handler.n_dofs() << " DoFs, " << fault->n_split_nodes()
          << " fault pairs (" << pairs_before << " before"
          << (n_without > 0 ?
                ", " + std::to_string(n_without) + " without an old pair near" :
                std::string())
          << "), time step " << std::setprecision(4) << state.time_step
          << " s\n";
    return true;
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
