#ifndef rupture_simulator_services_h
#define rupture_simulator_services_h

#include <rupture/simulator/simulator.h>

namespace rupture
{
  /**
   * The nonlinear solve of a step (Solver::NonlinearStep) implemented with
   * the simulator's members (a nested class, so it reaches them without
   * friendship), until Newton's method has a class of its own
   * (doc/design-core-plan.md, S16) and this class goes away. The other
   * contracts are implemented by the discretization
   * (TimeIntegration::Kinematics) and the elastic system
   * (Operators::ElasticSystem) themselves.
   */
  template <int dim>
  class Simulator<dim>::Services final : public Solver::NonlinearStep
  {
  public:
    using VectorType = typename Simulator<dim>::VectorType;

    explicit Services(Simulator<dim> &simulator)
      : s(simulator)
    {}

    // Solver::NonlinearStep
    void
    solve(const VectorType            &old_displacement,
          const std::function<void()> &update_rates,
          const std::function<void()> &compute_residual,
          VectorType                  &residual,
          const VectorType            *predicted_increment) override
    {
      s.solve_step(old_displacement,
                   update_rates,
                   compute_residual,
                   residual,
                   predicted_increment);
    }
    void
    add_contact_force(VectorType &force) override
    {
      s.assemble_contact(force, false, 1);
    }

  private:
    Simulator<dim> &s;
  };
} // namespace rupture

#endif
