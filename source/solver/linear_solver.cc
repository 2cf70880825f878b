#include <rupture/base/utilities.h>
#include <rupture/solver/linear_solver.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_solver.h>

#include <EpetraExt_MatrixMatrix.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <iomanip>
#include <sstream>

namespace rupture
{
  namespace Solver
  {
    namespace
    {
      std::string
      short_number(const double x)
      {
        std::ostringstream s;
        s << std::setprecision(3) << x;
        return s.str();
      }
    } // namespace

    void
    LinearSolver::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Solver");
      {
        prm.declare_entry("Linear solver",
                          "automatic",
                          Patterns::Selection(
                            "automatic|CG|GMRES|direct|MUMPS"),
                          "Krylov method: 'automatic' uses CG for symmetric "
                          "positive definite systems and GMRES otherwise. "
                          "'direct' factorises the matrix (KLU through "
                          "Trilinos Amesos): robust and reproducible, but "
                          "slow in 3-D. 'MUMPS' is the multifrontal direct "
                          "solver MUMPS: the fastest for small models (up to "
                          "some 1e5 DoFs; 4 times faster than GMRES on "
                          "northeast-japan-fault-coarse.prm), but on several "
                          "ranks not bitwise reproducible, and its memory "
                          "grows fast with the model.");
        prm.declare_entry(
          "Preconditioner",
          "AMG",
          Patterns::Selection("AMG|block Jacobi|multigrid"),
          "Preconditioner of the Krylov solvers. 'AMG' is Trilinos ML's "
          "algebraic multigrid on the assembled system matrix: robust for "
          "quasi-static and dynamic steps alike, but the matrix and the "
          "multigrid hierarchy cost about 1.5-3 kB per DoF. 'block Jacobi' "
          "stores no matrix: the system is applied matrix-free (stiffness, "
          "consistent or lumped mass, damping, absorbing boundaries and "
          "the fault's contact tangent) and preconditioned by its diagonal, "
          "with each split fault node pair's 2 dim x 2 dim block (which the "
          "penalty dominates) solved exactly. It suits the mass-dominated "
          "dynamic steps of the implicit scheme at time steps near the "
          "explicit limit; in quasi-static steps its iteration count grows "
          "with the number of cells across the model (doc/performance.md). "
          "'multigrid' stores no matrix either: a multigrid V-cycle that "
          "coarsens first in polynomial degree on the mesh (halving it "
          "down to 1), then on the p4est hierarchy of the mesh (the coarse "
          "mesh refined globally), with Chebyshev smoothing around the "
          "same block Jacobi on each level, the fault re-discretised on "
          "each level and a GMRES solve to a tenth of the residual on the "
          "coarse mesh; its iteration count stays bounded as the mesh is "
          "refined, which quasi-static steps need. It needs a fault on "
          "faces of the coarse mesh, and works best with a coarse mesh of "
          "few cells and its refinements. 'block Jacobi' or "
          "'multigrid' together with a direct 'Linear solver' is an "
          "error: the direct solvers store and factorise the matrix.");
        prm.declare_entry(
          "Multigrid in dynamic steps",
          "true",
          Patterns::Bool(),
          "With <Preconditioner> = multigrid: whether the dynamic (implicit "
          "Newmark) steps use it too, or block Jacobi. Quasi-static steps "
          "always use multigrid. In dynamic steps the mass term dominates "
          "and block Jacobi needs few iterations, each as dear as a tenth "
          "of a V-cycle (doc/performance.md).");
        prm.declare_entry(
          "AMG aggregation",
          "uncoupled",
          Patterns::Selection("uncoupled|MIS"),
          "How ML's algebraic multigrid groups nodes into coarse nodes: "
          "'uncoupled' (ML's default, per process) or 'MIS' (maximal "
          "independent sets), another code path in ML that needs more "
          "memory.");
        prm.declare_entry(
          "AMG smoother",
          "automatic",
          Patterns::Selection("automatic|Chebyshev|symmetric Gauss-Seidel|"
                              "symmetric block Gauss-Seidel"),
          "Smoother on each level of the algebraic multigrid. 'Chebyshev' "
          "(polynomial, only matrix products) suits elasticity alone. With a "
          "penalty fault the slipping nodes couple normal and tangential "
          "jumps through mu p_n (the nonsymmetric tangent), which only a "
          "smoother that solves each node's dim x dim block at once handles "
          "well: 'symmetric block Gauss-Seidel' (3-D only). 'automatic' picks "
          "that one with a penalty fault in 3-D, 'symmetric Gauss-Seidel' "
          "with one in 2-D and 'Chebyshev' otherwise.");
        prm.declare_entry("AMG smoother sweeps",
                          "2",
                          Patterns::Integer(1, 100),
                          "Smoothing steps before and after each coarse "
                          "correction.");
        prm.declare_entry(
          "AMG aggregation threshold",
          "1e-4",
          Patterns::Double(0, 1),
          "Couplings weaker than this fraction (relative to the diagonal) "
          "are ignored when ML groups nodes. Raising it did not help with "
          "stiff penalty faults (measured: doc/performance.md); the fault "
          "pair transform does.");
        prm.declare_entry(
          "Fault pair transform",
          "true",
          Patterns::Bool(),
          "With a penalty fault: build the AMG in the coordinates 'mean' and "
          "'jump' of each split node pair instead of 'minus side' and 'plus "
          "side' (manual, section 3.7). A penalty many times "
          "the element stiffness then no longer stalls GMRES. 'false' builds "
          "the AMG on the matrix as it is.");
        prm.declare_entry(
          "Direct solver refinement steps",
          "2",
          Patterns::Integer(0, 10),
          "With 'direct' or 'MUMPS': at most this many steps of iterative "
          "refinement after each solve (x += A^-1 (b - A x) with the same "
          "factors; a step costs a matrix product and two triangular "
          "solves, far less than the factorisation). A stiff penalty fault "
          "makes the system ill-conditioned, and the refinement recovers "
          "the digits that the factorisation loses; it stops early once "
          "the residual no longer falls.");
        prm.declare_entry("Linear solver tolerance",
                          "1e-10",
                          Patterns::Double(1e-15, 1),
                          "Relative residual reduction of the Krylov solve, "
                          "from 1e-15 (about what double precision can "
                          "reach: a smaller one would only end in a "
                          "breakdown of the solver) to 1.");
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
      solver_type         = prm.get("Linear solver");
      preconditioner_name = prm.get("Preconditioner");
      block_jacobi        = (preconditioner_name == "block Jacobi");
      use_multigrid       = (preconditioner_name == "multigrid");
      multigrid_dynamic   = prm.get_bool("Multigrid in dynamic steps");
      AssertThrow(
        !matrix_free() || (solver_type != "direct" && solver_type != "MUMPS"),
        ExcMessage("<Solver/Preconditioner> = " + preconditioner_name +
                   " needs a Krylov "
                   "<Solver/Linear solver> (automatic, CG or GMRES), but "
                   "it is '" +
                   solver_type +
                   "': a direct solver stores and factorises the matrix and "
                   "uses no preconditioner. Set one of the two entries "
                   "differently."));
      aggregation           = prm.get("AMG aggregation");
      smoother              = prm.get("AMG smoother");
      smoother_sweeps       = prm.get_integer("AMG smoother sweeps");
      aggregation_threshold = prm.get_double("AMG aggregation threshold");
      use_pair_transform    = prm.get_bool("Fault pair transform");
      relative_tolerance    = prm.get_double("Linear solver tolerance");
      max_iterations        = prm.get_integer("Maximum linear iterations");
      refinement_steps      = prm.get_integer("Direct solver refinement steps");
      prm.leave_subsection();
      AssertThrow(relative_tolerance > 0,
                  ExcMessage("<Solver/Linear solver tolerance> must be > 0."));
    }



