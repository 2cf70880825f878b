#ifndef rupture_operators_node_coupling_h
#define rupture_operators_node_coupling_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <vector>

namespace rupture
{
  namespace Operators
  {
    using namespace dealii;

    /**
     * The inverses of the blocks of a node-by-node matrix
     * (NodeCoupling::invert_blocks()).
     */
    class NodeBlockInverse
    {
    public:
      /// At the blocks' nodes, replace @p x by the solution of the block
      /// system with right-hand side @p r (0 at DoFs that do not move).
      void
      solve(const double *r, double *x) const;

      /// The number of blocks.
      std::size_t
      size() const
      {
        return dofs.size();
      }

    private:
      friend class NodeCoupling;
      unsigned int n_components = 0;
      /// The nodes' DoFs (positions among the owned ones), which of them
      /// move, and the inverses of the blocks (3 x 3, row by row; a 2-D
      /// node's third row and column are the identity's).
      std::vector<std::array<unsigned int, 3>> dofs;
      std::vector<std::array<bool, 3>>         moves;
      std::vector<std::array<double, 9>>       inverses;
    };



    /**
     * A symmetric matrix whose entries couple the displacement components
     * of one node only, without its diagonal: the off-diagonal part of
     * the absorbing boundaries' lumped dashpot blocks (the diagonal stays
     * a vector). A node's components are owned by one process, so every
     * product is local.
     *
     * Assembly: reinit(), then add each cell's contributions to
     * coefficients(k) (entry i couples DoF i with the DoF of the same node
     * whose component is k + 1 places further, modulo dim) with the
     * constraints' distribute_local_to_global(), name the siblings with
     * set_sibling(), and call finalize().
     */
    class NodeCoupling
    {
    public:
      using VectorType = TrilinosWrappers::MPI::Vector;

      /// Start again for @p dim components per node. Collective.
      void
      reinit(const unsigned int dim,
             const IndexSet    &owned,
             const MPI_Comm     communicator);

      /// The coefficients of component offset @p k + 1 (k < dim - 1).
      VectorType &
      coefficients(const unsigned int k);

      /// The locally owned DoF @p row couples at offset @p k + 1 with
      /// @p column (of the same node).
      void
      set_sibling(const types::global_dof_index row,
                  const unsigned int            k,
                  const types::global_dof_index column);

      /**
       * Compress the coefficients and keep the entries larger than
       * 1e-13 sqrt(d_row d_column) (@p diagonal the matrix's diagonal, so
       * that the round-off of a diagonal block is dropped). Collective.
       */
      void
      finalize(const VectorType &diagonal);

      /// No entry on any process (set by finalize()).
      bool
      empty() const
      {
        return globally_empty;
      }

      /// y += factor C x on the locally owned arrays.
      void
      vmult_add(const double factor, const double *x, double *y) const;

      /// y += factor C x.
      void
      vmult_add(const double factor, const VectorType &x, VectorType &y) const;

      /// Add factor C to @p matrix, except on rows and columns that
      /// @p constraints constrain. Collective (compresses the matrix).
      void
      add_to(TrilinosWrappers::SparseMatrix  &matrix,
             const double                     factor,
             const AffineConstraints<double> &constraints) const;

      /**
       * The inverses of the nodes' blocks D + factor C, with D the diagonal
       * whose inverse is @p inverse_diagonal (0 at DoFs that do not move:
       * their rows and columns leave the block), at the nodes none of
       * whose DoFs is among @p excluded (positions among the owned DoFs).
       */
      NodeBlockInverse
      invert_blocks(const double                    *inverse_diagonal,
                    const double                     factor,
                    const std::vector<unsigned int> &excluded) const;

    private:
      struct Entry
      {
        unsigned int row, column; // positions among the owned DoFs
        double       value;
      };
      /// The entry (@p row, @p column), 0 if there is none.
      double
               value(const unsigned int row, const unsigned int column) const;
      IndexSet owned_dofs;
      MPI_Comm mpi_communicator = MPI_COMM_SELF;
      std::vector<VectorType>                  coefficient_vectors;
      std::vector<std::array<unsigned int, 2>> siblings;
      std::vector<Entry>                       entries;
      bool                                     globally_empty = true;
    };
  } // namespace Operators
} // namespace rupture

#endif
