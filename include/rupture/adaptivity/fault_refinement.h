#ifndef rupture_adaptivity_fault_refinement_h
#define rupture_adaptivity_fault_refinement_h

#include <rupture/adaptivity/parameters.h>

#include <deal.II/base/point.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace rupture
{
  namespace Fault
  {
    template <int dim>
    class Fault;
  }

  namespace Adaptivity
  {
    template <int dim>
    class FrontCriterion;
    template <int dim>
    class ProcessZoneCriterion;
    template <int dim>
    class WavefieldCriterion;

    /**
     * Which cells a mesh that follows the rupture refines and coarsens
     * (the criteria of <Mesh refinement>: the rupture front, the process
     * zone, the wavefield), within which limits (the levels, the DoF budget),
     * and how many adaptations it made. It only flags cells: the caller
     * executes the refinement, carries the state over and sets everything up
     * again, then says so (mesh_changed()).
     *
     * By the fault's criteria, a cell at the fault is judged at its fault
     * faces (both cells of a face alike), a cell away from it at its centre
     * (only coarsened, to its base level: the level of the mesh as set up,
     * which @p base_level gives). The wavefield criterion judges every cell
     * by itself; a cell is refined if one criterion asks for it and
     * coarsened only if all allow it. Without a fault (@p fault null) only
     * the wavefield criterion can be chosen.
     */
    template <int dim>
    class FaultRefinement
    {
    public:
      using CellIterator = typename dealii::Triangulation<dim>::cell_iterator;

      FaultRefinement(
        const Parameters                                  &parameters,
        dealii::parallel::distributed::Triangulation<dim> &triangulation,
        const Fault::Fault<dim>                           *fault,
        std::function<unsigned int(const CellIterator &)>  base_level,
        const unsigned int                                 degree);

      ~FaultRefinement();

      /// The finest level of the fault's cells now, and whether an
      /// adaptation has refined one of them beyond its base level (or found
      /// nothing to refine while a node was active), over all processes.
      /// Collective; cached until mesh_changed().
      std::pair<unsigned int, bool>
      fault_levels() const;

      /// True when the mesh should be adapted between the regular times:
      /// no fault cell is refined beyond its base level yet (a rupture that
      /// starts without an overstressed patch, as rate-and-state nucleation
      /// does) and a fault node is active at @p phase_time. Collective.
      bool
      front_outside_fine_cells(const double phase_time) const;

      /**
       * Evaluate the criteria for the fault as it is now: its active nodes
       * at @p phase_time (with @p before_first_step also those that slip
       * from the start), the band ahead of them as far as a P wave of
       * @p p_wave_speed travels until the next adaptation (with steps of
       * @p time_step, which the explicit scheme halves once for every level
       * this adaptation adds beyond the finest now), the process zone.
       * Collective.
       */
      void
      evaluate(const double phase_time,
               const bool   before_first_step,
               const double p_wave_speed,
               const double time_step,
               const bool   explicit_scheme);

      /**
       * Evaluate the criterion "wavefield" on the mesh as it is now, from
       * the velocity @p velocity (with ghost entries) on @p dofs, with the
       * band that the last evaluate() found (call that first); the next
       * flag() uses it and then forgets it (it refines one level per
       * adaptation). Returns the largest indicator (1/s). Collective.
       */
      double
      evaluate_wavefield(const dealii::DoFHandler<dim>               &dofs,
                         const dealii::TrilinosWrappers::MPI::Vector &velocity);

      /**
       * Flag the cells for one level by the evaluated criteria, coarsening
       * only with @p coarsen, and prepare the flags (the mesh's balance);
       * a level whose estimated DoFs, from the @p n_dofs now, exceed the
       * budget is not flagged (budget_held()). Returns whether any cell is
       * flagged. Collective.
       */
      bool
      flag(const bool coarsen, const double n_dofs);

      /// Whether the last flag() held a level back for the budget.
      bool
      budget_held() const
      {
        return held;
      }

      /// True the first time the budget holds a level back (the run says
      /// so once).
      bool
      budget_newly_held();

      /// The mesh changed: what was cached for it goes.
      void
      mesh_changed()
      {
        levels_now.reset();
      }

      /// The evaluated criteria changed nothing: if a node was active,
      /// front_outside_fine_cells() asks again only once the mesh has
      /// changed.
      void
      nothing_changed();

      /// An adaptation that changed the mesh took @p seconds of wall time.
      void
      count(const double seconds)
      {
        ++adaptations;
        wall_seconds += seconds;
      }

      unsigned int
      n_adaptations() const
      {
        return adaptations;
      }

      double
      seconds() const
      {
        return wall_seconds;
      }

    private:
      /// The criterion "process zone" of the fault as it is now (the
      /// widths of all processes), or none without it. Collective.
      std::unique_ptr<ProcessZoneCriterion<dim>>
      process_zone_criterion() const;

      /// The finest level the cell @p cell may have at its fault face
      /// @p face: its base level plus <Levels>, or less where the process
      /// zone (taken @p margin times narrower) needs less.
      unsigned int
      finest_fault_level(const CellIterator &cell,
                         const unsigned int  face,
                         const double        margin = 1) const;

      /// Whether face @p f of @p cell lies on the fault (between its two
      /// sides).
      bool
      at_fault(const CellIterator &cell, const unsigned int f) const;

      /// The DoFs the mesh would have after the flags set now: @p n_dofs
      /// times the ratio of the cell counts. Collective.
      double
      dofs_after_flags(const double n_dofs) const;

      const Parameters                                  &parameters;
      dealii::parallel::distributed::Triangulation<dim> &triangulation;
      const Fault::Fault<dim>                           *fault;
      std::function<unsigned int(const CellIterator &)>  base_level;
      const unsigned int                                 degree;
      const MPI_Comm                                     communicator;

      /// What evaluate() found.
      std::unique_ptr<ProcessZoneCriterion<dim>> zone;
      std::unique_ptr<FrontCriterion<dim>>       front;
      std::unique_ptr<WavefieldCriterion<dim>>   wave;
      bool                                       any_active = false;
      /// The band around the cells that the wavefield refines (m).
      double wave_band = 0;

      mutable std::optional<std::pair<unsigned int, bool>> levels_now;
      bool                                                 held = false;
      bool         budget_reported                              = false;
      unsigned int adaptations                                  = 0;
      double       wall_seconds                                 = 0;
    };
  } // namespace Adaptivity
} // namespace rupture

#endif