    LinearSolver::LinearSolver() = default;



    LinearSolver::~LinearSolver()
    {
      clear();
    }



    void
    LinearSolver::clear()
    {
      amg.reset();
      transformed.reset();
      direct.reset();
      direct_control.reset();
    }



    void
    LinearSolver::set_fault_pairs(
      const std::vector<
        std::pair<types::global_dof_index, types::global_dof_index>> &pairs,
      const IndexSet &locally_owned_dofs,
      const MPI_Comm  communicator)
    {
      clear();
      transform.reset();
      const bool has_pairs =
        dealii::Utilities::MPI::sum(pairs.size(), communicator) > 0;
      penalty_fault = has_pairs;
      if (!use_pair_transform || solver_type == "direct" ||
          solver_type == "MUMPS" || !has_pairs)
        return;

      // T is the identity except on the pairs, whose rows may belong to
      // another process: every process writes the pairs it owns.
      IndexSet touched(locally_owned_dofs.size());
      for (const auto &p : pairs)
        {
          touched.add_index(p.first);
          touched.add_index(p.second);
        }
      IndexSet writable = locally_owned_dofs;
      writable.add_indices(touched);
      DynamicSparsityPattern dsp(writable);
      for (const auto i : locally_owned_dofs)
        dsp.add(i, i);
      for (const auto &p : pairs)
        for (const auto r : {p.first, p.second})
          for (const auto c : {p.first, p.second})
            dsp.add(r, c);
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 locally_owned_dofs,
                                                 communicator,
                                                 writable);
      transform = std::make_unique<TrilinosWrappers::SparseMatrix>();
      transform->reinit(locally_owned_dofs,
                        locally_owned_dofs,
                        dsp,
                        communicator);
      for (const auto i : locally_owned_dofs)
        transform->add(i, i, 1.);
      // Rows: minus -> (1, 1) / sqrt(2), plus -> (1, -1) / sqrt(2); the
      // owner of each row has already put 1 on its diagonal.
      const double s = 1. / std::sqrt(2.);
      for (const auto &p : pairs)
        {
          transform->add(p.first, p.first, s - 1.);
          transform->add(p.first, p.second, s);
          transform->add(p.second, p.first, s);
          transform->add(p.second, p.second, -s - 1.);
        }
      transform->compress(VectorOperation::add);
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
      if (solver_type == "direct" || solver_type == "MUMPS")
        {
          // Factorise now; solve() only does the triangular solves (deal.II's
          // SolverDirect: Amesos KLU or MUMPS).
          direct_control = std::make_unique<SolverControl>(1, 0);
          direct         = std::make_unique<TrilinosWrappers::SolverDirect>(
            *direct_control,
            TrilinosWrappers::SolverDirect::AdditionalData(
              false, solver_type == "MUMPS" ? "Amesos_Mumps" : "Amesos_Klu"));
          try
            {
              direct->initialize(matrix);
            }
          catch (const std::exception &)
            {
              direct.reset();
              AssertThrow(false,
                          ExcMessage(
                            "The direct solver (<Solver/Linear solver> = " +
                            solver_type +
                            ") could not factorise the system matrix. Most "
                            "likely it is singular: a part of the model is "
                            "held by no boundary condition (or Trilinos was "
                            "built without this solver)."));
            }
          ++factorizations;
          return;
        }

      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = higher_order;
      data.smoother_sweeps       = smoother_sweeps;
      // ML's block smoother keeps the fine level's block size (dim) on the
      // coarse levels, whose rows come in groups of the number of rigid
      // body modes: 6 in 3-D fits blocks of 3, but 3 in 2-D does not fit
      // blocks of 2, so there the point smoother is used.
      const bool blocks_fit = (rigid_body_modes.size() != 3);
      AssertThrow(blocks_fit || smoother != "symmetric block Gauss-Seidel",
                  ExcMessage("<Solver/AMG smoother> = symmetric block "
                             "Gauss-Seidel works in 3-D only (Trilinos ML "
                             "cannot block the coarse levels of 2-D "
                             "elasticity). Use 'automatic', 'symmetric "
                             "Gauss-Seidel' or 'Chebyshev'."));
      data.smoother_type =
        smoother != "automatic" ?
          smoother.c_str() :
          (penalty_fault ? (blocks_fit ? "symmetric block Gauss-Seidel" :
                                         "symmetric Gauss-Seidel") :
                           "Chebyshev");
      data.aggregation_threshold = aggregation_threshold;

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

