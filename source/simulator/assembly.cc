// The phases of a run: the operators of the mesh assembled, the time step
// of a phase (the explicit stable step), its integrator and what the
// integrators work with; the L2 error against an exact displacement.

#include <rupture/operators/local_elasticity.h>
#include <rupture/simulator/simulator.h>

#include <deal.II/base/partitioner.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <sstream>

namespace rupture
{
  template <int dim>
  void
  Simulator<dim>::assemble_physics_matrices(const bool prepare_first_phase)
  {
    elastic_system.assemble();

    // The first phase: the quasi-static loading phase, or the run itself.
    if (!prepare_first_phase)
      return;
    using Scheme        = TimeIntegration::Scheme;
    const Scheme scheme = time_parameters.scheme;
    if (time_parameters.loading_phase)
      prepare_phase(Scheme::quasi_static,
                    time_parameters.loading_time_step,
                    time_parameters.loading_end_time);
    else
      prepare_phase(scheme,
                    time_parameters.time_step,
                    time_parameters.end_time);
  }



  template <int dim>
  double
  Simulator<dim>::n_steps_of_phase(const double duration,
                                   const double requested_time_step) const
  {
    const double n_steps =
      TimeIntegration::PhaseClock::steps_to_cover(duration,
                                                  requested_time_step);
    if (!(n_steps >= 1 && n_steps <= 1e9))
      {
        std::ostringstream message;
        message << "The phase of " << duration << " s with time steps of "
                << requested_time_step << " s would take ";
        if (n_steps < 1)
          message << "less than one step";
        else
          message << n_steps << " steps";
        message << ". Allowed are 1 to 1e9 steps: check <Time "
                   "integration/End time>, <Time integration/Time step> and "
                   "<Time integration/Courant fraction> (for the loading "
                   "phase <Time integration/Loading phase/End time> and "
                   "<Time integration/Loading phase/Time step>).";
        AssertThrow(false, ExcMessage(message.str()));
      }
    return n_steps;
  }



  template <int dim>
  void
  Simulator<dim>::prepare_phase(const TimeIntegration::Scheme scheme,
                                const double requested_time_step,
                                const double duration,
                                const bool   within_phase)
  {
    using Scheme = TimeIntegration::Scheme;
    // Without inertia the stiffness alone must hold the body: a direction
    // that no boundary condition holds anywhere leaves it free to move, the
    // system singular, and the solver would break down.
    if (scheme == Scheme::quasi_static)
      {
        const auto              held_here = discretization.held_components();
        std::array<double, dim> held{};
        for (unsigned int c = 0; c < dim; ++c)
          held[c] =
            dealii::Utilities::MPI::max(held_here[c] ? 1. : 0., communicator);
        std::string  free_directions;
        unsigned int n_free = 0;
        for (unsigned int c = 0; c < dim; ++c)
          if (held[c] == 0)
            free_directions +=
              std::string(n_free++ == 0 ? "" : " and ") + "xyz"[c];
        AssertThrow(
          free_directions.empty(),
          ExcMessage(
            std::string("The quasi-static ") +
            (time_parameters.loading_phase ? "loading phase" : "run") +
            " has no boundary condition that holds the model in the " +
            free_directions + (n_free > 1 ? " directions" : " direction") +
            ": without inertia nothing keeps the body from moving "
            "as a whole, its stiffness matrix is singular and no solver can "
            "find its displacement. Allowed: at least one boundary that holds "
            "each direction, with <Boundary conditions/Fixed>, <Boundary "
            "conditions/Roller> or <Boundary conditions/Prescribed "
            "velocity>."));
      }
    // The time step, and for the explicit scheme its stability check.
    state.time_step = requested_time_step;
    if (scheme == Scheme::explicit_central_difference)
      {
        const double omega =
          element_frequencies.highest(discretization.dof_handler(),
                                      materials,
                                      discretization.degree(),
                                      communicator);
        stable_time_step = TimeIntegration::central_difference_stable_step(
          omega,
          elastic_system.rayleigh_alpha(),
          elastic_system.rayleigh_beta(),
          elastic_system.fault_zone_fraction_in_use());
        if (!within_phase)
          pcout << "   Stable explicit time step: " << std::setprecision(6)
                << stable_time_step << " s (highest element frequency " << omega
                << " rad/s)\n";
        if (state.time_step == 0)
          state.time_step = time_parameters.courant_fraction * stable_time_step;
        else
          AssertThrow(time_parameters.allow_unstable_time_step ||
                        state.time_step <= stable_time_step,
                      ExcMessage(
                        "<Time integration/Time step> = " +
                        std::to_string(state.time_step) +
                        " s is above the stable limit of the explicit scheme "
                        "on this mesh, " +
                        std::to_string(stable_time_step) +
                        " s. Allowed are steps up to that limit; set <Time "
                        "step> = 0 to use <Courant fraction> times it, or "
                        "use the implicit scheme."));
      }
    // The steps fit the phase, or within it the rest of its current
    // segment (the mesh changed, and with it the stable step).
    const double span =
      within_phase ? state.clock.segment_duration(duration) : duration;
    state.time_step = span / n_steps_of_phase(span, state.time_step);

    // Within a phase the new integrator goes on from the old one's state.
    BinaryIO::Records records;
    if (within_phase && integrator)
      integrator->save(records);
    elastic_system.set_scheme(scheme);
    integrator = TimeIntegration::create(scheme, integrator_context());
    if (within_phase && !records.empty())
      integrator->load(records);
    integrator->prepare();
  }



  template <int dim>
  TimeIntegration::Context<dim>
  Simulator<dim>::integrator_context()
  {
    return {state,
            energy,
            time_parameters,
            elastic_system,
            newton,
            discretization,
            fault.get(),
            newton.status(),
            newton.parameters(),
            timer,
            pcout};
  }



  template <int dim>
  double
  Simulator<dim>::compute_l2_error(const double time) const
  {
    const VectorType &u_ghost =
      discretization.ghosted_copy(0, state.displacement);
    exact_displacement->set_time(time);
    const hp::QCollection<dim> q_cells(
      QGauss<dim>(discretization.degree() + 2));
    hp::FEValues<dim>           hp_values(discretization.fe_collection(),
                                q_cells,
                                update_values | update_quadrature_points |
                                  update_JxW_values);
    double                      error = 0;
    std::vector<Tensor<1, dim>> uh;
    Vector<double>              exact(dim);
    for (const auto &cell :
         discretization.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const FEValuesExtractors::Vector u(cell->active_fe_index() * dim);
          hp_values.reinit(cell);
          const FEValues<dim> &fe_values = hp_values.get_present_fe_values();
          uh.resize(fe_values.n_quadrature_points);
          fe_values[u].get_function_values(u_ghost, uh);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              exact_displacement->vector_value(fe_values.quadrature_point(q),
                                               exact);
              for (unsigned int d = 0; d < dim; ++d)
                error += std::pow(uh[q][d] - exact(d), 2) * fe_values.JxW(q);
            }
        }
    return std::sqrt(dealii::Utilities::MPI::sum(error, communicator));
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
