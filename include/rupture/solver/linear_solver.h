#ifndef rupture_solver_linear_solver_h
#define rupture_solver_linear_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <vector>

namespace rupture
{
  using namespace dealii;

  namespace Solver
  {
    /**
     * The Krylov solve of the (effective) stiffness system: CG for
     * symmetric positive definite matrices, GMRES otherwise, both
     * preconditioned by Trilinos ML algebraic multigrid whose near null
     * space is the rigid-body modes of elasticity.
     */
    class LinearSolver
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /**
       * Build the AMG hierarchy for @p matrix. @p rigid_body_modes holds
       * dim (dim+1)/2 vectors over the locally owned DoFs, from which the
       * dimension follows: the dim DoFs of each node (numbered together)
       * are aggregated as one block. @p symmetric selects CG under the
       * 'automatic' choice.
       */
      void
      initialize(const TrilinosWrappers::SparseMatrix   &matrix,
                 const std::vector<std::vector<double>> &rigid_body_modes,
                 const bool                              symmetric,
                 const bool                              higher_order);

      /**
       * Solve matrix x = b to the relative tolerance; returns the number of
       * iterations. Throws with a diagnosis if the solver fails.
       */
      unsigned int
      solve(const TrilinosWrappers::SparseMatrix &matrix,
            TrilinosWrappers::MPI::Vector        &x,
            const TrilinosWrappers::MPI::Vector  &b) const;

      double
      tolerance() const
      {
        return relative_tolerance;
      }

    private:
      std::string  solver_type;
      std::string  aggregation = "uncoupled";
      double       relative_tolerance;
      unsigned int max_iterations;
      bool         use_cg = true;
      std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
    };
  } // namespace Solver
} // namespace rupture

#endif
