#ifndef rupture_operators_elastic_operator_h
#define rupture_operators_elastic_operator_h

#include <rupture/material/elastic_material.h>

#include <deal.II/base/vectorization.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <functional>
#include <memory>
#include <string>

namespace rupture
{
  namespace Operators
  {
    using namespace dealii;

    /**
     * The stiffness operator of linear isotropic elasticity, K x, applied
     * without a stored matrix: deal.II's MatrixFree and FEEvaluation with
     * sum factorisation, on the displacement field of the simulator (plain
     * FE_Q^dim, or the hp field with one FESystem per side of a fault, in
     * which component s*dim + c is component c on side s).
     *
     * The product is that of the condensed matrix C^T K C: the values of
     * constrained DoFs (hanging nodes, welded fault nodes) are taken from
     * their constraints, their rows of the result are zero. This is what
     * the stored matrix, assembled through the same constraints, gives
     * too (up to its placeholder diagonal in constrained rows).
     *
     * It works on degrees 1 to 4 with kernels compiled for each (other
     * degrees through a slower generic path),
     * in 2-D and 3-D, on affine and general hexahedra (MatrixFree stores
     * one Jacobian per cell for affine cells and one per quadrature point
     * otherwise) and with hanging nodes. The implementation is hidden in
     * elastic_operator.cc, so that this header stays cheap to include.
     */
    template <int dim>
    class ElasticOperator
    {
    public:
      using VectorType = LinearAlgebra::distributed::Vector<double>;

      ElasticOperator();
      ~ElasticOperator();

      /**
       * Set up for @p dof_handler (its active FE indices are the sides of
       * a fault), with the constraints @p constraints (on the locally
       * relevant DoFs, closed) and the Lame constants of each cell's
       * material id. @p fe_degree is the degree of FE_Q.
       */
      void
      reinit(const Mapping<dim>               &mapping,
             const DoFHandler<dim>            &dof_handler,
             const AffineConstraints<double>  &constraints,
             const Material::ElasticMaterials &materials,
             const unsigned int                fe_degree);

      /// Size @p v for this operator (owned and ghost DoFs).
      void
      initialize_dof_vector(VectorType &v) const;

      /// dst = K src. @p src must have been sized by initialize_dof_vector().
      void
      vmult(VectorType &dst, const VectorType &src) const;

      /**
       * dst = stiffness_factor K src + mass_factor M src in one pass over
       * the cells, M the consistent mass matrix (Gauss quadrature, the
       * density of each cell's material): the effective stiffness of an
       * implicit Newmark step without a stored matrix.
       */
      void
      vmult(VectorType       &dst,
            const VectorType &src,
            const double      stiffness_factor,
            const double      mass_factor) const;

      /**
       * Mark the cells of a Kelvin-Voigt zone (the cells next to a fault,
       * see FaultZoneDamping) for the products below.
       */
      void
      set_zone(
        const std::function<bool(
          const typename DoFHandler<dim>::active_cell_iterator &)> &in_zone);

      /// dst += eta K_zone v, a pass over the zone's cell batches only
      /// (dst's ghost entries must be zero, as compress() leaves them).
      void
      vmult_zone(VectorType &dst, const VectorType &v, const double eta) const;

      /// The diagonal of K_zone (zero away from the zone).
      void
      compute_zone_diagonal(VectorType &diagonal) const;

      /**
       * The diagonals of K and of the consistent M, for Jacobi-type
       * preconditioners. The cells' diagonal entries are added up through
       * the constraints, which is exact for unconstrained DoFs and for the
       * welded fault nodes (whose two sides never share a cell) and an
       * approximation for the parents of hanging nodes.
       */
      void
      compute_diagonals(VectorType &stiffness_diagonal,
                        VectorType &mass_diagonal) const;

      /// Number of cells and DoFs, for the screen.
      unsigned long
      n_dofs() const;

      /// Memory of the operator's own data (bytes, this rank).
      std::size_t
      memory_consumption() const;

      /**
       * How the cell batches of this rank are stored, for the screen: how
       * many have Cartesian, affine or general geometry (one Jacobian per
       * batch, or one per quadrature point), and how many read their DoFs
       * contiguously or through an index list.
       */
      std::string
      layout_summary() const;

    private:
      struct Implementation;
      std::unique_ptr<Implementation> impl;
    };
  } // namespace Operators
} // namespace rupture

#endif
