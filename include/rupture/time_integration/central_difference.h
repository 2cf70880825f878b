#ifndef rupture_time_integration_central_difference_h
#define rupture_time_integration_central_difference_h

#include <rupture/operators/node_coupling.h>
#include <rupture/time_integration/interface.h>

#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace rupture
{
  namespace TimeIntegration
  {
    /**
     * Explicit central differences: Newmark with beta = 0, gamma = 1/2 and
     * the lumped mass, so that a step needs no solve. With absorbing
     * boundaries and mass-proportional damping the step solves the
     * system (M (1 + gamma dt alpha) + gamma dt C_abs) a = r, diagonal
     * but for the blocks by which the dashpots couple a node's components
     * where the boundary is oblique to the material's axes; the
     * split-node fault adds its forces to r at its own entries only. One
     * fused pass over the owned entries does the predictors, another the
     * correctors and the energy budget.
     */
    template <int dim>
    class CentralDifference : public Interface<dim>
    {
    public:
      using VectorType = TrilinosWrappers::MPI::Vector;
      using Interface<dim>::Interface;

      Scheme
      scheme() const override;
      void
      prepare() override;
      void
      step() override;

    private:
      /// The inverse of the step's diagonal, 0 at constrained DoFs.
      VectorType inverse_diagonal;
      /// Work vectors kept between steps: the displacement at the start of
      /// the step, K u, the residual and the fault's forces.
      VectorType old_displacement, stiffness_force, residual, fault_force;
      /// eta K_zone v at the end of the step (the fault zone's damping).
      VectorType zone_force;
      /// The absorbing dashpots' coupling force at the end of the step.
      VectorType coupling_force;
      /// The inverses of the nodes' blocks M (1 + gamma dt alpha) +
      /// gamma dt C_abs where the dashpots couple a node's components
      /// (not at the fault's entries, whose force assumes the diagonal).
      Operators::NodeBlockInverse absorbing_blocks;
      /// The owned entries the split-node fault force touches.
      std::vector<unsigned int> fault_entries;
      /// What each locally owned DoF is, for the energy budget.
      enum DofKind : unsigned char
      {
        free,
        /// Tied to others: a hanging or welded node.
        tied,
        /// Held by a kinematic boundary condition.
        kinematic
      };
      std::vector<unsigned char> dof_kind;
    };
  } // namespace TimeIntegration
} // namespace rupture

#endif