      clear();
      amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      if (!transform)
        {
          amg->initialize(matrix, parameters);
          return;
        }
      // AMG for T A T, with the near null space T r (T = T^-1).
      const Epetra_CrsMatrix &a = matrix.trilinos_matrix();
      const Epetra_CrsMatrix &t = transform->trilinos_matrix();
      {
        Epetra_CrsMatrix at(Copy, a.RowMap(), 0);
        int ierr = EpetraExt::MatrixMatrix::Multiply(a, false, t, false, at);
        AssertThrow(ierr == 0, ExcTrilinosError(ierr));
        transformed = std::make_unique<Epetra_CrsMatrix>(Copy, a.RowMap(), 0);
        ierr =
          EpetraExt::MatrixMatrix::Multiply(t, false, at, false, *transformed);
        AssertThrow(ierr == 0, ExcTrilinosError(ierr));
      }
      Epetra_MultiVector transformed_modes(map, modes.NumVectors());
      t.Multiply(false, modes, transformed_modes);
      parameters.set("null space: vectors", transformed_modes.Values());
      amg->initialize(*transformed, parameters);
    }



    unsigned int
    LinearSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                        TrilinosWrappers::MPI::Vector        &x,
                        const TrilinosWrappers::MPI::Vector  &b)
    {
      const double b_norm = b.l2_norm();
      if (solver_type == "direct" || solver_type == "MUMPS")
        {
          Assert(direct,
                 ExcMessage("LinearSolver::initialize() was not called."));
          AssertThrow(std::isfinite(b_norm),
                      ExcMessage("The right-hand side of the linear system is "
                                 "not finite: the run has become unstable."));
          if (b_norm == 0)
            {
              x             = 0;
              last_residual = 0;
              return 0;
            }
          // x = A^-1 b, then iterative refinement x += A^-1 (b - A x) while
          // the residual falls by at least half.
          TrilinosWrappers::MPI::Vector r(b), d(b);
          direct->solve(x, b);
          matrix.residual(r, x, b);
          double r_norm = r.l2_norm();
          for (unsigned int s = 0; s < refinement_steps && r_norm > 0; ++s)
            {
              direct->solve(d, r);
              TrilinosWrappers::MPI::Vector y(x);
              y += d;
              TrilinosWrappers::MPI::Vector r_new(b);
              const double new_norm = matrix.residual(r_new, y, b);
              if (!(new_norm < r_norm))
                break;
              x.swap(y);
              r.swap(r_new);
              // A step that gained less than a factor 2 ends the refinement.
              const bool slow = (new_norm > 0.5 * r_norm);
              r_norm          = new_norm;
              if (slow)
                break;
            }
          last_residual = r_norm / b_norm;
          AssertThrow(std::isfinite(last_residual),
                      ExcMessage("The direct solver returned a solution that "
                                 "is not finite: the system matrix is "
                                 "singular or the run has become unstable."));
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
          if (transform)
            {
              // M^-1 = T AMG(T A T)^-1 T, right preconditioned so that the
              // residual checked is that of the system itself.
              struct TransformedAMG
              {
                const TrilinosWrappers::SparseMatrix    &t;
                const TrilinosWrappers::PreconditionAMG &amg;
                mutable TrilinosWrappers::MPI::Vector    u, v;
                void
                vmult(TrilinosWrappers::MPI::Vector       &dst,
                      const TrilinosWrappers::MPI::Vector &src) const
                {
                  t.vmult(u, src);
                  amg.vmult(v, u);
                  t.vmult(dst, v);
                }
              } preconditioner{*transform, *amg, b, b};
              dealii::SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
                control,
                dealii::SolverGMRES<
                  TrilinosWrappers::MPI::Vector>::AdditionalData(200, true));
              gmres.solve(matrix, x, b, preconditioner);
            }
          else if (use_cg)
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
                        short_number(e.last_residual / b_norm) +
                        " of its start, wanted " +
                        short_number(relative_tolerance) +
                        "). Raise <Solver/Maximum linear iterations>, loosen "
                        "<Solver/Linear solver tolerance>, or check the "
                        "model for a part that no boundary condition "
                        "holds in place (a singular stiffness)."));
        }
      catch (const ExceptionBase &e)
        {
          // Trilinos's own failures (a breakdown of its Krylov method, a
          // failed factorisation) come with the library's words only.
          AssertThrow(false,
                      ExcMessage(
                        std::string("The ") + (use_cg ? "CG" : "GMRES") +
                        " solve of the step (algebraic multigrid) failed "
                        "inside Trilinos (" +
                        Utilities::message_of(e) +
                        "). This happens when the system is singular or "
                        "nearly so: check that the boundary conditions hold "
                        "every part of the model (<Boundary conditions>), "
                        "that no material is far softer or stiffer than the "
                        "others (<Material>), and that the fault penalties "
                        "are not orders of magnitude above the stiffness of "
                        "the elements (<Fault/Normal penalty>, <Fault/"
                        "Tangential penalty>)."));
        }
      last_residual = control.last_value() / b_norm;
      return control.last_step();
    }



    unsigned int
    LinearSolver::solve(const Operator                      &system,
                        const Operator                      &preconditioner,
                        const bool                           symmetric,
                        TrilinosWrappers::MPI::Vector       &x,
                        const TrilinosWrappers::MPI::Vector &b,
                        const double                         tolerance)
    {
      Assert(matrix_free(),
             ExcMessage("The matrix-free solve needs <Solver/Preconditioner> "
                        "= block Jacobi or multigrid."));
      const double b_norm = b.l2_norm();
      AssertThrow(std::isfinite(b_norm),
                  ExcMessage("The right-hand side of the linear system is "
                             "not finite: the run has become unstable."));
      if (b_norm == 0)
        {
          x             = 0;
          last_residual = 0;
          return 0;
        }
      // deal.II's solvers call vmult(dst, src) on the operator and the
      // preconditioner.
      struct Wrapper
      {
        const Operator &apply;
        void
        vmult(TrilinosWrappers::MPI::Vector       &dst,
              const TrilinosWrappers::MPI::Vector &src) const
        {
          apply(src, dst);
        }
      };
      const Wrapper a{system}, p{preconditioner};
      use_cg =
        (solver_type == "CG" || (solver_type == "automatic" && symmetric));
      const double wanted =
        (tolerance > 0 ? std::max(tolerance, relative_tolerance) :
                         relative_tolerance);
      SolverControl control(max_iterations, wanted * b_norm);
      try
        {
          // The multigrid V-cycle ends in an iterative coarse solve, so it
          // is not exactly linear: the flexible variants keep each
          // preconditioned vector instead of applying the preconditioner to
          // a combination of them (with the stiff penalty, GMRES's final
          // combination cancels so strongly that the plain variant's
          // result missed its residual by orders of magnitude).
          if (use_cg && use_multigrid)
            {
              dealii::SolverFlexibleCG<TrilinosWrappers::MPI::Vector> cg(
                control);
              cg.solve(a, x, b, p);
            }
          else if (use_cg)
            {
              dealii::SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
              cg.solve(a, x, b, p);
            }
          else if (use_multigrid)
            {
              dealii::SolverFGMRES<TrilinosWrappers::MPI::Vector> fgmres(
                control,
                dealii::SolverFGMRES<
                  TrilinosWrappers::MPI::Vector>::AdditionalData(40));
              fgmres.solve(a, x, b, p);
            }
          else
            {
              // Right preconditioning: the residual checked is that of the
              // system itself.
              dealii::SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
                control,
                dealii::SolverGMRES<
                  TrilinosWrappers::MPI::Vector>::AdditionalData(100, true));
              gmres.solve(a, x, b, p);
            }
        }
      catch (const SolverControl::NoConvergence &e)
        {
          AssertThrow(
            false,
            ExcMessage(
              std::string("The matrix-free ") + (use_cg ? "CG" : "GMRES") +
              " solve (" + preconditioner_name +
              " preconditioner) did not "
              "converge within " +
              std::to_string(max_iterations) +
              " iterations (residual reduced to " +
              short_number(e.last_residual / b_norm) +
              " of its start, wanted " + short_number(wanted) + "). " +
              (block_jacobi ? "Block Jacobi suits dynamic steps near the "
                              "explicit time step; for quasi-static steps or "
                              "long time steps use <Solver/Preconditioner> = "
                              "multigrid or AMG, or raise <Solver/Maximum "
                              "linear iterations>." :
                              "Raise <Solver/Maximum linear iterations>, or "
                              "check the model for a part that no boundary "
                              "condition holds in place.")));
        }
      last_residual = control.last_value() / b_norm;
      return control.last_step();
    }
  } // namespace Solver
} // namespace rupture
