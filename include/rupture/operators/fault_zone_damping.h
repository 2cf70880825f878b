#ifndef rupture_operators_fault_zone_damping_h
#define rupture_operators_fault_zone_damping_h

#include <rupture/operators/elastic_operator.h>

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <vector>

namespace rupture
{
  namespace Operators
  {
    using namespace dealii;

    /**
     * Kelvin-Voigt damping in the cells that touch the fault: the stress
     * there is C : (eps + eta d eps / dt), so the damping force is
     * eta K_zone v, where K_zone is the stiffness of those cells alone.
     * This class owns which cells these are and the products with
     * K_zone: through the matrix-free elastic operator where there is one
     * (it then visits the zone's cells only), else through a stored
     * matrix of the zone's rows, which the simulator fills with the
     * cells' stiffness. The simulator decides eta (a fraction of the time
     * step).
     */
    template <int dim>
    class FaultZoneDamping
    {
    public:
      using VectorType = TrilinosWrappers::MPI::Vector;

      /**
       * Mark the locally owned cells of @p dof_handler for which
       * @p touches_fault is true (given their DoFs). With
       * @p matrix_free_operator, mark them there too; without, size the
       * stored matrix for their couplings through @p constraints (the
       * hanging-node and welding constraints that the stiffness uses).
       */
      void
      reinit(
        const DoFHandler<dim>           &dof_handler,
        const AffineConstraints<double> &constraints,
        const std::function<bool(const std::vector<types::global_dof_index> &)>
                             &touches_fault,
        ElasticOperator<dim> *matrix_free_operator,
        const IndexSet       &owned_dofs,
        const IndexSet       &relevant_dofs,
        const MPI_Comm        communicator);

      /// Whether @p cell (locally owned) is in the zone.
      bool
      contains(
        const typename DoFHandler<dim>::active_cell_iterator &cell) const;

      /// Whether the cells' stiffness must be added to matrix() (then
      /// compress()): without the matrix-free operator.
      bool
      stored() const;

      /// The stored matrix, to add the cells' stiffness to.
      TrilinosWrappers::SparseMatrix &
      matrix();

      /// y += factor K_zone x.
      void
      vmult_add(const double factor, const VectorType &x, VectorType &y) const;

      /// d += factor diag(K_zone).
      void
      add_diagonal(const double factor, VectorType &d) const;

      /// Number of cells in the zone, over all ranks.
      types::global_cell_index
      n_cells() const;

    private:
      std::vector<bool>              in_zone;
      types::global_cell_index       n_zone_cells = 0;
      const ElasticOperator<dim>    *elastic      = nullptr;
      TrilinosWrappers::SparseMatrix zone_stiffness;
      /// diag(K_zone), computed on first use.
      mutable VectorType                                 diagonal;
      mutable VectorType                                 product;
      mutable LinearAlgebra::distributed::Vector<double> source, result;
      /// The owned entries (local numbers) that the zone's product reads
      /// and writes (matrix-free): the DoFs of the zone's cells and the
      /// masters of their constrained ones. Only these are copied.
      std::vector<unsigned int> zone_entries;
    };
  } // namespace Operators
} // namespace rupture

#endif
