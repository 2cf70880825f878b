#include <rupture/simulator/simulator.h>
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
      simulator.assemble_system_matrix(1, 0, 0);
    }



    template <int dim>
    void
    QuasiStatic<dim>::step()
    {
      using VectorType     = typename Simulator<dim>::VectorType;
      Simulator<dim>    &s = simulator;
      TimerOutput::Scope t(s.timer, "Quasi-static step");
      const VectorType   old_u(s.state.displacement);
      VectorType load(s.state.displacement), residual(s.state.displacement),
        tmp(s.state.displacement), zero(s.state.displacement);
      s.assemble_load_vector(s.state.time, load);

      const auto compute_residual = [&]() {
        residual = load;
        s.apply_stiffness(s.state.displacement, tmp);
        residual -= tmp;
        if (s.fault)
          {
            tmp = 0;
            s.assemble_contact(tmp, false, 1);
            residual -= tmp;
          }
      };
      s.solve_step(
        old_u, []() {}, compute_residual, residual);

      // The rate of the loading, for output; no inertia.
      s.state.velocity = s.state.displacement;
      s.state.velocity -= old_u;
      s.state.velocity /= s.state.time_step;
      zero = 0;
      s.finish_step(old_u, load, residual, zero);
    }



    template class QuasiStatic<2>;
    template class QuasiStatic<3>;
  } // namespace TimeIntegration
} // namespace rupture
