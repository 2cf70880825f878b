#include <rupture/operators/local_elasticity.h>
#include <rupture/simulator/services.h>
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
    TimerOutput::Scope t(timer, "Assemble matrices");
    using Scheme        = TimeIntegration::Scheme;
    const Scheme scheme = time_parameters.scheme;

    const hp::QCollection<dim> q_cells(
      QGauss<dim>(discretization.degree() + 1));
    const hp::QCollection<dim> q_lumped(
      QGaussLobatto<dim>(discretization.degree() + 1));
    const hp::QCollection<dim - 1> q_faces(
      QGaussLobatto<dim - 1>(discretization.degree() + 1));
    const hp::QCollection<dim - 1> q_load_faces(
      QGauss<dim - 1>(discretization.degree() + 1));
    // (The matrix-free solver applies the consistent mass through the
    // elastic operator.)
    const bool need_mass = (scheme == Scheme::implicit_newmark &&
                            !use_lumped_mass && !linear_solver.matrix_free());
    // With the matrix-free operator, element stiffness matrices are only
    // computed for a stored mass matrix (the same loop): otherwise the
    // cells only contribute loads and lumped masses.
    const bool            need_matrices = !stiffness_matrix_free || need_mass;
    hp::FEValues<dim>     hp_values(discretization.fe_collection(),
                                q_cells,
                                update_values | update_JxW_values |
                                  (need_matrices ? update_gradients :
                                                       update_default));
    hp::FEValues<dim>     hp_lumped(discretization.fe_collection(),
                                q_lumped,
                                update_values | update_JxW_values);
    hp::FEFaceValues<dim> hp_faces(discretization.fe_collection(),
                                   q_faces,
                                   update_values | update_normal_vectors |
                                     update_JxW_values);
    hp::FEFaceValues<dim> hp_load_faces(discretization.fe_collection(),
                                        q_load_faces,
                                        update_values | update_JxW_values);

    FullMatrix<double>                   k, mass;
    Vector<double>                       lumped, absorbing, load;
    std::vector<types::global_dof_index> dofs;
    std::vector<unsigned int>            component;

    Tensor<1, dim> g;
    g[dim - 1] = -gravity;
    // The same check on every rank: all have all materials.
    std::ostringstream gravity_text;
    gravity_text << gravity;
    for (unsigned int i = 0; i < materials.n_materials(); ++i)
      AssertThrow(std::isfinite(materials.get(i).density * gravity),
                  ExcMessage("<Loads/Gravity> = " + gravity_text.str() +
                             " m/s^2 times the density of material " +
                             std::to_string(i) + " (" + materials.get(i).name +
                             ") is not a finite force density. Allowed: a "
                             "finite product (e.g. 9.81 m/s^2)."));

    for (const auto &cell :
         discretization.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto &m = materials.get(cell->material_id());
          const FEValuesExtractors::Vector u(cell->active_fe_index() * dim);
          hp_values.reinit(cell);
          const FEValues<dim> &fe_values = hp_values.get_present_fe_values();
          const unsigned int   n         = fe_values.dofs_per_cell;
          if (need_matrices)
            k.reinit(n, n);
          if (need_mass)
            mass.reinit(n, n);
          dofs.resize(n);
          cell->get_dof_indices(dofs);
          // Every shape function has one nonzero component: the one of its
          // own scalar element (FE_Q per component, FE_Nothing for the
          // other side). Its value there is all that gravity and the lumped
          // mass need, and far cheaper than the vector of values at high
          // degree.
          const FiniteElement<dim> &fe = fe_values.get_fe();
          component.resize(n);
          for (unsigned int i = 0; i < n; ++i)
            component[i] =
              fe.system_to_component_index(i).first - u.first_vector_component;

          if (need_matrices)
            Operators::local_elasticity_matrices(
              fe_values, u, m, k, need_mass ? &mass : nullptr);
          if (!stiffness_matrix_free)
            discretization.hanging_constraints().distribute_local_to_global(
              k, dofs, stiffness_matrix);
          if (need_mass)
            discretization.hanging_constraints().distribute_local_to_global(
              mass, dofs, mass_matrix);

          // Gravity: rho g.
          load.reinit(n);
          if (gravity != 0)
            for (const unsigned int q : fe_values.quadrature_point_indices())
              for (unsigned int i = 0; i < n; ++i)
                load(i) += m.density *
                           (g[component[i]] * fe_values.shape_value(i, q)) *
                           fe_values.JxW(q);

          if (use_lumped_mass)
            {
              // Gauss-Lobatto points coincide with the nodes, so this mass
              // is diagonal: the lumped mass.
              hp_lumped.reinit(cell);
              const FEValues<dim> &lv = hp_lumped.get_present_fe_values();
              lumped.reinit(n);
              for (const unsigned int q : lv.quadrature_point_indices())
                for (unsigned int i = 0; i < n; ++i)
                  lumped(i) +=
                    m.density *
                    dealii::Utilities::fixed_power<2>(lv.shape_value(i, q)) *
                    lv.JxW(q);
              discretization.hanging_constraints().distribute_local_to_global(
                lumped, dofs, lumped_mass);
            }

          for (const auto f : cell->face_indices())
            {
              if (!cell->face(f)->at_boundary())
                continue;
              const types::boundary_id id = cell->face(f)->boundary_id();
              for (const auto &[traction_id, traction] :
                   boundary_conditions.tractions)
                if (traction_id == id)
                  {
                    hp_load_faces.reinit(cell, f);
                    const FEFaceValues<dim> &fv =
                      hp_load_faces.get_present_fe_values();
                    for (const unsigned int q : fv.quadrature_point_indices())
                      for (unsigned int i = 0; i < n; ++i)
                        load(i) += (traction * fv[u].value(i, q)) * fv.JxW(q);
                  }
              if (has_absorbing &&
                  std::find(boundary_conditions.absorbing.begin(),
                            boundary_conditions.absorbing.end(),
                            id) != boundary_conditions.absorbing.end())
                {
                  // Lysmer-Kuhlemeyer dashpots, lumped to the nodes: the
                  // normal part rho vp, the tangential part rho vs. Exact
                  // for faces normal to a coordinate axis; on oblique faces
                  // the coupling between components is dropped.
                  hp_faces.reinit(cell, f);
                  const FEFaceValues<dim> &fv =
                    hp_faces.get_present_fe_values();
                  absorbing.reinit(n);
                  const double zp = m.density * m.p_wave_speed();
                  const double zs = m.density * m.s_wave_speed();
                  for (const unsigned int q : fv.quadrature_point_indices())
                    for (unsigned int i = 0; i < n; ++i)
                      {
                        const unsigned int c =
                          cell->get_fe().system_to_component_index(i).first %
                          dim;
                        const double nc = fv.normal_vector(q)[c];
                        absorbing(i) += (zp * nc * nc + zs * (1 - nc * nc)) *
                                        fv[u].value(i, q).norm_square() *
                                        fv.JxW(q);
                      }
                  discretization.hanging_constraints()
                    .distribute_local_to_global(absorbing,
                                                dofs,
                                                absorbing_damping);
                }
            }
          discretization.hanging_constraints().distribute_local_to_global(
            load, dofs, constant_load);
        }

    if (!stiffness_matrix_free)
      stiffness_matrix.compress(VectorOperation::add);
    if (need_mass)
      mass_matrix.compress(VectorOperation::add);
    constant_load.compress(VectorOperation::add);
    if (use_lumped_mass)
      lumped_mass.compress(VectorOperation::add);
    if (has_absorbing)
      absorbing_damping.compress(VectorOperation::add);

    // The first phase: the quasi-static loading phase, or the run itself.
    if (!prepare_first_phase)
      return;
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
                << requested_time_step << " s would take " << n_steps
                << " steps. Allowed are 1 to 1e9 steps: check <Time "
                   "integration/End time> and <Time step> (or those of its "
                   "<Loading phase>).";
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
          rayleigh_alpha,
          rayleigh_beta,
          fault_zone ? fault_zone_fraction : 0.);
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
            *services,
            *services,
            discretization,
            fault.get(),
            newton,
            newton_parameters,
            timer,
            pcout};
  }



  template <int dim>
  void
  Simulator<dim>::assemble_system_matrix(const double stiffness_factor,
                                         const double mass_factor,
                                         const double absorbing_factor)
  {
    system_factors = {stiffness_factor, mass_factor, absorbing_factor};
    if (linear_solver.matrix_free())
      {
        // Only the diagonal, for the block-Jacobi preconditioner.
        TimerOutput::Scope t(timer, "System diagonal");
        system_diagonal = stiffness_diagonal;
        system_diagonal *= stiffness_factor;
        if (mass_factor != 0)
          system_diagonal.add(mass_factor,
                              use_lumped_mass ? lumped_mass :
                                                consistent_mass_diagonal);
        if (absorbing_factor != 0 && has_absorbing)
          system_diagonal.add(absorbing_factor, absorbing_damping);
        if (absorbing_factor != 0 && fault_zone_viscosity() != 0)
          fault_zone->add_diagonal(absorbing_factor * fault_zone_viscosity(),
                                   system_diagonal);
        max_system_diagonal = system_diagonal.linfty_norm();
        return;
      }
    TimerOutput::Scope t(timer, "Assemble system matrix");
    system_matrix        = 0;
    const bool with_mass = (mass_factor != 0 && !use_lumped_mass);
    // The fault zone's Kelvin-Voigt damping adds a1 eta K there.
    const double zone_factor = absorbing_factor * fault_zone_viscosity();
    for_each_cell_matrix(
      with_mass,
      [&](const auto                                 &cell,
          const std::vector<types::global_dof_index> &dofs,
          FullMatrix<double>                         &k,
          const FullMatrix<double>                   &mass) {
        k *=
          stiffness_factor +
          ((zone_factor != 0 && fault_zone->contains(cell)) ? zone_factor : 0.);
        if (with_mass)
          k.add(mass_factor, mass);
        discretization.increment_constraints().distribute_local_to_global(
          k, dofs, system_matrix);
      });
    system_matrix.compress(VectorOperation::add);

    // Diagonal parts: lumped mass and absorbing dashpots.
    if ((mass_factor != 0 && use_lumped_mass) ||
        (absorbing_factor != 0 && has_absorbing))
      {
        for (const auto i : discretization.locally_owned_dofs())
          if (!discretization.increment_constraints().is_constrained(i))
            {
              double d = 0;
              if (mass_factor != 0 && use_lumped_mass)
                d += mass_factor * lumped_mass(i);
              if (absorbing_factor != 0 && has_absorbing)
                d += absorbing_factor * absorbing_damping(i);
              system_matrix.add(i, i, d);
            }
        system_matrix.compress(VectorOperation::add);
      }

    max_system_diagonal = 0;
    for (const auto i : discretization.locally_owned_dofs())
      max_system_diagonal =
        std::max(max_system_diagonal, std::abs(system_matrix.diag_element(i)));
    max_system_diagonal =
      dealii::Utilities::MPI::max(max_system_diagonal, communicator);

    linear_solver.initialize(system_matrix,
                             rigid_body_modes(),
                             true,
                             discretization.degree() > 1);
  }



  template <int dim>
  void
  Simulator<dim>::assemble_load_vector(const double time,
                                       VectorType  &load) const
  {
    load = constant_load;
    if (!has_body_force)
      return;
    TimerOutput::Scope t(timer, "Assemble loads");
    body_force->set_time(time);
    const hp::QCollection<dim> q_cells(
      QGauss<dim>(discretization.degree() + 1));
    hp::FEValues<dim> hp_values(discretization.fe_collection(),
                                q_cells,
                                update_values | update_quadrature_points |
                                  update_JxW_values);
    Vector<double>    local, f(dim);
    std::vector<types::global_dof_index> dofs;
    std::string                          bad_point;
    for (const auto &cell :
         discretization.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && bad_point.empty())
        {
          const FEValuesExtractors::Vector u(cell->active_fe_index() * dim);
          hp_values.reinit(cell);
          const FEValues<dim> &fe_values = hp_values.get_present_fe_values();
          const unsigned int   n         = fe_values.dofs_per_cell;
          local.reinit(n);
          dofs.resize(n);
          cell->get_dof_indices(dofs);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              body_force->vector_value(fe_values.quadrature_point(q), f);
              Tensor<1, dim> force;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  force[d] = f(d);
                  if (!std::isfinite(f(d)) && bad_point.empty())
                    {
                      std::ostringstream where;
                      where << "(" << fe_values.quadrature_point(q) << ")";
                      bad_point = where.str();
                    }
                }
              for (unsigned int i = 0; i < n; ++i)
                local(i) +=
                  (force * fe_values[u].value(i, q)) * fe_values.JxW(q);
            }
          discretization.hanging_constraints().distribute_local_to_global(local,
                                                                          dofs,
                                                                          load);
        }
    // Every process stops, not only the one that found the value.
    AssertThrow(dealii::Utilities::MPI::max(bad_point.empty() ? 0 : 1,
                                            communicator) == 0,
                ExcMessage("<Loads/Body force> is not a finite number at " +
                           (bad_point.empty() ?
                              std::string("a point of another process") :
                              bad_point) +
                           " at t = " + std::to_string(time) +
                           " s. Allowed are expressions that are finite "
                           "throughout the body and the run."));
    load.compress(VectorOperation::add);
  }



  template <int dim>
  double
  Simulator<dim>::compute_l2_error(const double time) const
  {
    const VectorType &u_ghost = ghosted_copy(0, state.displacement);
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



  template <int dim>
  void
  Simulator<dim>::for_each_cell_matrix(
    const bool with_mass,
    const std::function<
      void(const typename DoFHandler<dim>::active_cell_iterator &,
           const std::vector<types::global_dof_index> &,
           FullMatrix<double> &,
           const FullMatrix<double> &)>                        &action,
    const std::function<bool(
      const typename DoFHandler<dim>::active_cell_iterator &)> &selected) const
  {
    std::vector<types::global_dof_index> dofs;
    FullMatrix<double>                   k, mass;
    const hp::QCollection<dim>           q_cells(
      QGauss<dim>(discretization.degree() + 1));
    hp::FEValues<dim> hp_values(discretization.fe_collection(),
                                q_cells,
                                update_values | update_gradients |
                                  update_JxW_values);
    for (const auto &cell :
         discretization.dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && (!selected || selected(cell)))
        {
          const FEValuesExtractors::Vector u(cell->active_fe_index() * dim);
          hp_values.reinit(cell);
          const FEValues<dim> &fe_values = hp_values.get_present_fe_values();
          const unsigned int   n         = fe_values.dofs_per_cell;
          k.reinit(n, n);
          mass.reinit(with_mass ? n : 0, with_mass ? n : 0);
          dofs.resize(n);
          cell->get_dof_indices(dofs);
          Operators::local_elasticity_matrices<dim>(
            fe_values,
            u,
            materials.get(cell->material_id()),
            k,
            with_mass ? &mass : nullptr);
          action(cell, dofs, k, mass);
        }
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
