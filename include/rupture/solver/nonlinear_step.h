#ifndef rupture_solver_nonlinear_step_h
#define rupture_solver_nonlinear_step_h

#include <deal.II/lac/trilinos_vector.h>

#include <functional>

namespace rupture
{
  namespace Solver
  {
    /**
     * The nonlinear solve of an implicit or quasi-static step: Newton's
     * method on the displacement with the fault's contact forces and their
     * consistent tangent. The time integrator says how the velocity and
     * acceleration follow from the displacement and what the residual of
     * its other forces is; the solver iterates on the time state's
     * displacement in place.
     */
    class NonlinearStep
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      virtual ~NonlinearStep() = default;

      /**
       * Solve for the displacement at the new time, starting from
       * @p old_displacement plus @p predicted_increment (if given) and the
       * prescribed boundary motion. @p update_rates sets the velocity and
       * acceleration from the displacement; @p compute_residual sets
       * @p residual (all forces but the inertia already included). With
       * @p hold (a balance at a fixed time, not a step) the prescribed DoFs
       * keep their values of @p old_displacement and every closed fault
       * pair sticks on its springs (Fault::hold()). Throws
       * Solver::NewtonFailure if Newton's method does not converge.
       */
      virtual void
      solve(const VectorType            &old_displacement,
            const std::function<void()> &update_rates,
            const std::function<void()> &compute_residual,
            VectorType                  &residual,
            const VectorType            *predicted_increment = nullptr,
            const bool                   hold                = false) = 0;

      /// Add the fault's contact forces at the current displacement to
      /// @p force.
      virtual void
      add_contact_force(VectorType &force) = 0;
    };
  } // namespace Solver
} // namespace rupture

#endif
