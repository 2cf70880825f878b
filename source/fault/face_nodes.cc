// The Gauss-Lobatto nodes of one fault face: coordinates, interpolation
// weights and sub-cells, for faces of any degree.

#include <rupture/base/lobatto_points.h>
#include <rupture/fault/face_nodes.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <cmath>

namespace rupture
{
  namespace Fault
  {
    namespace FaceNodes
    {
      namespace
      {
        /// The Lagrange polynomials through @p nodes, at @p x.
        std::vector<double>
        lagrange(const std::vector<double> &nodes, const double x)
        {
          std::vector<double> l(nodes.size(), 1.);
          for (unsigned int i = 0; i < nodes.size(); ++i)
            for (unsigned int j = 0; j < nodes.size(); ++j)
              if (j != i)
                l[i] *= (x - nodes[j]) / (nodes[i] - nodes[j]);
          return l;
        }
      } // namespace



      template <int dim>
      unsigned int
      degree(const unsigned int n_nodes)
      {
        const unsigned int p =
          (dim == 2) ? n_nodes - 1 :
                       static_cast<unsigned int>(
                         std::lround(std::sqrt(static_cast<double>(n_nodes)))) -
                         1;
        AssertThrow(p >= 1 && (dim == 2 ? p + 1 : (p + 1) * (p + 1)) == n_nodes,
                    ExcInternalError());
        return p;
      }



      template <int dim>
      std::vector<unsigned int>
      corners(const unsigned int degree)
      {
        if (dim == 2)
          return {0, degree};
        const unsigned int n = degree + 1;
        return {0, degree, degree * n, n * n - 1};
      }



      template <int dim>
      Point<dim>
      point(const std::vector<Point<dim>>     &corners,
            const std::array<double, dim - 1> &xi)
      {
        if (dim == 2)
          return Point<dim>(corners[0] * (1 - xi[0]) + corners[1] * xi[0]);
        const double e = xi[dim - 2];
        return Point<dim>(corners[0] * ((1 - xi[0]) * (1 - e)) +
                          corners[1] * (xi[0] * (1 - e)) +
                          corners[2] * ((1 - xi[0]) * e) +
                          corners[3] * (xi[0] * e));
      }



      template <int dim>
      std::array<double, dim - 1>
      coordinates(const std::vector<Point<dim>> &corners, const Point<dim> &x)
      {
        std::array<double, dim - 1> xi{};
        if (dim == 2)
          {
            const Tensor<1, dim> e = corners[1] - corners[0];
            xi[0]                  = (x - corners[0]) * e / e.norm_square();
            return xi;
          }
        // Gauss-Newton on the bilinear map (exact in one step for a
        // parallelogram).
        double &a = xi[0], &b = xi[dim - 2];
        for (unsigned int it = 0; it < 20; ++it)
          {
            const Tensor<1, dim> da = (corners[1] - corners[0]) * (1 - b) +
                                      (corners[3] - corners[2]) * b;
            const Tensor<1, dim> db = (corners[2] - corners[0]) * (1 - a) +
                                      (corners[3] - corners[1]) * a;
            const Tensor<1, dim> r  = x - point<dim>(corners, xi);
            const double         aa = da * da, ab = da * db, bb = db * db;
            const double         det = aa * bb - ab * ab;
            a += (bb * (da * r) - ab * (db * r)) / det;
            b += (aa * (db * r) - ab * (da * r)) / det;
          }
        return xi;
      }



      template <int dim>
      std::vector<double>
      weights(const unsigned int degree, const std::array<double, dim - 1> &xi)
      {
        const std::vector<double> nodes = LobattoPoints::points(degree);
        const std::vector<double> la    = lagrange(nodes, xi[0]);
        if (dim == 2)
          return la;
        const std::vector<double> lb = lagrange(nodes, xi[dim - 2]);
        std::vector<double>       w;
        for (unsigned int j = 0; j <= degree; ++j)
          for (unsigned int i = 0; i <= degree; ++i)
            w.push_back(la[i] * lb[j]);
        return w;
      }



      template <int dim>
      std::vector<std::vector<unsigned int>>
      sub_cells(const unsigned int degree)
      {
        std::vector<std::vector<unsigned int>> cells;
        const unsigned int                     n = degree + 1;
        for (unsigned int j = 0; j < (dim == 2 ? 1 : degree); ++j)
          for (unsigned int i = 0; i < degree; ++i)
            if (dim == 2)
              cells.push_back({i, i + 1});
            else
              cells.push_back({j * n + i,
                               j * n + i + 1,
                               (j + 1) * n + i + 1,
                               (j + 1) * n + i});
        return cells;
      }



      template unsigned int
      degree<2>(unsigned int);
      template unsigned int
      degree<3>(unsigned int);
      template std::vector<unsigned int>
      corners<2>(unsigned int);
      template std::vector<unsigned int>
      corners<3>(unsigned int);
      template Point<2>
      point<2>(const std::vector<Point<2>> &, const std::array<double, 1> &);
      template Point<3>
      point<3>(const std::vector<Point<3>> &, const std::array<double, 2> &);
      template std::array<double, 1>
      coordinates<2>(const std::vector<Point<2>> &, const Point<2> &);
      template std::array<double, 2>
      coordinates<3>(const std::vector<Point<3>> &, const Point<3> &);
      template std::vector<double>
      weights<2>(unsigned int, const std::array<double, 1> &);
      template std::vector<double>
      weights<3>(unsigned int, const std::array<double, 2> &);
      template std::vector<std::vector<unsigned int>>
      sub_cells<2>(unsigned int);
      template std::vector<std::vector<unsigned int>>
      sub_cells<3>(unsigned int);
    } // namespace FaceNodes
  }   // namespace Fault
} // namespace rupture
