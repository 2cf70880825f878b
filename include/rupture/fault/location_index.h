#ifndef rupture_fault_location_index_h
#define rupture_fault_location_index_h

#include <deal.II/base/point.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace rupture
{
  namespace Fault
  {
    using dealii::Point;

    /**
     * The identity of fault nodes by location: finds, for a point, the
     * stored point within a tolerance of it (the nearest if several are).
     * A node pair keeps its identity across set-ups and checkpoints by its
     * location, not by its DoF indices, which change with the mesh and
     * the number of processes.
     *
     * Points are binned in cubes of twice the tolerance, so a search looks
     * at the 3^dim bins around a point: found whatever the round-off in
     * the coordinates, as long as it stays below the tolerance.
     */
    template <int dim>
    class LocationIndex
    {
    public:
      static constexpr unsigned int invalid =
        std::numeric_limits<unsigned int>::max();

      /**
       * Index @p points (their positions in the vector are what find()
       * returns) with the tolerance @p tolerance (m, > 0).
       */
      LocationIndex(const std::vector<Point<dim>> &points,
                    const double                   tolerance)
        : points(points)
        , tolerance(tolerance)
        , bin_size(2 * tolerance)
      {
        for (unsigned int i = 0; i < points.size(); ++i)
          bins[bin_of(points[i])].push_back(i);
      }

      /**
       * The index of the stored point nearest to @p p within the
       * tolerance, or @p invalid if there is none.
       */
      unsigned int
      find(const Point<dim> &p) const
      {
        const Key    centre = bin_of(p);
        unsigned int best   = invalid;
        double       best_d = tolerance;
        for (unsigned int n = 0; n < n_neighbours; ++n)
          {
            Key          key  = centre;
            unsigned int code = n;
            for (unsigned int d = 0; d < dim; ++d, code /= 3)
              key[d] += static_cast<long long>(code % 3) - 1;
            const auto at = bins.find(key);
            if (at == bins.end())
              continue;
            for (const unsigned int i : at->second)
              {
                const double distance = points[i].distance(p);
                if (distance <= best_d)
                  {
                    best_d = distance;
                    best   = i;
                  }
              }
          }
        return best;
      }

    private:
      using Key = std::array<long long, dim>;
      static constexpr unsigned int n_neighbours =
        (dim == 1 ? 3 : (dim == 2 ? 9 : 27));

      Key
      bin_of(const Point<dim> &p) const
      {
        Key key;
        for (unsigned int d = 0; d < dim; ++d)
          key[d] = static_cast<long long>(std::floor(p[d] / bin_size));
        return key;
      }

      std::vector<Point<dim>>              points;
      double                               tolerance;
      double                               bin_size;
      std::map<Key, std::vector<unsigned>> bins;
    };
  } // namespace Fault
} // namespace rupture

#endif
