// Set-up of the degrees of freedom and of what depends on them: the
// discretization's DoFs and constraints (with the fault's pairs), the
// elastic system's operators, the state's vectors and the outputs.

#include <rupture/base/utilities.h>
#include <rupture/simulator/simulator.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <limits>


namespace rupture
{
  template <int dim>
  void
  Simulator<dim>::setup_dofs()
  {
    TimerOutput::Scope t(timer, "Set up DoFs");
    timer.enter_subsection("Set up DoFs: distribute");
    discretization.distribute_dofs();
    timer.leave_subsection();
    // Constants that vary in space must be positive on this mesh.
    fastest_wave_speed =
      materials.check_on_mesh(discretization.dof_handler().get_triangulation(),
                              discretization.degree(),
                              communicator);
    // The fault's welded nodes are tied before the constraints close.
    const auto add_fault = [&](AffineConstraints<double> &constraints) {
      TimerOutput::Scope t(timer, "Set up DoFs: fault");
      fault->setup(
        discretization.dof_handler(),
        discretization.locally_owned_dofs(),
        discretization.locally_relevant_dofs(),
        constraints,
        [this](const types::material_id id,
               const Tensor<1, dim>    &normal,
               const Point<dim>        &location) {
          const Material::ElasticConstants m = materials.at(id, location);
          return std::array<double, 2>{
            {m.template shear_modulus_across<dim>(normal), m.density}};
        },
        communicator);
    };
    discretization.make_constraints(
      fault ? std::function<void(AffineConstraints<double> &)>(add_fault) :
              std::function<void(AffineConstraints<double> &)>(),
      boundary_conditions);

    elastic_system.setup();
    for (VectorType *v : {&state.displacement,
                          &state.velocity,
                          &state.acceleration,
                          &energy.applied_force,
                          &energy.damping_force,
                          &energy.contact_force})
      v->reinit(discretization.locally_owned_dofs(), communicator);

    pcout << "   Degrees of freedom: " << discretization.dof_handler().n_dofs()
          << "\n";
    if (fault)
      pcout << "   Fault: " << fault->n_split_nodes() << " split node pairs, "
            << fault->n_welded_nodes() << " welded interface nodes\n";
    TimerOutput::Scope outputs(timer, "Set up DoFs: outputs");
    receivers->setup(discretization.dof_handler(),
                     discretization.locally_owned_dofs());
    if (fault)
      {
        {
          // The model's top, from which down-dip distances count.
          double top = -std::numeric_limits<double>::max();
          for (const auto &cell :
               discretization.triangulation().active_cell_iterators())
            if (cell->is_locally_owned())
              for (const auto v : cell->vertex_indices())
                top = std::max(top, cell->vertex(v)[dim - 1]);
          top = dealii::Utilities::MPI::max(top, communicator);
          fault_output->setup(*fault, communicator, top);
        }
        if (!fault->uses_split_nodes() &&
            elastic_system.effective_matrix().m() > 0)
          linear_solver.set_fault_pairs(fault->dof_pairs(),
                                        discretization.locally_owned_dofs(),
                                        communicator);
      }
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
