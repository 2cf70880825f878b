#ifndef rupture_operators_elastic_system_h
#define rupture_operators_elastic_system_h

#include <deal.II/lac/trilinos_vector.h>

namespace rupture
{
  namespace Operators
  {
    class NodeCoupling;

    /**
     * The elastic body as a time integrator sees it: products with the
     * stiffness K and the mass M, the damping forces (Rayleigh, the fault
     * zone's Kelvin-Voigt layer, the absorbing boundaries), the loads, and
     * the effective stiffness k K + m M + c C_absorbing of the implicit
     * solves. Matrix-free or with stored matrices: the integrators do not
     * know which. All vectors are the locally owned, distributed vectors
     * of the displacement's DoFs.
     */
    class ElasticSystem
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      virtual ~ElasticSystem() = default;

      /// y = K x.
      virtual void
      apply_stiffness(const VectorType &x, VectorType &y) const = 0;
      /// K x left in the matrix-free operator's destination vector (the
      /// owned entries, valid until its next product); nullptr without a
      /// matrix-free operator.
      virtual const double *
      apply_stiffness_in_place(const VectorType &x) const = 0;
      /// y = M x (lumped or consistent, as the run asks).
      virtual void
      apply_mass(const VectorType &x, VectorType &y) const = 0;
      /// y = C v: every damping force at the velocity @p v (none in a
      /// quasi-static phase), zero at tied DoFs.
      virtual void
      damping_force(const VectorType &v, VectorType &y) const = 0;
      /// y = C_absorbing v: the absorbing boundaries' dashpots alone.
      virtual void
      absorbing_force(const VectorType &v, VectorType &y) const = 0;
      /// The effective stiffness of the coming solves:
      /// @p k K + @p m M + @p c C_absorbing (Rayleigh damping folded into
      /// the first two factors).
      virtual void
      set_effective_stiffness(const double k,
                              const double m,
                              const double c) = 0;
      /// The load vector at time @p t (valid until the next call).
      virtual const VectorType &
      load(const double t) = 0;
      /// Assemble the load vector at time @p t into @p f.
      virtual void
      assemble_load(const double t, VectorType &f) const = 0;
      /// The lumped (diagonal) mass.
      virtual const VectorType &
      lumped_mass() const = 0;
      /// The absorbing boundaries' diagonal dashpots; nullptr without them.
      virtual const VectorType *
      absorbing_damping() const = 0;
      /// The coupling of a node's components by the absorbing dashpots
      /// (their off-diagonal part); nullptr without it.
      virtual const NodeCoupling *
      absorbing_coupling() const = 0;
      /// Rayleigh damping C = alpha M + beta K.
      virtual double
      rayleigh_alpha() const = 0;
      virtual double
      rayleigh_beta() const = 0;
      /// The fault zone's Kelvin-Voigt coefficient eta (s) for the current
      /// time step, 0 without the zone.
      virtual double
      fault_zone_viscosity() const = 0;
      /// y += factor K_zone v.
      virtual void
      add_fault_zone_force(const double      factor,
                           const VectorType &v,
                           VectorType       &y) const = 0;
    };
  } // namespace Operators
} // namespace rupture

#endif
