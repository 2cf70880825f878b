#ifndef rupture_adaptivity_parameters_h
#define rupture_adaptivity_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <string>

namespace rupture
{
  /**
   * A mesh that changes during the run: which cells are refined and
   * coarsened (the criteria), how often and how far.
   */
  namespace Adaptivity
  {
    /**
     * The subsection <Mesh refinement>.
     */
    struct Parameters
    {
      /// <Criteria> contains "rupture front": refine the cells of the fault
      /// where it slips and in a band ahead of the front, coarsen them
      /// once it has healed.
      bool follow_front = false;
      /// <Criteria> contains "process zone": the fault's cells are refined
      /// until <Nodes per process zone> node spacings fit into the friction
      /// law's process zone (with "rupture front": that deep only).
      bool process_zone = false;
      /// <Criteria> contains "wavefield": the cells are refined where the
      /// velocity's normal derivative jumps across their faces by more
      /// than <Wavefield threshold> (WavefieldCriterion).
      bool wavefield = false;
      /// The jump (root mean square over a cell's faces) in 1/s above
      /// which "wavefield" refines a cell.
      double wavefield_threshold = 1e-3;
      /// Levels above the base mesh that "wavefield" refines to.
      unsigned int wavefield_levels = 1;
      /// "wavefield" also refines the band around the cells above the
      /// threshold that a P wave crosses until the next adaptation.
      bool wavefield_band = true;
      /// Steps between two adaptations of the mesh.
      unsigned int interval = 10;
      /// Time between two adaptations (s); 0: <Interval> steps.
      double time_interval = 0;
      /// Node spacings per process-zone width.
      double nodes_per_zone = 3;
      /// No refinement that would take the DoFs above it; 0: no limit.
      double max_dofs = 0;
      /// Levels above the base mesh (global refinements and the static
      /// refinement region) that the front's cells get.
      unsigned int levels = 1;
      /// A fault node whose slip rate is above it is slipping (m/s).
      double slip_rate_threshold = 1e-3;
      /// The time after a node's rupture during which it counts as active
      /// although it slips slower (s); negative: for ever (no coarsening).
      double coarsening_delay = -1;
      /// Added to the band ahead of the front (m).
      double extra_band = 0;
      /// The cells ahead of the band are refined in rings, one level less
      /// per band's width (FrontCriterion).
      bool graded_band = false;
      /// After each adaptation in an implicit dynamic phase that follows a
      /// loading phase: move the displacement into balance on the new mesh
      /// (TimeIntegration::Interface::balance_displacement()).
      bool balance = true;

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      bool
      enabled() const
      {
        return follow_front || process_zone || wavefield;
      }

      /// Whether the mesh is adapted after step @p step of a phase (its
      /// number in the run), which ended at @p phase_time (s) after a step
      /// of @p time_step: every <Interval> steps, or with <Time interval>
      /// when the step crossed a multiple of it.
      bool
      due(const unsigned int step,
          const double       phase_time,
          const double       time_step) const;

      /// The time until the next adaptation, for the band ahead of the
      /// front: <Time interval>, or <Interval> steps of @p time_step.
      double
      time_to_next(const double time_step) const
      {
        return time_interval > 0 ? std::max(time_interval, time_step) :
                                   interval * time_step;
      }
    };
  } // namespace Adaptivity
} // namespace rupture

#endif
