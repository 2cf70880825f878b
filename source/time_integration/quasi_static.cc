#include <rupture/time_integration/quasi_static.h>

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
      Context<dim>      &s = this->context;
      TimerOutput::Scope t(s.timer, "Quasi-static step");
      const VectorType   old_u(s.state.displacement);
      VectorType load(s.state.displacement), residual(s.state.displacement),
        tmp(s.state.displacement), zero(s.state.displacement);
      s.system.assemble_load(s.state.time, load);

      const auto compute_residual = [&]() {
        residual = load;
        s.system.apply_stiffness(s.state.displacement, tmp);
        residual -= tmp;
        if (s.fault)
          {
            tmp = 0;
            s.nonlinear.add_contact_force(tmp);
            residual -= tmp;
          }
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
