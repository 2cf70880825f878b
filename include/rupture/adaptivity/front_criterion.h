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
     *
     * Graded, a cell k levels below the finest is refined where a node
     * lies within k bands (and coarsened where none lies within 2 (k + 1)
     * bands): rings ahead of the band, one level coarser per band's width.
     * A front that travels at most a band between two adaptations then
     * finds each cell at most one level short, so that an adaptation needs
     * one new mesh, not one per level.
     */
    template <int dim>
    class FrontCriterion
    {
    public:
      /// @p active: the active nodes of the whole fault; @p band: the
      /// distance ahead of them that is refined (m); @p graded: rings of
      /// coarser cells beyond it.
      FrontCriterion(const std::vector<dealii::Point<dim>> &active,
                     const double                           band,
                     const bool                             graded = false)
        : band(band)
        , graded(graded)
        , cloud(active)
      {}

      Decision
      decide(const dealii::Point<dim> &where,
             const double              size,
             const unsigned int        level,
             const unsigned int        base_level,
             const unsigned int        finest_level) const
      {
        // The bands' widths that a cell of this level sees: k for refining
        // it, k + 1 for coarsening it (1 and 1 without grading).
        const int    short_of     = static_cast<int>(finest_level) - int(level);
        const double refine_bands = graded ? std::max(short_of, 1) : 1;
        const double keep_bands   = graded ? std::max(short_of + 1, 1) : 1;
        if (level < finest_level &&
            cloud.any_within(where, refine_bands * band + 0.5 * size))
          return Decision::refine;
        if (level > base_level &&
            !cloud.any_within(where, 2 * keep_bands * band + 2 * size))
          return Decision::coarsen;
        return Decision::keep;
      }

    private:
      double          band;
      bool            graded;
      PointCloud<dim> cloud;
    };
  } // namespace Adaptivity
} // namespace rupture

#endif
