#include <rupture/fault/fault.h>
#include <rupture/time_integration/quasi_static.h>

#include <functional>

namespace rupture
{
  namespace TimeIntegration
  {
    template <int dim>
    Scheme
    QuasiStatic<dim>::scheme() const
    {
      return Scheme::quasi_static;
    }



    template <int dim>
    void
    QuasiStatic<dim>::prepare()
    {
      this->context.system.set_effective_stiffness(1, 0, 0);
    }



    template <int dim>
    void
    QuasiStatic<dim>::step()
    {
      // Try the step; if Newton's method fails, restore the displacement
      // (the fault state changes only when a step converged) and redo it
      // as two half steps, recursively, up to <Solver/Maximum step cuts>
      // times. The step controller hears of each cut (a controller that
      // adapts then goes on from the half step that converged).
      using Solver::NewtonFailure;
      Context<dim>      &s   = this->context;
      const double       end = s.state.time, dt = s.state.time_step;
      const unsigned int cuts = s.newton_parameters.max_step_cuts;
      std::function<void(double, double, unsigned int)> attempt =
        [&](const double t_start, const double h, const unsigned int depth) {
          const VectorType u(s.state.displacement);
          s.state.time_step = h;
          s.state.time      = t_start + h;
          if (s.fault)
            s.fault->set_time(s.state.time);
          // (Newton iterates on through a stall here, to its iteration
          // limit: only a step that fails outright is cut, so a run that
          // converged before is the same.)
          s.newton.may_cut = false;
          try
            {
              substep();
            }
          catch (const NewtonFailure &failure)
            {
              if (depth == cuts)
                throw NewtonFailure(
                  std::string(failure.what()) +
                    (cuts > 0 ? " The step was cut " + std::to_string(depth) +
                                  " times (<Solver/Maximum step "
                                  "cuts>)." :
                                std::string(" No step was cut (<Solver/"
                                            "Maximum step cuts> = 0).")),
                  failure.reason);
              s.state.displacement = u;
              s.pcout << "    Newton failed with dt = " << h << " s ("
                      << failure.reason << "): the step is cut in half\n";
              ++s.newton.n_step_cuts;
              ++s.newton.total_step_cuts;
              this->controller->reject(h);
              attempt(t_start, h / 2, depth + 1);
              attempt(t_start + h / 2, h / 2, depth + 1);
            }
        };
      attempt(end - dt, dt, 0);
      s.state.time_step = dt;
      s.state.time      = end;
    }



    template <int dim>
    void
    QuasiStatic<dim>::substep()
    {
      Context<dim>      &s = this->context;
      TimerOutput::Scope t(s.timer, "Quasi-static step");
      const VectorType   old_u(s.state.displacement);
      VectorType load(s.state.displacement), residual(s.state.displacement),
        tmp(s.state.displacement), zero(s.state.displacement);
      s.system.assemble_load(s.state.time, load);

      const auto compute_residual = [&]() {
        this->static_residual(load, residual, tmp);
      };
      s.nonlinear.solve(
        old_u, []() {}, compute_residual, residual);

      // The rate of the loading, for output; no inertia.
      s.state.velocity = s.state.displacement;
      s.state.velocity -= old_u;
      s.state.velocity /= s.state.time_step;
      zero = 0;
      this->accept_step(old_u, load, residual, zero);
    }



    template class QuasiStatic<2>;
    template class QuasiStatic<3>;
  } // namespace TimeIntegration
} // namespace rupture
