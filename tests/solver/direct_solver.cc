// The direct solvers of Solver::LinearSolver ('direct' = KLU, 'MUMPS'): one
// factorisation in initialize() serves several solves; the solution and the
// reported relative residual |b - A x| / |b| are checked on a stiff system
// (a chain of springs with one pair of nodes tied by a penalty 1e8 times
// stiffer, like a split fault node pair), with and without iterative
// refinement; a singular matrix is refused with a message that says so.

#include <rupture/solver/linear_solver.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace dealii;

namespace
{
  const unsigned int n = 40;

  // Springs of stiffness 1 between neighbours, node 0 tied to the ground;
  // nodes 19 and 20 are tied by the penalty p. With singular = true the last
  // node is left out: its row and column are zero.
  void
  make_matrix(TrilinosWrappers::SparseMatrix &a,
              const double                    p,
              const bool                      singular)
  {
    IndexSet all(n);
    all.add_range(0, n);
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i > 0 ? i - 1 : 0); j <= std::min(i + 1, n - 1);
           ++j)
        dsp.add(i, j);
    a.reinit(all, all, dsp, MPI_COMM_WORLD);
    const unsigned int last = singular ? n - 1 : n;
    a.add(0, 0, 1.);
    for (unsigned int i = 0; i + 1 < last; ++i)
      {
        const double k = (i == 19) ? p : 1.;
        a.add(i, i, k);
        a.add(i + 1, i + 1, k);
        a.add(i, i + 1, -k);
        a.add(i + 1, i, -k);
      }
    a.compress(VectorOperation::add);
  }

  void
  check(const std::string &type, const unsigned int refinement_steps)
  {
    ParameterHandler prm;
    rupture::Solver::LinearSolver::declare_parameters(prm);
    prm.enter_subsection("Solver");
    prm.set("Linear solver", type);
    prm.set("Direct solver refinement steps", std::to_string(refinement_steps));
    prm.leave_subsection();
    rupture::Solver::LinearSolver solver;
    solver.parse_parameters(prm);

    TrilinosWrappers::SparseMatrix a;
    make_matrix(a, 1e8, false);
    solver.initialize(a, {}, true, false);

    IndexSet all(n);
    all.add_range(0, n);
    TrilinosWrappers::MPI::Vector exact(all, MPI_COMM_WORLD), b(exact),
      x(exact);
    bool all_good = true;
    for (const unsigned int rhs : {0u, 1u})
      {
        for (unsigned int i = 0; i < n; ++i)
          exact(i) = (rhs == 0) ? 1. + i : std::sin(0.3 * i);
        a.vmult(b, exact);
        x = 0;
        solver.solve(a, x, b);
        x -= exact;
        const double error = x.linfty_norm() / exact.linfty_norm();
        const bool   good =
          (error < 1e-6) && (solver.last_relative_residual() < 1e-12);
        all_good = all_good && good;
        if (!good)
          std::printf("  %s, right-hand side %u: error %.3e, residual %.3e\n",
                      type.c_str(),
                      rhs,
                      error,
                      solver.last_relative_residual());
      }
    std::printf("%s, %u refinement steps: two solves accurate (error < 1e-6, "
                "residual < 1e-12): %s; factorisations: %u\n",
                type.c_str(),
                refinement_steps,
                all_good ? "yes" : "no",
                solver.n_factorizations());

    // A zero solution for a zero right-hand side, without a solve.
    b = 0;
    x = 1;
    solver.solve(a, x, b);
    std::printf("  zero right-hand side: x = 0: %s, residual %g\n",
                x.linfty_norm() == 0 ? "yes" : "no",
                solver.last_relative_residual());

    // A singular matrix.
    TrilinosWrappers::SparseMatrix s;
    make_matrix(s, 1., true);
    try
      {
        solver.initialize(s, {}, true, false);
        std::printf("  singular matrix: accepted\n");
      }
    catch (const ExceptionBase &e)
      {
        const std::string what = e.what();
        std::printf("  singular matrix refused, the message names the cause: "
                    "%s\n",
                    (what.find("could not") != std::string::npos &&
                     what.find("singular") != std::string::npos) ?
                      "yes" :
                      "no");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string type : {"direct", "MUMPS"})
    for (const unsigned int steps : {0u, 2u})
      check(type, steps);
}
