#ifndef rupture_boundary_integral_finite_element_grid_h
#define rupture_boundary_integral_finite_element_grid_h

#include <vector>

namespace rupture
{
  namespace BoundaryIntegral
  {
    /**
     * What the finite-element bodies of the fault-only solver
     * (AntiplaneFiniteElements, PlaneStrainFiniteElements) share: their
     * graded grids and the checks of the settings that make them.
     */
    namespace FiniteElementGrid
    {
      /// Cell sizes from @p first growing by @p growth until they add up to
      /// at least @p length.
      std::vector<double>
      graded(const double first, const double growth, const double length);

      /**
       * Check the fault's extent @p extent (m), the polynomial @p degree
       * (1 to 4), the @p node_spacing on the fault (m, at most extent /
       * degree), the box's @p domain_size (m, at least twice the extent)
       * and the cells' @p growth (in (1, 2]); the messages name the
       * <Boundary integral> entries. Returns the number of cells along the
       * fault down to the extent.
       */
      double
      check(const double extent,
            const int    degree,
            const double node_spacing,
            const double domain_size,
            const double growth);
    } // namespace FiniteElementGrid
  }   // namespace BoundaryIntegral
} // namespace rupture

#endif
