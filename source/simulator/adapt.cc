// A mesh that follows the rupture (<Mesh refinement>): between two steps
// the cells of the fault are refined where it slips and ahead of its
// front and coarsened behind it; the state moves to the new mesh and the
// operators, the time step and the integrator are set up again.

#include <rupture/adaptivity/front_criterion.h>
#include <rupture/adaptivity/gather.h>
#include <rupture/adaptivity/process_zone_criterion.h>
#include <rupture/fault/fault.h>
#include <rupture/simulator/simulator.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
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



  namespace
  {
    /// The edge of a face (m): its length in 2-D, the root of its area in
    /// 3-D.
    template <class FaceIterator>
    double
    edge_of(const FaceIterator &face, const unsigned int dim)
    {
      return std::pow(face->measure(), 1. / (dim - 1));
    }
  } // namespace



  template <int dim>
  std::unique_ptr<Adaptivity::ProcessZoneCriterion<dim>>
  Simulator<dim>::process_zone_criterion() const
  {
    if (!mesh_refinement.process_zone)
      return nullptr;
    // The widths are kept per cube as large as the coarsest fault face of
    // the base mesh, which is where the criterion asks (level_needed()).
    double edge = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (!cell->at_boundary(f) &&
              fault->side(cell->neighbor(f)) != fault->side(cell))
            {
              typename Triangulation<dim>::cell_iterator ancestor = cell;
              while (static_cast<unsigned int>(ancestor->level()) >
                     base_level(cell))
                ancestor = ancestor->parent();
              edge = std::max(edge, edge_of(ancestor->face(f), dim));
            }
    edge = dealii::Utilities::MPI::max(edge, communicator);
    const Adaptivity::ProcessZoneCriterion<dim> mine(
      fault->process_zone_widths(),
      edge,
      mesh_refinement.nodes_per_zone,
      fe_degree);
    return std::make_unique<Adaptivity::ProcessZoneCriterion<dim>>(
      Adaptivity::all_gather(mine.binned(), communicator),
      edge,
      mesh_refinement.nodes_per_zone,
      fe_degree);
  }



  template <int dim>
  unsigned int
  Simulator<dim>::finest_fault_level(
    const typename Triangulation<dim>::cell_iterator &cell,
    const unsigned int                                face,
    const Adaptivity::ProcessZoneCriterion<dim>      *zone,
    const double                                      margin) const
  {
    const unsigned int base   = base_level(cell);
    const unsigned int finest = base + mesh_refinement.levels;
    if (zone == nullptr)
      return finest;
    // Asked at the cell's ancestor of the base mesh, so that every level
    // of a cell gets the same answer (a cell never undoes its refinement
    // because its own, smaller face sees fewer of the zone's nodes).
    auto ancestor = cell;
    while (static_cast<unsigned int>(ancestor->level()) > base)
      ancestor = ancestor->parent();
    const int needed = zone->level_needed(ancestor->face(face)->center(),
                                          edge_of(ancestor->face(face), dim),
                                          ancestor->level(),
                                          margin);
    return std::clamp<int>(needed, base, finest);
  }



  template <int dim>
  std::pair<unsigned int, bool>
  Simulator<dim>::fault_levels() const
  {
    if (fault_levels_now)
      return *fault_levels_now;
    unsigned int finest = 0, refined = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && fault->side(cell) == 0)
        for (const auto f : cell->face_indices())
          if (!cell->at_boundary(f) &&
              fault->side(cell->neighbor(f)) != fault->side(cell))
            {
              finest = std::max<unsigned int>(finest, cell->level());
              if (static_cast<unsigned int>(cell->level()) > base_level(cell))
                refined = 1;
            }
    finest           = dealii::Utilities::MPI::max(finest, communicator);
    refined          = dealii::Utilities::MPI::max(refined, communicator);
    fault_levels_now = std::make_pair(finest, refined == 1);
    return *fault_levels_now;
  }



  template <int dim>
  bool
  Simulator<dim>::front_outside_fine_cells() const
  {
    // (After the budget held refinement back, the fault stays coarser.)
    if (!mesh_refinement.follow_front || budget_reported ||
        fault_levels().second)
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
  double
  Simulator<dim>::dofs_after_flags() const
  {
    // A refined cell becomes 2^dim, a coarsened family of 2^dim one; the
    // DoFs change in proportion to the cells.
    double cells = 0, change = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          ++cells;
          if (cell->refine_flag_set())
            change += (1 << dim) - 1;
          else if (cell->coarsen_flag_set())
            change -= 1. - 1. / (1 << dim);
        }
    cells  = dealii::Utilities::MPI::sum(cells, communicator);
    change = dealii::Utilities::MPI::sum(change, communicator);
    return dof_handler.n_dofs() * (cells + change) / cells;
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
    const auto zone = process_zone_criterion();
    // The active nodes of the whole fault, on every process: both cells
    // of a fault face decide alike from them. (Without the front
    // criterion: none, so that cells away from the fault coarsen to their
    // base level.)
    const std::vector<Point<dim>> active =
      mesh_refinement.follow_front ?
        Adaptivity::all_gather(
          fault->active_locations(mesh_refinement.slip_rate_threshold,
                                  state.clock.phase_time,
                                  mesh_refinement.coarsening_delay,
                                  steps_done == 0),
          communicator) :
        std::vector<Point<dim>>();
    // The band ahead of the front: as far as a P wave travels until the
    // next adaptation. The explicit step follows the finest cell: where
    // this adaptation refines the fault beyond its finest level now (the
    // cells that a band of the present step reaches, up to their finest
    // level), the steps to come are shorter by as many halvings.
    double p_wave_speed = 0;
    for (unsigned int m = 0; m < materials.n_materials(); ++m)
      p_wave_speed = std::max(p_wave_speed, materials.get(m).p_wave_speed());
    const auto band_for = [&](const double time_step) {
      return mesh_refinement.follow_front ?
               p_wave_speed * mesh_refinement.time_to_next(time_step) +
                 mesh_refinement.extra_band :
               0.;
    };
    unsigned int reach = fault_levels().first;
    if (current_scheme() ==
        TimeIntegration::Scheme::explicit_central_difference)
      {
        const Adaptivity::FrontCriterion<dim> wide(active,
                                                   band_for(state.time_step));
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() && fault->side(cell) == 0)
            for (const auto f : cell->face_indices())
              if (!cell->at_boundary(f) &&
                  fault->side(cell->neighbor(f)) != fault->side(cell))
                {
                  const unsigned int finest =
                    finest_fault_level(cell, f, zone.get());
                  if (finest > reach &&
                      (!mesh_refinement.follow_front ||
                       wide.decide(cell->face(f)->center(),
                                   cell->face(f)->diameter(),
                                   cell->level(),
                                   base_level(cell),
                                   finest) == Decision::refine))
                    reach = finest;
                }
        reach = dealii::Utilities::MPI::max(reach, communicator);
      }
    const double band =
      band_for(std::ldexp(state.time_step,
                          -static_cast<int>(reach - fault_levels().first)));
    const Adaptivity::FrontCriterion<dim> criterion(active, band);

    const double       energy_before  = energy.kinetic + energy.strain;
    const unsigned int pairs_before   = fault->n_split_nodes();
    unsigned int       n_without      = 0;
    bool               changed        = false;
    bool               held_by_budget = false;
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
                    const unsigned int finest =
                      finest_fault_level(cell, f, zone.get());
                    Decision of = Decision::keep;
                    if (mesh_refinement.follow_front)
                      of = criterion.decide(cell->face(f)->center(),
                                            cell->face(f)->diameter(),
                                            level,
                                            base,
                                            finest);
                    else if (level < finest)
                      of = Decision::refine;
                    else if (level >
                             finest_fault_level(cell, f, zone.get(), 1.5))
                      of = Decision::coarsen;
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
        if (mesh_refinement.max_dofs > 0 &&
            dofs_after_flags() > mesh_refinement.max_dofs)
          {
            // The level is not made; coarsening goes on.
            for (const auto &cell : triangulation.active_cell_iterators())
              if (cell->is_locally_owned())
                cell->clear_refine_flag();
            triangulation.prepare_coarsening_and_refinement();
            held_by_budget = true;
          }
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
        if (held_by_budget)
          break;
      }
    timer.leave_subsection();
    if (held_by_budget && !budget_reported)
      {
        pcout << "   The mesh stays below <Mesh refinement/Maximum degrees "
                 "of freedom> = "
              << static_cast<long long>(mesh_refinement.max_dofs)
              << " after step " << state.step
              << ": a level of refinement was not made.\n";
        budget_reported = true;
      }
    if (!changed)
      {
        // Nothing to refine at the fault although a node is active (the
        // process zone needs no finer cells): front_outside_fine_cells()
        // asks again only once the mesh has changed.
        if (fault_levels_now && !active.empty())
          fault_levels_now->second = true;
        return false;
      }
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
