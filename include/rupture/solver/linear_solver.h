#ifndef rupture_solver_linear_solver_h
#define rupture_solver_linear_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <memory>
#include <utility>
#include <vector>

class Epetra_CrsMatrix;

namespace dealii
{
  namespace TrilinosWrappers
  {
    class SolverDirect;
  }
} // namespace dealii

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
            const TrilinosWrappers::MPI::Vector  &b);

      /// y = A x for an operator that is given by its action.
      using Operator =
        std::function<void(const TrilinosWrappers::MPI::Vector &x,
                           TrilinosWrappers::MPI::Vector       &y)>;

      /**
       * Whether no system matrix is stored: <Solver/Preconditioner> =
       * block Jacobi with a Krylov method. Then solve() below is used with
       * the system's matrix-free product and its block-Jacobi
       * preconditioner, and initialize() is never called.
       */
      bool
      matrix_free() const
      {
        return block_jacobi || use_multigrid;
      }

      /// <Solver/Preconditioner> = multigrid (matrix-free).
      bool
      multigrid() const
      {
        return use_multigrid;
      }

      /// <Solver/Multigrid in dynamic steps>.
      bool
      multigrid_in_dynamic_steps() const
      {
        return use_multigrid && multigrid_dynamic;
      }

      /**
       * Solve A x = b with CG (if @p symmetric under 'automatic') or
       * right-preconditioned GMRES for the operator @p system, preconditioned
       * by @p preconditioner (z = P^-1 r), to the relative tolerance
       * <Solver/Linear solver tolerance>, or to @p tolerance if that is
       * looser (an inexact Newton iteration's forcing term); returns the
       * number of iterations. Throws with a diagnosis if the solver fails.
       */
      unsigned int
      solve(const Operator                      &system,
            const Operator                      &preconditioner,
            const bool                           symmetric,
            TrilinosWrappers::MPI::Vector       &x,
            const TrilinosWrappers::MPI::Vector &b,
            const double                         tolerance = 0);

      /// Numeric factorisations done by the direct solvers so far.
      unsigned int
      n_factorizations() const
      {
        return factorizations;
      }

      /**
       * The DoF pairs (minus side, plus side) of the split fault nodes that
       * this process owns, one pair per component. With a stiff penalty
       * these pairs are coupled far more strongly than anything else, and
       * ML's aggregation cannot represent the two sides moving together.
       * The preconditioner then works in the orthogonal coordinates
       * a = (u_minus + u_plus) / sqrt(2), j = (u_minus - u_plus) / sqrt(2)
       * (the transform T is its own inverse): AMG is built for T A T,
       * where the penalty acts on j alone and a is an ordinary welded
       * elastic body. Called once after the DoFs are set up; unless
       * <Solver/Fault pair transform> is false.
       */
      void
      set_fault_pairs(
        const std::vector<
          std::pair<types::global_dof_index, types::global_dof_index>> &pairs,
        const IndexSet &locally_owned_dofs,
        const MPI_Comm  communicator);

      /**
       * Free the preconditioner. ML's Ifpack smoothers keep a pointer to
       * the matrix, so this must run before the matrix is destroyed.
       */
      void
      clear();

      LinearSolver();

      ~LinearSolver();

      /**
       * Whether the preconditioner refers to its own matrix (T A T) rather
       * than to the one passed to initialize(), so that it stays valid
       * while that matrix changes.
       */
      bool
      keeps_own_matrix() const
      {
        return transform != nullptr;
      }

      double
      tolerance() const
      {
        return relative_tolerance;
      }

      /**
       * The relative residual |b - A x| / |b| of the last solve, as
       * checked after it (for the direct solvers, after iterative
       * refinement).
       */
      double
      last_relative_residual() const
      {
        return last_residual;
      }

    private:
      std::string  solver_type;
      std::string  aggregation           = "uncoupled";
      std::string  smoother              = "automatic";
      bool         penalty_fault         = false;
      unsigned int smoother_sweeps       = 2;
      double       aggregation_threshold = 1e-4;
      double       relative_tolerance;
      unsigned int max_iterations;
      bool         use_cg            = true;
      bool         block_jacobi      = false;
      bool         use_multigrid     = false;
      bool         multigrid_dynamic = true;
      std::string  preconditioner_name;
      bool         use_pair_transform = true;
      std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
      /// T (see set_fault_pairs()), or null without a penalty fault.
      std::unique_ptr<TrilinosWrappers::SparseMatrix> transform;
      /// T A T of the last initialize(), which the AMG refers to.
      std::unique_ptr<Epetra_CrsMatrix> transformed;
      /// The direct solvers: the factors of the last initialize().
      std::unique_ptr<SolverControl>                  direct_control;
      std::unique_ptr<TrilinosWrappers::SolverDirect> direct;
      /// Refinement steps of a direct solve (see solve()).
      unsigned int refinement_steps = 2;
      unsigned int factorizations   = 0;
      double       last_residual    = 0;
    };
  } // namespace Solver
} // namespace rupture

#endif
