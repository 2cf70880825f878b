#ifndef rupture_adaptivity_parameters_h
#define rupture_adaptivity_parameters_h

#include <deal.II/base/parameter_handler.h>

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
      /// Steps between two adaptations of the mesh.
      unsigned int interval = 10;
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

      static void
      declare_parameters(dealii::ParameterHandler &prm);
      void
      parse_parameters(dealii::ParameterHandler &prm);

      bool
      enabled() const
      {
        return follow_front;
      }
    };
  } // namespace Adaptivity
} // namespace rupture

#endif
