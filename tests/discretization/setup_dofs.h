// The DoFs and constraints of a discretization with a fault, set up as
// Simulator::setup_dofs() does: the fault's pairs are set up in the hook
// between the hanging nodes and the closing of the constraints.
#ifndef rupture_tests_discretization_setup_dofs_h
#define rupture_tests_discretization_setup_dofs_h

#include <rupture/discretization/discretization.h>
#include <rupture/fault/fault.h>
#include <rupture/scene/boundary_conditions.h>

#include <vector>

namespace tests
{
  /// Distribute the DoFs of @p discretization and make their constraints,
  /// with @p fault (one material of shear modulus @p mu) and the kinematic
  /// boundaries of @p boundary_conditions.
  template <int dim>
  void
  setup_dofs(rupture::Discretization::Discretization<dim>  &discretization,
             rupture::Fault::Fault<dim>                    &fault,
             const rupture::Scene::BoundaryConditions<dim> &boundary_conditions,
             const double                                   mu)
  {
    discretization.distribute_dofs();
    discretization.make_constraints(
      [&](dealii::AffineConstraints<double> &constraints) {
        fault.setup(
          discretization.dof_handler(),
          discretization.locally_owned_dofs(),
          discretization.locally_relevant_dofs(),
          constraints,
          [mu](const dealii::types::material_id,
               const dealii::Tensor<1, dim> &,
               const dealii::Point<dim> &) {
            return std::array<double, 2>{{mu, 2670.}};
          },
          MPI_COMM_WORLD);
      },
      boundary_conditions);
  }
} // namespace tests

#endif
