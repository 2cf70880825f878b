#ifndef rupture_operators_pair_blocks_h
#define rupture_operators_pair_blocks_h

#include <rupture/base/sparse_gather.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <tuple>
#include <utility>
#include <vector>

namespace rupture
{
  namespace Operators
  {
    using namespace dealii;

    /**
     * The contact tangent of a fault's split node pairs as a matrix-free
     * operator: pair k couples its minus and plus DoFs by the block
     * [D_k, -D_k; -D_k, D_k] (D_k the area times the tangent). Applies the
     * product and the pair part of the block-Jacobi preconditioner on the
     * locally owned arrays of distributed vectors (Trilinos or deal.II),
     * exchanging the pairs' entries alone. Used by the fault on the fine
     * mesh and by every level of the multigrid preconditioner.
     */
    template <int dim>
    class PairBlocks
    {
    public:
      using PairDofs = std::pair<std::array<types::global_dof_index, dim>,
                                 std::array<types::global_dof_index, dim>>;

      /// Set up for @p pairs of vectors with the locally owned DoFs
      /// @p owned. Collective.
      void
      reinit(const std::vector<PairDofs> &pairs,
             const IndexSet              &owned,
             const MPI_Comm               communicator);

      /// The pairs' DoFs.
      const std::vector<PairDofs> &
      pairs() const
      {
        return pair_dofs;
      }

      /// Exchanges the pairs' 2 dim entries (minus, then plus, pair by
      /// pair).
      const SparseGather &
      gather() const
      {
        return exchange;
      }

      /**
       * Pairs on hanging nodes: entry (slot, master, weight) says that the
       * pairs' entry number slot (2 dim per pair, minus then plus) follows
       * the DoF @p master with @p weight. apply() then reads such an entry
       * from its masters and adds its product to them (the constrained
       * operator). Collective; after reinit().
       */
      void
      set_hanging(
        const std::vector<
          std::tuple<unsigned int, types::global_dof_index, double>> &entries,
        const IndexSet                                               &owned,
        const MPI_Comm communicator);

      /// The blocks D_k, one per pair, to be set by the user.
      std::vector<Tensor<2, dim>> blocks;

      /// y += T x (x zero at constrained DoFs). Collective.
      void
      apply(const double *x, double *y) const;

      /**
       * Invert each pair's 2 dim x 2 dim block diag + [D, -D; -D, D] for
       * precondition(); @p free is 1 at free DoFs and 0 at constrained
       * ones, whose rows and columns are the identity. Collective.
       */
      void
      prepare(const double *diagonal, const double *free);

      /// @p z holds the point-Jacobi value r / diag (r at constrained DoFs):
      /// replace it at the pairs by the solution of their blocks.
      /// Collective.
      void
      precondition(const double *r, double *z) const;

    private:
      static constexpr unsigned int n = 2 * dim;
      std::vector<PairDofs>         pair_dofs;
      SparseGather                  exchange;
      std::vector<double>           inverses, point_inverses;
      /// set_hanging(): the slots and weights of the masters that
      /// hanging_exchange reads and adds to.
      std::vector<std::pair<unsigned int, double>> hanging_slots;
      SparseGather                                 hanging_exchange;
      mutable std::vector<double>                  hanging_values;
      /// set_hanging() was called (on every process).
      bool                        hanging_active = false;
      mutable std::vector<double> values, results;
    };
  } // namespace Operators
} // namespace rupture

#endif
