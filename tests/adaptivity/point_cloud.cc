// The point cloud that the rupture-front criterion asks "is an active fault
// node within r of x?" for every cell: against the question answered point
// by point, for points on a plane (as a fault's nodes are) and points in a
// volume, 2-D and 3-D, for radii from far below to far above the points'
// spacing, and for an empty set.

#include <rupture/adaptivity/point_cloud.h>

#include <iostream>
#include <random>
#include <vector>

namespace
{
  template <int dim>
  bool
  brute_force(const std::vector<dealii::Point<dim>> &points,
              const dealii::Point<dim>              &x,
              const double                           r)
  {
    for (const auto &p : points)
      if (p.distance(x) <= r)
        return true;
    return false;
  }



  template <int dim>
  void
  check(const bool planar)
  {
    std::mt19937                           random(42);
    std::uniform_real_distribution<double> coordinate(-1000., 1000.);
    std::vector<dealii::Point<dim>>        points(500);
    for (auto &p : points)
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = (planar && d == 1) ? 0. : coordinate(random);
    const rupture::Adaptivity::PointCloud<dim> cloud(points);

    unsigned int asked = 0, disagree = 0, within = 0;
    for (const double r : {0., 1., 10., 50., 200., 1000., 5000.})
      for (unsigned int k = 0; k < 400; ++k)
        {
          dealii::Point<dim> x;
          for (unsigned int d = 0; d < dim; ++d)
            x[d] = 1.5 * coordinate(random);
          // Some questions at a point of the set itself.
          if (k % 10 == 0)
            x = points[k % points.size()];
          const bool answer = cloud.any_within(x, r);
          ++asked;
          within += answer;
          disagree += answer != brute_force(points, x, r);
        }
    std::cout << dim << "-D, points " << (planar ? "on a plane" : "in a volume")
              << ": " << asked << " questions, " << within
              << " with a point within r, " << disagree
              << " answered otherwise than point by point" << std::endl;

    const rupture::Adaptivity::PointCloud<dim> none({});
    std::cout << "   empty set: a point within 1e9 m of the origin: "
              << (none.any_within(dealii::Point<dim>(), 1e9) ? "yes" : "no")
              << std::endl;
  }
} // namespace



int
main()
{
  check<2>(true);
  check<2>(false);
  check<3>(true);
  check<3>(false);
}
