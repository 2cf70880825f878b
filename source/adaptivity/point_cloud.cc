#include <rupture/adaptivity/point_cloud.h>

#include <deal.II/numerics/rtree.h>

namespace rupture
{
  namespace Adaptivity
  {
    template <int dim>
    struct PointCloud<dim>::Tree
    {
      explicit Tree(const std::vector<dealii::Point<dim>> &points)
        : rtree(dealii::pack_rtree(points))
      {}

      dealii::RTree<dealii::Point<dim>> rtree;
    };



    template <int dim>
    PointCloud<dim>::PointCloud(const std::vector<dealii::Point<dim>> &points)
      : tree(std::make_unique<Tree>(points))
    {}



    template <int dim>
    PointCloud<dim>::~PointCloud() = default;



    template <int dim>
    bool
    PointCloud<dim>::any_within(const dealii::Point<dim> &x,
                                const double              r) const
    {
      // The nearest point decides.
      for (auto p = tree->rtree.qbegin(boost::geometry::index::nearest(x, 1));
           p != tree->rtree.qend();
           ++p)
        return p->distance(x) <= r;
      return false;
    }



    template class PointCloud<2>;
    template class PointCloud<3>;
  } // namespace Adaptivity
} // namespace rupture
