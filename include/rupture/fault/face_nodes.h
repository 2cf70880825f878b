#ifndef rupture_fault_face_nodes_h
#define rupture_fault_face_nodes_h

#include <deal.II/base/point.h>

#include <array>
#include <vector>

namespace rupture
{
  namespace Fault
  {
    using namespace dealii;

    /**
     * The nodes of one fault face: the (p+1)^(dim-1) Gauss-Lobatto nodes of
     * FE_Q of degree p on a line (2-D) or a quadrilateral (3-D), numbered
     * lexicographically in the face's own coordinates, so that nodes 0 and
     * p (and p(p+1), (p+1)^2 - 1 in 3-D) are its corners. Stations
     * interpolate with these weights, and the fault surface output draws
     * each face as p (p^2) sub-cells between its nodes.
     */
    namespace FaceNodes
    {
      /// The degree p of a face with @p n_nodes nodes.
      template <int dim>
      unsigned int
      degree(const unsigned int n_nodes);

      /// The corners of a face of degree @p degree among its nodes.
      template <int dim>
      std::vector<unsigned int>
      corners(const unsigned int degree);

      /**
       * The face coordinates (in [0, 1]^(dim-1) on the face) of @p x on
       * the d-linear face with @p corners (lexicographic): the closest
       * point, by Newton's method on the d-linear map.
       */
      template <int dim>
      std::array<double, dim - 1>
      coordinates(const std::vector<Point<dim>> &corners, const Point<dim> &x);

      /// The point of face coordinates @p xi on the face with @p corners.
      template <int dim>
      Point<dim>
      point(const std::vector<Point<dim>>     &corners,
            const std::array<double, dim - 1> &xi);

      /**
       * The weights of the nodes (lexicographic) that interpolate at face
       * coordinates @p xi: products of the 1-D Lagrange polynomials through
       * the Gauss-Lobatto points of degree @p degree.
       */
      template <int dim>
      std::vector<double>
      weights(const unsigned int degree, const std::array<double, dim - 1> &xi);

      /**
       * The sub-cells of a face of degree @p degree, each as node numbers
       * in VTK order (segments in 2-D, quadrilaterals in 3-D).
       */
      template <int dim>
      std::vector<std::vector<unsigned int>>
      sub_cells(const unsigned int degree);
    } // namespace FaceNodes
  }   // namespace Fault
} // namespace rupture

#endif
