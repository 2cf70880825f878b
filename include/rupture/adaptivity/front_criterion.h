#ifndef rupture_adaptivity_front_criterion_h
#define rupture_adaptivity_front_criterion_h

#include <rupture/adaptivity/point_cloud.h>

#include <deal.II/base/point.h>

#include <algorithm>
#include <vector>

namespace rupture
{
  namespace Adaptivity
  {
    /// What a cell should do at an adaptation of the mesh.
    enum class Decision
    {
      keep,
      refine,
      coarsen
    };

    /**
     * The criterion "rupture front": a cell of the fault (judged at the
     * centre of its fault face, which both cells of the face share, so that
     * both sides are refined alike) is refined up to the finest level
     * where an active fault node lies within the band (plus half the
     * face's size), and coarsened, down to its base level, where none lies
     * within twice the band plus twice its size: the gap between the two
     * keeps a cell from being refined and coarsened in turn.
     */
    template <int dim>
    class FrontCriterion
    {
    public:
      /// @p active: the active nodes of the whole fault; @p band: the
      /// distance ahead of them that is refined (m).
      FrontCriterion(const std::vector<dealii::Point<dim>> &active,
                     const double                           band)
        : band(band)
        , cloud(active)
      {}

      Decision
      decide(const dealii::Point<dim> &where,
             const double              size,
             const unsigned int        level,
             const unsigned int        base_level,
             const unsigned int        finest_level) const
      {
        if (level < finest_level && cloud.any_within(where, band + 0.5 * size))
          return Decision::refine;
        if (level > base_level && !cloud.any_within(where, 2 * band + 2 * size))
          return Decision::coarsen;
        return Decision::keep;
      }

    private:
      double          band;
      PointCloud<dim> cloud;
    };
  } // namespace Adaptivity
} // namespace rupture

#endif
