#ifndef rupture_time_integration_kinematics_h
#define rupture_time_integration_kinematics_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <mpi.h>

namespace rupture
{
  namespace TimeIntegration
  {
    /**
     * What a time integrator needs to know of the discretization: the
     * locally owned DoFs, the DoFs tied to others (hanging and welded
     * nodes) and those whose motion is prescribed (kinematic boundaries),
     * and how to impose both.
     */
    class Kinematics
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      virtual ~Kinematics() = default;

      virtual const dealii::IndexSet &
      owned_dofs() const = 0;
      virtual MPI_Comm
      communicator() const = 0;
      /// The hanging-node and welded-node constraints.
      virtual const dealii::AffineConstraints<double> &
      hanging_constraints() const = 0;
      /// Those plus the kinematic boundaries: what a step's increment is
      /// constrained by.
      virtual const dealii::AffineConstraints<double> &
      increment_constraints() const = 0;
      /// Set the tied DoFs of @p v from their constraints.
      virtual void
      distribute_hanging(VectorType &v) const = 0;
      /// Set the prescribed velocity at time @p t in @p v.
      virtual void
      set_kinematic_velocity(VectorType &v, const double t) const = 0;
      /// u = old_u + dt v(t - dt/2) at the kinematically held DoFs.
      virtual void
      impose_kinematic_motion(const VectorType &old_u,
                              VectorType       &u,
                              const double      t,
                              const double      dt) const = 0;
    };
  } // namespace TimeIntegration
} // namespace rupture

#endif
