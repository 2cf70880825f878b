// What the fault-only solver's finite-element bodies share.

#include <rupture/boundary_integral/finite_element_grid.h>
#include <rupture/boundary_integral/text.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <string>

namespace rupture
{
  namespace BoundaryIntegral
  {
    namespace FiniteElementGrid
    {
      using dealii::ExcMessage;

      std::vector<double>
      graded(const double first, const double growth, const double length)
      {
        std::vector<double> sizes;
        double              sum = 0, size = first;
        while (sum < length * (1 - 1e-12))
          {
            sizes.push_back(size);
            sum += size;
            size *= growth;
          }
        return sizes;
      }



      double
      check(const double extent,
            const int    degree,
            const double node_spacing,
            const double domain_size,
            const double growth)
      {
        const double W = extent, p = degree;
        AssertThrow(std::isfinite(W) && W > 0,
                    ExcMessage("<Boundary integral/Fault depth> is " +
                               number(W) + ", but it must be > 0 (m)."));
        AssertThrow(degree >= 1 && degree <= 4,
                    ExcMessage("<Boundary integral/Finite-element degree> "
                               "is " +
                               std::to_string(degree) +
                               ", but it must be 1, 2, 3 or 4."));
        AssertThrow(std::isfinite(node_spacing) && node_spacing > 0 &&
                      p * node_spacing <= W,
                    ExcMessage("<Boundary integral/Element size> is " +
                               number(node_spacing) +
                               ", but with finite elements it must be > 0 "
                               "and at most <Fault depth> / <Finite-element "
                               "degree> (m: the node spacing on the "
                               "fault)."));
        AssertThrow(std::isfinite(domain_size) && domain_size >= 2 * W,
                    ExcMessage("<Boundary integral/Domain size> is " +
                               number(domain_size) +
                               ", but it must be at least twice <Fault "
                               "depth> (m)."));
        AssertThrow(growth > 1 && growth <= 2,
                    ExcMessage("<Boundary integral/Cell growth factor> is " +
                               number(growth) +
                               ", but it must be > 1 and at most 2."));
        return std::ceil(W / (p * node_spacing) - 1e-9);
      }
    } // namespace FiniteElementGrid
  }   // namespace BoundaryIntegral
} // namespace rupture
