#ifndef rupture_adaptivity_point_cloud_h
#define rupture_adaptivity_point_cloud_h

#include <deal.II/base/point.h>

#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace rupture
{
  namespace Adaptivity
  {
    /**
     * A set of points binned in cubes of a given size, for the question
     * "is one of them within the distance r of x?" in time proportional to
     * the points of the (r / size)^dim bins around x.
     */
    template <int dim>
    class PointCloud
    {
    public:
      PointCloud(const std::vector<dealii::Point<dim>> &points,
                 const double                           bin_size)
        : size(bin_size > 0 ? bin_size : 1.)
      {
        for (const auto &p : points)
          bins[key(p)].push_back(p);
      }

      bool
      empty() const
      {
        return bins.empty();
      }

      /// Whether a point of the set lies within @p r of @p x.
      bool
      any_within(const dealii::Point<dim> &x, const double r) const
      {
        if (bins.empty())
          return false;
        const long reach = static_cast<long>(std::ceil(r / size));
        const std::array<long, dim> centre = key(x);
        std::array<long, dim>       k      = centre;
        // Every bin of the cube of side 2 reach + 1 around x.
        long n = 1;
        for (unsigned int d = 0; d < dim; ++d)
          n *= 2 * reach + 1;
        for (long i = 0; i < n; ++i)
          {
            long rest = i;
            for (unsigned int d = 0; d < dim; ++d)
              {
                k[d] = centre[d] + rest % (2 * reach + 1) - reach;
                rest /= 2 * reach + 1;
              }
            const auto b = bins.find(k);
            if (b != bins.end())
              for (const auto &p : b->second)
                if (p.distance(x) <= r)
                  return true;
          }
        return false;
      }

    private:
      std::array<long, dim>
      key(const dealii::Point<dim> &p) const
      {
        std::array<long, dim> k;
        for (unsigned int d = 0; d < dim; ++d)
          k[d] = static_cast<long>(std::floor(p[d] / size));
        return k;
      }

      double                                                           size;
      std::map<std::array<long, dim>, std::vector<dealii::Point<dim>>> bins;
    };
  } // namespace Adaptivity
} // namespace rupture

#endif
