// The Kelvin-Voigt damping of the cells at the fault (<Damping/Fault zone
// damping>): which cells, their stiffness, and its coefficient now.

#include <rupture/simulator/simulator.h>

namespace rupture
{
  template <int dim>
  void
  Simulator<dim>::setup_fault_zone_damping()
  {
    fault_zone.reset();
    if (fault_zone_fraction != 0 && !fault)
      pcout << "   Fault zone damping: the scene has no fault, so there is "
               "nothing to damp\n";
    if (!fault || fault_zone_fraction == 0)
      return;
    TimerOutput::Scope t(timer, "Fault zone set-up");
    fault_zone = std::make_unique<Operators::FaultZoneDamping<dim>>();
    fault_zone->reinit(
      discretization.dof_handler(),
      discretization.hanging_constraints(),
      [this](const std::vector<types::global_dof_index> &dofs) {
        return fault->touches_fault_region(dofs);
      },
      stiffness_matrix_free ? elastic_operator.get() : nullptr,
      discretization.locally_owned_dofs(),
      discretization.locally_relevant_dofs(),
      communicator);
    pcout << "   Fault zone damping: " << fault_zone->n_cells()
          << " cells touch the fault region, eta = " << fault_zone_fraction
          << " dt\n";
    if (!fault_zone->stored())
      return;
    // Without the matrix-free operator: the zone's stiffness, stored.
    TrilinosWrappers::SparseMatrix &k = fault_zone->matrix();
    for_each_cell_matrix(
      false,
      [&](const auto &,
          const std::vector<types::global_dof_index> &dofs,
          FullMatrix<double>                         &cell_matrix,
          const FullMatrix<double> &) {
        discretization.hanging_constraints().distribute_local_to_global(
          cell_matrix, dofs, k);
      },
      [this](const auto &cell) { return fault_zone->contains(cell); });
    k.compress(VectorOperation::add);
  }



  template <int dim>
  double
  Simulator<dim>::fault_zone_viscosity() const
  {
    return fault_zone ? fault_zone_fraction * state.time_step : 0.;
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
