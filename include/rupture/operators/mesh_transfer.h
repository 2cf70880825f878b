#ifndef rupture_operators_mesh_transfer_h
#define rupture_operators_mesh_transfer_h

#include <deal.II/base/partitioner.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <memory>
#include <utility>
#include <vector>

namespace rupture
{
  namespace Operators
  {
    using namespace dealii;

    /**
     * Prolongation from a coarse level of the multigrid hierarchy to the
     * next finer one, and its transpose, cell by cell. Each locally owned
     * coarse cell knows its children on the fine mesh (the first child is
     * owned by the same rank, the others are ghosts at least), or itself
     * where the mesh did not change. Each side of the fault's hp split
     * uses the FE_Q prolongation on its own components (deal.II 9.4's
     * transfers do not take the FE_Nothing split); a fine DoF shared by
     * several cells gets the mean of what they give it. Where the cell
     * stays, the two levels may differ in degree (p-coarsening): the
     * matrix is then FE_Q's interpolation from the coarse degree into the
     * fine one.
     */
    template <int dim>
    class MeshTransfer
    {
    public:
      using VectorType = LinearAlgebra::distributed::Vector<double>;

      /**
       * Build the transfer between the levels @p coarse and @p fine (their
       * locally relevant partitioners, and the coarse level's hanging-node
       * and welding constraints). @p prolongation holds, per active FE
       * index, the prolongation matrices of the children and, last, the
       * matrix of a cell that stays (the identity, or the interpolation
       * between two degrees on the same mesh: fine DoFs times coarse
       * DoFs); it must outlive this object.
       */
      void
      reinit(const DoFHandler<dim> &coarse,
             const std::shared_ptr<const dealii::Utilities::MPI::Partitioner>
                                             &coarse_relevant,
             const AffineConstraints<double> &coarse_constraints,
             const DoFHandler<dim>           &fine,
             const std::shared_ptr<const dealii::Utilities::MPI::Partitioner>
                                                                &fine_relevant,
             const std::vector<std::vector<FullMatrix<double>>> &prolongation);

      /// fine = P coarse (owned entries).
      void
      prolongate(const VectorType &coarse, VectorType &fine) const;

      /// coarse = P^T fine (owned entries).
      void restrict(const VectorType &fine, VectorType &coarse) const;

      std::size_t
      memory_consumption() const;

    private:
      /// The coarse level's constraints: the prolongation first gives
      /// constrained coarse DoFs their values, the restriction ends with
      /// the transpose.
      void
      distribute_coarse() const;
      void
      condense_coarse() const;

      struct Block
      {
        unsigned int              coarse_first, fine_first, n_coarse, n_fine;
        const FullMatrix<double> *matrix;
      };
      std::vector<Block>        blocks;
      std::vector<unsigned int> coarse_dofs, fine_dofs;
      VectorType                weights;
      mutable VectorType        coarse_ghosted, fine_ghosted;
      /// The coarse constraints in local indices.
      std::vector<
        std::pair<unsigned int, std::vector<std::pair<unsigned int, double>>>>
        coarse_lines;
    };
  } // namespace Operators
} // namespace rupture

#endif
