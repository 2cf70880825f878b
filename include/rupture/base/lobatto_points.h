#ifndef rupture_base_lobatto_points_h
#define rupture_base_lobatto_points_h

#include <vector>

namespace rupture
{
  /**
   * The Gauss-Lobatto points on [0, 1]: the 1-D node coordinates of FE_Q
   * of a degree, which the fault's face nodes and the volume output's
   * sub-cells share.
   */
  namespace LobattoPoints
  {
    /// The points of degree @p degree (degree + 1 of them, from 0 to 1).
    std::vector<double>
    points(const unsigned int degree);

    /// The index (0..degree) of the point of degree @p degree nearest to
    /// the coordinate @p xi.
    unsigned int
    nearest(const unsigned int degree, const double xi);
  } // namespace LobattoPoints
} // namespace rupture

#endif
