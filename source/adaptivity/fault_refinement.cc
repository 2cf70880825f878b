#include <rupture/adaptivity/consistent_flags.h>
#include <rupture/adaptivity/fault_refinement.h>
#include <rupture/adaptivity/front_criterion.h>
#include <rupture/adaptivity/gather.h>
#include <rupture/adaptivity/process_zone_criterion.h>
#include <rupture/adaptivity/wavefield_criterion.h>
#include <rupture/fault/fault.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rupture
{
  namespace Adaptivity
  {
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

      /// One decision of two criteria: refine if one asks for it, coarsen
      /// only if both allow it.
      Decision
      combined(const Decision a, const Decision b)
      {
        if (a == Decision::refine || b == Decision::refine)
          return Decision::refine;
        if (a == Decision::coarsen && b == Decision::coarsen)
          return Decision::coarsen;
        return Decision::keep;
      }



      /// The ancestor of @p cell on level @p base (the cell itself if it
      /// is there): where the process-zone criterion asks.
      template <class CellIterator>
      CellIterator
      ancestor_on(CellIterator cell, const unsigned int base)
      {
        while (static_cast<unsigned int>(cell->level()) > base)
          cell = cell->parent();
        return cell;
      }
    } // namespace



    template <int dim>
    FaultRefinement<dim>::FaultRefinement(
      const Parameters                                  &parameters,
      dealii::parallel::distributed::Triangulation<dim> &triangulation,
      const Fault::Fault<dim>                           *fault,
      std::function<unsigned int(const CellIterator &)>  base_level,
      const unsigned int                                 degree)
      : parameters(parameters)
      , triangulation(triangulation)
      , fault(fault)
      , base_level(std::move(base_level))
      , degree(degree)
      , communicator(triangulation.get_communicator())
    {}



    template <int dim>
    FaultRefinement<dim>::~FaultRefinement() = default;



    template <int dim>
    bool
    FaultRefinement<dim>::at_fault(const CellIterator &cell,
                                   const unsigned int  f) const
    {
      return fault && fault->interface_face(cell, f);
    }



    template <int dim>
    std::unique_ptr<ProcessZoneCriterion<dim>>
    FaultRefinement<dim>::process_zone_criterion() const
    {
      if (!parameters.process_zone)
        return nullptr;
      // The widths are kept per cube as large as the smallest fault face
      // of the base mesh, which is where the criterion asks
      // (finest_fault_level()): a graded mesh's large faces far out would
      // otherwise mix a barrier's tiny zones into the core's cubes.
      double edge = std::numeric_limits<double>::max();
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (at_fault(cell, f))
              edge = std::min(
                edge,
                edge_of(
                  ancestor_on(CellIterator(cell), base_level(cell))->face(f),
                  dim));
      edge = dealii::Utilities::MPI::min(edge, communicator);
      const ProcessZoneCriterion<dim> mine(fault->process_zone_widths(),
                                           edge,
                                           parameters.nodes_per_zone,
                                           degree);
      return std::make_unique<ProcessZoneCriterion<dim>>(
        all_gather(mine.binned(), communicator),
        edge,
        parameters.nodes_per_zone,
        degree);
    }



    template <int dim>
    unsigned int
    FaultRefinement<dim>::finest_fault_level(const CellIterator &cell,
                                             const unsigned int  face,
                                             const double        margin) const
    {
      const unsigned int base   = base_level(cell);
      const unsigned int finest = base + parameters.levels;
      if (!zone)
        return finest;
      // Asked at the cell's ancestor of the base mesh, so that every level
      // of a cell gets the same answer (a cell never undoes its refinement
      // because its own, smaller face sees fewer of the zone's nodes).
      const auto ancestor = ancestor_on(cell, base);
      const int  needed   = zone->level_needed(ancestor->face(face)->center(),
                                            edge_of(ancestor->face(face), dim),
                                            ancestor->level(),
                                            margin);
      return std::clamp<int>(needed, base, finest);
    }



    template <int dim>
    std::pair<unsigned int, bool>
    FaultRefinement<dim>::fault_levels() const
    {
      if (levels_now)
        return *levels_now;
      unsigned int finest = 0, refined = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && fault && fault->side(cell) == 0)
          for (const auto f : cell->face_indices())
            if (at_fault(cell, f))
              {
                finest = std::max<unsigned int>(finest, cell->level());
                if (static_cast<unsigned int>(cell->level()) > base_level(cell))
                  refined = 1;
              }
      finest     = dealii::Utilities::MPI::max(finest, communicator);
      refined    = dealii::Utilities::MPI::max(refined, communicator);
      levels_now = std::make_pair(finest, refined == 1);
      return *levels_now;
    }



    template <int dim>
    bool
    FaultRefinement<dim>::front_outside_fine_cells(
      const double phase_time) const
    {
      // (After the budget held refinement back, the fault stays coarser.)
      if (!parameters.follow_front || budget_reported || fault_levels().second)
        return false;
      const bool active = !fault
                             ->active_locations(parameters.slip_rate_threshold,
                                                phase_time,
                                                parameters.coarsening_delay,
                                                false)
                             .empty();
      return dealii::Utilities::MPI::max(active ? 1 : 0, communicator) == 1;
    }



    template <int dim>
    void
    FaultRefinement<dim>::evaluate(const double phase_time,
                                   const bool   before_first_step,
                                   const double p_wave_speed,
                                   const double time_step,
                                   const bool   explicit_scheme)
    {
      zone = process_zone_criterion();
      // The active nodes of the whole fault, on every process: both cells
      // of a fault face decide alike from them. (Without the front
      // criterion: none, so that cells away from the fault coarsen to
      // their base level.)
      const std::vector<dealii::Point<dim>> active =
        parameters.follow_front ?
          all_gather(fault->active_locations(parameters.slip_rate_threshold,
                                             phase_time,
                                             parameters.coarsening_delay,
                                             before_first_step),
                     communicator) :
          std::vector<dealii::Point<dim>>();
      any_active = !active.empty();
      // The band ahead of the front: as far as a P wave travels until the
      // next adaptation. The explicit step follows the finest cell: where
      // this adaptation refines the fault beyond its finest level now (the
      // cells that a band of the present step reaches, up to their finest
      // level), the steps to come are shorter by as many halvings.
      const auto band_for = [&](const double step) {
        return parameters.follow_front ?
                 p_wave_speed * parameters.time_to_next(step) +
                   parameters.extra_band :
                 0.;
      };
      unsigned int reach = fault_levels().first;
      if (explicit_scheme)
        {
          const FrontCriterion<dim> wide(active, band_for(time_step));
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned() && fault && fault->side(cell) == 0)
              for (const auto f : cell->face_indices())
                if (at_fault(cell, f))
                  {
                    const unsigned int finest = finest_fault_level(cell, f);
                    if (finest > reach &&
                        (!parameters.follow_front ||
                         wide.decide(cell->face(f)->center(),
                                     cell->face(f)->diameter(),
                                     cell->level(),
                                     base_level(cell),
                                     finest) == Decision::refine))
                      reach = finest;
                  }
          reach = dealii::Utilities::MPI::max(reach, communicator);
        }
      // With the wavefield criterion the step follows the finest cells
      // anywhere: where the front refines beyond them, the steps to come
      // are shorter by as many halvings; else the wavefield's coarsening
      // (one level per adaptation) may double the step.
      double step =
        std::ldexp(time_step, -static_cast<int>(reach - fault_levels().first));
      if (parameters.wavefield)
        {
          const int finest = triangulation.n_global_levels() - 1;
          step             = static_cast<int>(reach) > finest ?
                               std::ldexp(time_step, finest - int(reach)) :
                               2 * time_step;
        }
      front = std::make_unique<FrontCriterion<dim>>(active,
                                                    band_for(step),
                                                    parameters.graded_band);
      // The wavefield's band: as far as a P wave travels until the next
      // adaptation, with the steps to come: shorter where the front refines
      // beyond the finest cells. (Not twice the step, as for the front: the
      // step doubles only if no cell stays at the finest level or reaches
      // it, and a wave above the threshold in a finest cell keeps it.)
      if (parameters.wavefield && parameters.wavefield_band)
        {
          const int finest = triangulation.n_global_levels() - 1;
          wave_band =
            p_wave_speed *
            parameters.time_to_next(
              std::ldexp(time_step,
                         std::min(0, finest - static_cast<int>(reach))));
        }
      else
        wave_band = 0;
    }



    template <int dim>
    double
    FaultRefinement<dim>::evaluate_wavefield(
      const dealii::DoFHandler<dim>               &dofs,
      const dealii::TrilinosWrappers::MPI::Vector &velocity)
    {
      wave = std::make_unique<WavefieldCriterion<dim>>(
        dofs, velocity, parameters.wavefield_threshold, wave_band);
      return wave->largest();
    }



    template <int dim>
    bool
    FaultRefinement<dim>::flag(const bool coarsen, const double n_dofs)
    {
      const bool fault_criteria =
        parameters.follow_front || parameters.process_zone;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int level = cell->level();
            const unsigned int base  = base_level(cell);
            // By the fault's criteria, a cell of the fault is judged at
            // its fault faces, a cell away from it at its centre (only
            // coarsened).
            bool     at_the_fault = false, touches_fault = false;
            Decision decision = Decision::coarsen;
            for (const auto f : cell->face_indices())
              {
                if (!at_fault(cell, f))
                  continue;
                touches_fault = true;
                if (!fault_criteria || cell->neighbor(f)->has_children())
                  continue;
                at_the_fault              = true;
                const unsigned int finest = finest_fault_level(cell, f);
                Decision           of     = Decision::keep;
                if (parameters.follow_front)
                  of = front->decide(cell->face(f)->center(),
                                     cell->face(f)->diameter(),
                                     level,
                                     base,
                                     finest);
                else if (level < finest)
                  of = Decision::refine;
                else if (level > finest_fault_level(cell, f, 1.5))
                  of = Decision::coarsen;
                if (of == Decision::refine ||
                    (of == Decision::keep && decision != Decision::refine))
                  decision = of;
              }
            if (!at_the_fault)
              decision = front->decide(
                cell->center(), cell->diameter(), level, base, base);
            if (wave)
              {
                // Both cells of a fault face must stay alike, and the
                // indicator of the cell across is another process's: at
                // the fault the wavefield refines (the other side follows)
                // but leaves coarsening to the fault's criteria.
                Decision of_wave =
                  wave->decide(cell, base, base + parameters.wavefield_levels);
                if (of_wave == Decision::coarsen && touches_fault)
                  of_wave = Decision::keep;
                decision = combined(decision, of_wave);
              }
            if (decision == Decision::refine)
              cell->set_refine_flag();
            else if (decision == Decision::coarsen && coarsen)
              cell->set_coarsen_flag();
          }
      // The wavefield's indicators belong to this mesh.
      wave.reset();
      // Coarsening flags of incomplete families go; the level balance is
      // decided alike on every partition.
      make_flags_consistent(triangulation);
      triangulation.prepare_coarsening_and_refinement();
      held = false;
      if (parameters.max_dofs > 0 &&
          dofs_after_flags(n_dofs) > parameters.max_dofs)
        {
          // The level is not made; coarsening goes on. (Also the refine
          // flags that the first pass set on ghost cells go, or the next
          // would see them.)
          for (const auto &cell : triangulation.active_cell_iterators())
            if (!cell->is_artificial())
              cell->clear_refine_flag();
          make_flags_consistent(triangulation);
          triangulation.prepare_coarsening_and_refinement();
          held = true;
        }
      bool flagged = false;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() &&
            (cell->refine_flag_set() || cell->coarsen_flag_set()))
          flagged = true;
      return dealii::Utilities::MPI::max(flagged ? 1 : 0, communicator) == 1;
    }



    template <int dim>
    bool
    FaultRefinement<dim>::budget_newly_held()
    {
      if (!held || budget_reported)
        return false;
      budget_reported = true;
      return true;
    }



    template <int dim>
    void
    FaultRefinement<dim>::nothing_changed()
    {
      if (levels_now && any_active)
        levels_now->second = true;
    }



    template <int dim>
    double
    FaultRefinement<dim>::dofs_after_flags(const double n_dofs) const
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
      return n_dofs * (cells + change) / cells;
    }



    template class FaultRefinement<2>;
    template class FaultRefinement<3>;
  } // namespace Adaptivity
} // namespace rupture
