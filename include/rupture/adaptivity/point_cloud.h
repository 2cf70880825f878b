#ifndef rupture_adaptivity_point_cloud_h
#define rupture_adaptivity_point_cloud_h

#include <deal.II/base/point.h>

#include <memory>
#include <vector>

namespace rupture
{
  namespace Adaptivity
  {
    /**
     * A set of points for the question "is one of them within the distance
     * r of x?", asked for every cell of the mesh at each adaptation: the
     * points are packed in an R-tree (deal.II's pack_rtree()), so that a
     * question costs the logarithm of their number, whatever r is (source
     * in point_cloud.cc, to keep Boost's geometry out of the headers).
     */
    template <int dim>
    class PointCloud
    {
    public:
      explicit PointCloud(const std::vector<dealii::Point<dim>> &points);
      ~PointCloud();

      /// Whether a point of the set lies within @p r of @p x.
      bool
      any_within(const dealii::Point<dim> &x, const double r) const;

    private:
      struct Tree;
      std::unique_ptr<Tree> tree;
    };
  } // namespace Adaptivity
} // namespace rupture

#endif
