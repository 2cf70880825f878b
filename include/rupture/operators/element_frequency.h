#ifndef rupture_operators_element_frequency_h
#define rupture_operators_element_frequency_h

#include <rupture/material/elastic_material.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace rupture
{
  namespace Operators
  {
    using namespace dealii;

    /**
     * The element eigenvalue problem K x = omega^2 M x of linear isotropic
     * elasticity with the Gauss-Lobatto lumped mass M, for cells that are
     * axis-aligned boxes, assembled without quadrature. On a box of edge
     * lengths h_b the gradient along b is that of the unit cell divided by
     * h_b, and the volume factor cancels between K and M, so
     *
     *   M^-1/2 K M^-1/2 = (lambda d_a d_c S^ac + mu d_a d_c S^ca
     *                      + mu delta_ac sum_b d_b^2 S^bb) / rho
     *
     * in the block of components (a, c), with d_b = 1/h_b and S^bd the
     * unit cell's integrals of the derivatives along b and d of two shape
     * functions, scaled by the square roots of their lumped masses. These
     * dim^2 matrices are computed once per degree; a cell then costs a few
     * scaled additions instead of a quadrature over (p+1)^dim points, which
     * is what made the stable step of degree 4 on a graded mesh (thousands
     * of distinct cell shapes) take minutes.
     */
    template <int dim>
    class BoxElementFrequency
    {
    public:
      /// The unit cell's matrices for elements FE_Q(@p degree)^dim.
      explicit BoxElementFrequency(const unsigned int degree);

      /// M^-1/2 K M^-1/2 of a box with edge lengths @p h (dim (p+1)^dim
      /// rows, component by component; the order does not change
      /// eigenvalues).
      void
      scaled_matrix(const Tensor<1, dim>             &h,
                    const Material::ElasticConstants &material,
                    LAPACKFullMatrix<double>         &a) const;

    private:
      unsigned int n_nodes;
      /// S^bd scaled by the lumped masses (see the class description).
      std::array<std::array<FullMatrix<double>, dim>, dim> s;
    };

    /**
     * The explicit scheme's highest frequency by Irons' bound: the
     * highest frequency of the assembled system (lumped mass) is below the
     * highest of its elements, so the step computed from it is safe on any
     * mesh. One element eigenvalue problem per distinct cell shape, and
     * the shapes are remembered from one mesh to the next.
     */
    template <int dim>
    class ElementFrequencies
    {
    public:
      /**
       * The highest element frequency (rad/s) over the locally owned cells
       * of @p dof_handler on all processes of @p communicator, for
       * elements FE_Q(@p degree)^dim (one field per side of a fault) of
       * the cells' @p materials.
       */
      double
      highest(const DoFHandler<dim>            &dof_handler,
              const Material::ElasticMaterials &materials,
              const unsigned int                degree,
              const MPI_Comm                    communicator);

    private:
      /// The length unit of the shape keys (fixed by the first mesh).
      double unit = 0;
      /// An upper bound of the largest squared frequency of each shape.
      std::map<std::vector<std::int64_t>, double> omega2;
    };



    /**
     * Gershgorin's bound of the largest eigenvalue of the symmetric
     * matrix @p a: the largest sum of a row's absolute values.
     */
    double
    gershgorin_bound(const LAPACKFullMatrix<double> &a);

    /**
     * The largest eigenvalue of the symmetric matrix @p a if it exceeds
     * @p floor, else @p floor. Only the eigenvalues between @p floor and
     * Gershgorin's bound are computed.
     */
    double
    largest_eigenvalue_above(LAPACKFullMatrix<double> &a, const double floor);

    /**
     * The edge lengths of a cell whose vertices are those of an
     * axis-aligned box (to 1e-12 of its size; vertex v at vertex 0 plus
     * the edges whose bits v has, deal.II's numbering), else nothing.
     */
    template <int dim>
    std::optional<Tensor<1, dim>>
    box_edges(const std::array<Point<dim>, (1u << dim)> &vertices);
  } // namespace Operators
} // namespace rupture

#endif
