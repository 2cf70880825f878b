#ifndef rupture_adaptivity_process_zone_criterion_h
#define rupture_adaptivity_process_zone_criterion_h

#include <deal.II/base/point.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace rupture
{
  namespace Adaptivity
  {
    /**
     * The criterion "process zone": a fault face is fine enough when
     * <Nodes per process zone> of its node spacings (its edge divided by
     * the polynomial degree) fit into the narrowest process zone
     * (Friction::Interface::process_zone_width()) of the fault nodes within
     * an edge of its centre. Each level halves the spacing, so the level a
     * face needs follows from the ratio of the two lengths.
     */
    template <int dim>
    class ProcessZoneCriterion
    {
    public:
      /**
       * @p widths: fault nodes with a finite process-zone width (m), of the
       * whole fault (or their binned() summary). The widths are kept per
       * cube of side @p bin_size (the narrowest in each): a face is judged
       * by the cubes that the face itself touches, so cubes as large as
       * the smallest fault face of the base mesh keep that to a few cubes
       * there and resolve the zone's changes (a strength barrier's edge)
       * as finely as the base mesh does.
       */
      ProcessZoneCriterion(
        const std::vector<std::pair<dealii::Point<dim>, double>> &widths,
        const double                                              bin_size,
        const double       nodes_per_zone,
        const unsigned int degree)
        : size(bin_size > 0 ? bin_size : 1.)
        , nodes_per_zone(nodes_per_zone)
        , degree(degree)
      {
        for (const auto &[x, w] : widths)
          {
            const auto key = key_of(x);
            const auto at  = bins.find(key);
            if (at == bins.end())
              bins[key] = w;
            else
              at->second = std::min(at->second, w);
          }
      }

      /// The narrowest width in each cube, at the cube's centre: what one
      /// process contributes to the criterion of the whole fault.
      std::vector<std::pair<dealii::Point<dim>, double>>
      binned() const
      {
        std::vector<std::pair<dealii::Point<dim>, double>> v;
        for (const auto &[key, w] : bins)
          {
            dealii::Point<dim> centre;
            for (unsigned int d = 0; d < dim; ++d)
              centre[d] = (key[d] + 0.5) * size;
            v.emplace_back(centre, w);
          }
        return v;
      }

      /// The narrowest width of the cubes that the box of half-side @p r
      /// around @p x touches; infinite where there are none.
      double
      narrowest(const dealii::Point<dim> &x, const double r) const
      {
        double                w = std::numeric_limits<double>::infinity();
        std::array<long, dim> low, high, k;
        for (unsigned int d = 0; d < dim; ++d)
          {
            low[d]  = static_cast<long>(std::floor((x[d] - r) / size));
            high[d] = static_cast<long>(std::floor((x[d] + r) / size));
          }
        k = low;
        while (true)
          {
            const auto at = bins.find(k);
            if (at != bins.end())
              w = std::min(w, at->second);
            unsigned int d = 0;
            for (; d < dim; ++d)
              if (++k[d] <= high[d])
                break;
              else
                k[d] = low[d];
            if (d == dim)
              break;
          }
        return w;
      }

      /**
       * The level at which a face of edge @p edge (m) at @p level, centred
       * at @p centre, has <Nodes per process zone> node spacings in the
       * narrowest zone of the cubes it touches, the zone taken @p margin times
       * narrower (a margin above 1 for coarsening: a cell coarsens only when
       * its parent is fine enough with room to spare). Below @p level where the
       * face is finer than it needs; -1 where no node near it weakens.
       */
      int
      level_needed(const dealii::Point<dim> &centre,
                   const double              edge,
                   const unsigned int        level,
                   const double              margin = 1) const
      {
        const double w = narrowest(centre, 0.5 * edge);
        if (!std::isfinite(w))
          return -1;
        const double spacing = edge / degree;
        const double wanted  = w / (nodes_per_zone * margin);
        if (!(wanted > 0))
          return std::numeric_limits<int>::max();
        // The smallest k with spacing / 2^k <= wanted (a relative 1e-9 of
        // room: a spacing that equals the wanted one is fine).
        const double k = std::ceil(std::log2(spacing / wanted) - 1e-9);
        return static_cast<int>(std::clamp(k + level, 0., 1e6));
      }

    private:
      std::array<long, dim>
      key_of(const dealii::Point<dim> &p) const
      {
        std::array<long, dim> k;
        for (unsigned int d = 0; d < dim; ++d)
          k[d] = static_cast<long>(std::floor(p[d] / size));
        return k;
      }

      double                                  size;
      double                                  nodes_per_zone;
      unsigned int                            degree;
      std::map<std::array<long, dim>, double> bins;
    };
  } // namespace Adaptivity
} // namespace rupture

#endif
