#ifndef rupture_nonlinear_newton_h
#define rupture_nonlinear_newton_h

#include <rupture/solver/newton.h>
#include <rupture/solver/nonlinear_step.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <string>

namespace rupture
{
  namespace Discretization
  {
    template <int dim>
    class Discretization;
  }
  namespace Elasticity
  {
    template <int dim>
    class System;
  }
  namespace Fault
  {
    template <int dim>
    class Fault;
  }
  namespace Solver
  {
    class LinearSolver;
  }
  namespace TimeIntegration
  {
    struct TimeState;
  }

  /**
   * The nonlinear solve of an implicit or quasi-static step.
   */
  namespace Nonlinear
  {
    using namespace dealii;

    /**
     * Newton's method on the displacement of a step with the fault's
     * contact forces and their consistent tangent (the paper's Fig. 6):
     * an inexact Newton method with a backtracking line search, the
     * paper's two convergence criteria, the stick-crossing safeguard, and
     * a diagnosis of why it failed (Solver::NewtonFailure, so that the
     * time integrator can cut the step). Without a fault one linear solve.
     *
     * It iterates on the displacement of the time state, through the
     * elastic system's effective stiffness (stored, with the contact
     * tangent added for each solve, or matrix-free with the fault pairs'
     * tangents in the preconditioner) and the linear solver; it owns its
     * controls (<Solver>'s Newton entries) and what it reports
     * (Solver::NewtonStatus).
     */
    template <int dim>
    class Newton final : public Solver::NonlinearStep
    {
    public:
      using VectorType = TrilinosWrappers::MPI::Vector;
      /// Stops the run, naming the place and the likely cause, if the
      /// vector (described by the string) is not finite.
      using FiniteCheck =
        std::function<void(const VectorType &, const std::string &)>;

      Newton(TimeIntegration::TimeState                &state,
             const Discretization::Discretization<dim> &discretization,
             Elasticity::System<dim>                   &system,
             Solver::LinearSolver                      &linear_solver,
             TimerOutput                               &timer,
             ConditionalOStream                        &pcout,
             const FiniteCheck                         &check_finite);

      /// Read <Solver>'s Newton entries (the caller has entered the
      /// subsection; they are declared with the linear solver's).
      void
      parse_parameters(ParameterHandler &prm);
      /// The fault whose contact makes the step nonlinear (none: linear).
      void
      set_fault(Fault::Fault<dim> *fault)
      {
        this->fault = fault;
      }

      const Solver::NewtonParameters &
      parameters() const
      {
        return controls;
      }
      Solver::NewtonStatus &
      status()
      {
        return report;
      }
      const Solver::NewtonStatus &
      status() const
      {
        return report;
      }

      // Solver::NonlinearStep
      void
      solve(const VectorType            &old_displacement,
            const std::function<void()> &update_rates,
            const std::function<void()> &compute_residual,
            VectorType                  &residual,
            const VectorType            *predicted_increment,
            const bool                   hold) override;
      void
      add_contact_force(VectorType &force) override
      {
        assemble_contact(force, false, 1);
      }

      /**
       * Add the contact forces at the current displacement to @p force
       * (and @p sign times the contact tangent to the effective stiffness
       * matrix if asked).
       */
      void
      assemble_contact(VectorType  &force,
                       const bool   with_tangent,
                       const double sign);

    private:
      /// Throw Solver::NewtonFailure for iteration @p norm / @p reference
      /// (@p stalled or at the limit), with the diagnosis.
      [[noreturn]] void
      fail(const bool                        stalled,
           const double                      norm,
           const double                      reference,
           const double                      increment_ratio,
           const std::vector<unsigned long> &signatures) const;

      TimeIntegration::TimeState                &state;
      const Discretization::Discretization<dim> &discretization;
      Elasticity::System<dim>                   &system;
      Solver::LinearSolver                      &linear_solver;
      TimerOutput                               &timer;
      ConditionalOStream                        &pcout;
      FiniteCheck                                check_finite;
      Fault::Fault<dim>                         *fault = nullptr;
      Solver::NewtonParameters                   controls;
      Solver::NewtonStatus                       report;
    };
  } // namespace Nonlinear
} // namespace rupture

#endif
