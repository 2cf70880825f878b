#ifndef rupture_simulator_services_h
#define rupture_simulator_services_h

#include <rupture/simulator/simulator.h>

namespace rupture
{
  /**
   * The time integrators' contracts implemented with the simulator's
   * members (a nested class, so it reaches them without friendship). Each
   * function forwards to one member function, or is the verbatim loop the
   * integrator did itself before, so that results keep their bits. The
   * later steps of doc/design-core-plan.md give the elastic system and
   * Newton classes of their own, which then implement these contracts, and
   * this class goes away (the discretization already implements
   * TimeIntegration::Kinematics itself).
   */
  template <int dim>
  class Simulator<dim>::Services final : public Operators::ElasticSystem,
                                         public Solver::NonlinearStep
  {
  public:
    using VectorType = typename Simulator<dim>::VectorType;

    explicit Services(Simulator<dim> &simulator)
      : s(simulator)
    {}

    // Operators::ElasticSystem
    void
    apply_stiffness(const VectorType &x, VectorType &y) const override
    {
      s.apply_stiffness(x, y);
    }
    const double *
    apply_stiffness_in_place(const VectorType &x) const override
    {
      return s.apply_stiffness_in_place(x);
    }
    void
    apply_mass(const VectorType &x, VectorType &y) const override
    {
      s.apply_mass(x, y);
    }
    void
    damping_force(const VectorType &v, VectorType &y) const override
    {
      s.compute_damping_force(v, y);
    }
    void
    absorbing_force(const VectorType &v, VectorType &y) const override
    {
      s.compute_absorbing_force(v, y);
    }
    void
    set_effective_stiffness(const double k,
                            const double m,
                            const double c) override
    {
      s.assemble_system_matrix(k, m, c);
    }
    const VectorType &
    load(const double t) override
    {
      return s.current_load(t);
    }
    void
    assemble_load(const double t, VectorType &f) const override
    {
      s.assemble_load_vector(t, f);
    }
    const VectorType &
    lumped_mass() const override
    {
      return s.lumped_mass;
    }
    const VectorType *
    absorbing_damping() const override
    {
      return s.has_absorbing ? &s.absorbing_damping : nullptr;
    }
    double
    rayleigh_alpha() const override
    {
      return s.rayleigh_alpha;
    }
    double
    rayleigh_beta() const override
    {
      return s.rayleigh_beta;
    }
    double
    fault_zone_viscosity() const override
    {
      return s.fault_zone_viscosity();
    }
    void
    add_fault_zone_force(const double      factor,
                         const VectorType &v,
                         VectorType       &y) const override
    {
      s.fault_zone->vmult_add(factor, v, y);
    }

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
