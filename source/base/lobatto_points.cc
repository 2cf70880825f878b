#include <rupture/base/lobatto_points.h>

#include <deal.II/base/quadrature_lib.h>

#include <cmath>

namespace rupture
{
  namespace LobattoPoints
  {
    std::vector<double>
    points(const unsigned int degree)
    {
      std::vector<double> x;
      if (degree == 1)
        return {0., 1.};
      const dealii::QGaussLobatto<1> q(degree + 1);
      for (unsigned int i = 0; i <= degree; ++i)
        x.push_back(q.point(i)[0]);
      return x;
    }



    unsigned int
    nearest(const unsigned int degree, const double xi)
    {
      const std::vector<double> nodes = points(degree);
      unsigned int              best  = 0;
      for (unsigned int i = 1; i <= degree; ++i)
        if (std::abs(nodes[i] - xi) < std::abs(nodes[best] - xi))
          best = i;
      return best;
    }
  } // namespace LobattoPoints
} // namespace rupture
