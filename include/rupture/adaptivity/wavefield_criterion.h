#ifndef rupture_adaptivity_wavefield_criterion_h
#define rupture_adaptivity_wavefield_criterion_h

#include <rupture/adaptivity/front_criterion.h>
#include <rupture/adaptivity/point_cloud.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace rupture
{
  namespace Adaptivity
  {
    /**
     * The criterion "wavefield", a Kelly-type indicator of how well the
     * cells resolve the moving wavefield: per cell, the root mean square
     * over its inner faces of the jump of the velocity's normal derivative
     * (1/s, a jump in strain rate). Faces between the fault's two sides
     * are left out (the displacement jumps there by design), and so are the
     * boundary's. A cell is refined where its indicator exceeds the
     * threshold, up to its finest level, and coarsened, never below its
     * base level, where its parent's indicator (estimated as 2^degree
     * times its own: the jump falls as h^degree) is below half the
     * threshold, so that a refined cell is not coarsened at once.
     * With a band (the distance a P wave travels until the next
     * adaptation), a cell within it of a cell whose wave needs a finer
     * level (one above the threshold: its level plus one; one that the
     * indicator keeps from coarsening: its own) is refined to that level,
     * and one within it of a cell whose wave needs its level is not
     * coarsened: the waves move on until the next adaptation, onto cells
     * that are fine already.
     */
    template <int dim>
    class WavefieldCriterion
    {
    public:
      /**
       * The indicators of the locally owned cells of @p dofs from the
       * velocity @p velocity (with ghost entries). Each cell's displacement
       * is the component group of its active FE index (its side of the
       * fault).
       */
      WavefieldCriterion(const dealii::DoFHandler<dim>               &dofs,
                         const dealii::TrilinosWrappers::MPI::Vector &velocity,
                         const double                                 threshold,
                         const double                                 band = 0);

      ~WavefieldCriterion();

      Decision
      decide(const typename dealii::Triangulation<dim>::cell_iterator &cell,
             const unsigned int base_level,
             const unsigned int finest_level) const;

      /// The largest indicator over all processes (1/s), for the log.
      double
      largest() const
      {
        return largest_indicator;
      }

    private:
      double                threshold;
      unsigned int          degree;
      dealii::Vector<float> indicator;
      double                largest_indicator = 0;
      /// needing[l]: the centres of the cells, of any process but within
      /// the band's reach of this process's cells, that hold a wave which
      /// needs level l or finer (a cell kept at its level by the indicator
      /// needs its level, one above the threshold the next); and how far
      /// from one of them a cell is in its band: the band plus half the
      /// largest of those cells' diameters.
      std::vector<std::unique_ptr<PointCloud<dim>>> needing;
      double                                        reach = 0;
    };
  } // namespace Adaptivity
} // namespace rupture

#endif
