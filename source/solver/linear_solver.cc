#include <rupture/solver/linear_solver.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

namespace rupture
{
  namespace Solver
  {
    void
    LinearSolver::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      {
        prm.declare_entry("Linear solver",
                          "automatic",
                          Patterns::Selection("automatic|CG|GMRES|direct"),
                          "Krylov method: 'automatic' uses CG for symmetric "
                          "positive definite systems and GMRES otherwise. "
                          "'direct' factorises the matrix (Trilinos Amesos "
                          "KLU): robust, but only for small problems.");
        prm.declare_entry(
          "AMG aggregation",
          "uncoupled",
          Patterns::Selection("uncoupled|MIS"),
          "How ML's algebraic multigrid groups nodes into coarse nodes: "
          "'uncoupled' (ML's default, per process) or 'MIS' (maximal "
          "independent sets), another code path in ML that needs more "
          "memory.");
        prm.declare_entry("Linear solver tolerance",
                          "1e-10",
                          Patterns::Double(0, 1),
                          "Relative residual reduction of the Krylov solve.");
        prm.declare_entry("Maximum linear iterations",
                          "1000",
                          Patterns::Integer(1),
                          "A Krylov solve that needs more iterations fails "
                          "with a diagnosis.");
      }
      prm.leave_subsection();
    }



    void
    LinearSolver::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      solver_type        = prm.get("Linear solver");
      aggregation        = prm.get("AMG aggregation");
      relative_tolerance = prm.get_double("Linear solver tolerance");
      max_iterations     = prm.get_integer("Maximum linear iterations");
      prm.leave_subsection();
      AssertThrow(relative_tolerance > 0,
                  ExcMessage("<Solver/Linear solver tolerance> must be > 0."));
    }



    void
    LinearSolver::initialize(
      const TrilinosWrappers::SparseMatrix   &matrix,
      const std::vector<std::vector<double>> &rigid_body_modes,
      const bool                              symmetric,
      const bool                              higher_order)
    {
      use_cg =
        (solver_type == "CG" || (solver_type == "automatic" && symmetric));

      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = higher_order;
      data.smoother_sweeps       = 2;
      data.aggregation_threshold = 1e-4;

      Teuchos::ParameterList              parameters;
      std::unique_ptr<Epetra_MultiVector> unused;
      data.set_parameters(parameters, unused, matrix);

      // Near null space: the rigid-body modes (translations and rotations).
      const Epetra_Map  &map = matrix.trilinos_matrix().RowMap();
      Epetra_MultiVector modes(map, rigid_body_modes.size());
      for (unsigned int m = 0; m < rigid_body_modes.size(); ++m)
        {
          AssertDimension(rigid_body_modes[m].size(),
                          static_cast<unsigned int>(map.NumMyElements()));
          for (int i = 0; i < map.NumMyElements(); ++i)
            modes[m][i] = rigid_body_modes[m][i];
        }
      parameters.set("null space: type", "pre-computed");
      parameters.set("null space: dimension", modes.NumVectors());
      parameters.set("null space: vectors", modes.Values());
      // Aggregate nodes, not single DoFs: the dim displacement DoFs of a node
      // are numbered together. This is what elasticity needs, and it keeps
      // ML's aggregation graph (and its int-sized work arrays) nine times
      // smaller; on the full Northeast-Japan model (590 M nonzeros) the
      // scalar graph overflowed them.
      const int n_components = (rigid_body_modes.size() == 6) ? 3 : 2;
      AssertThrow(map.NumMyElements() % n_components == 0, ExcInternalError());
      parameters.set("PDE equations", n_components);
      parameters.set("aggregation: type",
                     aggregation == "MIS" ? "MIS" : "Uncoupled");

      amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      amg->initialize(matrix, parameters);
    }



    unsigned int
    LinearSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                        TrilinosWrappers::MPI::Vector        &x,
                        const TrilinosWrappers::MPI::Vector  &b) const
    {
      const double b_norm = b.l2_norm();
      if (solver_type == "direct")
        {
          SolverControl                  control(1, 0);
          TrilinosWrappers::SolverDirect direct(control);
          direct.solve(matrix, x, b);
          return 1;
        }
      Assert(amg, ExcMessage("LinearSolver::initialize() was not called."));
      AssertThrow(std::isfinite(b_norm),
                  ExcMessage("The right-hand side of the linear system is "
                             "not finite: the run has become unstable."));
      if (b_norm == 0)
        {
          x = 0;
          return 0;
        }
      SolverControl control(max_iterations, relative_tolerance * b_norm);
      try
        {
          if (use_cg)
            {
              TrilinosWrappers::SolverCG cg(control);
              cg.solve(matrix, x, b, *amg);
            }
          else
            {
              TrilinosWrappers::SolverGMRES gmres(
                control,
                TrilinosWrappers::SolverGMRES::AdditionalData(false, 200));
              gmres.solve(matrix, x, b, *amg);
            }
        }
      catch (const SolverControl::NoConvergence &e)
        {
          AssertThrow(false,
                      ExcMessage(
                        std::string("The ") + (use_cg ? "CG" : "GMRES") +
                        " solve did not converge within " +
                        std::to_string(max_iterations) +
                        " iterations (residual reduced to " +
                        std::to_string(e.last_residual / b_norm) +
                        " of its start, wanted " +
                        std::to_string(relative_tolerance) +
                        "). Raise <Solver/Maximum linear iterations>, loosen "
                        "<Solver/Linear solver tolerance>, or check the "
                        "model for a part that no boundary condition "
                        "holds in place (a singular stiffness)."));
        }
      return control.last_step();
    }
  } // namespace Solver
} // namespace rupture
