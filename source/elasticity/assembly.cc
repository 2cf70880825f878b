// The elastic system's assembly: the stored matrices, the lumped mass, the
// absorbing dashpots and the loads; the effective stiffness and its
// algebraic preconditioner; the rigid-body modes.

#include <rupture/discretization/discretization.h>
#include <rupture/elasticity/system.h>
#include <rupture/fault/fault.h>
#include <rupture/material/elastic_material.h>
#include <rupture/operators/fault_zone_damping.h>
#include <rupture/operators/local_elasticity.h>
#include <rupture/scene/boundary_conditions.h>
#include <rupture/solver/linear_solver.h>
#include <rupture/time_integration/time_state.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rupture
{
  namespace Elasticity
  {
    template <int dim>
    void
    System<dim>::assemble()
    {
      TimerOutput::Scope t(timer, "Assemble matrices");
      if (has_absorbing())
        absorbing_blocks.reinit(dim,
                                discretization.locally_owned_dofs(),
                                communicator);
      using Scheme            = TimeIntegration::Scheme;
      const Scheme run_scheme = time_parameters.scheme;

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
      const bool need_mass = (run_scheme == Scheme::implicit_newmark &&
                              !use_lumped_mass && !linear_solver.matrix_free());
      // With the matrix-free operator, element stiffness matrices are only
      // computed for a stored mass matrix (the same loop): otherwise the
      // cells only contribute loads and lumped masses.
      const bool need_matrices = !stiffness_matrix_free || need_mass;
      // Constants that vary in space need the points of evaluation.
      const bool        varying = materials.varies_in_space();
      const UpdateFlags points =
        varying ? update_quadrature_points : update_default;
      hp::FEValues<dim>     hp_values(discretization.fe_collection(),
                                  q_cells,
                                  update_values | update_JxW_values | points |
                                    (need_matrices ? update_gradients :
                                                         update_default));
      hp::FEValues<dim>     hp_lumped(discretization.fe_collection(),
                                  q_lumped,
                                  update_values | update_JxW_values | points);
      hp::FEFaceValues<dim> hp_faces(discretization.fe_collection(),
                                     q_faces,
                                     update_values | update_normal_vectors |
                                       update_JxW_values | points);
      hp::FEFaceValues<dim> hp_load_faces(discretization.fe_collection(),
                                          q_load_faces,
                                          update_values | update_JxW_values);

      FullMatrix<double>                   k, mass;
      Vector<double>                       lumped, absorbing, load;
      std::array<Vector<double>, dim - 1>  coupling;
      std::vector<types::global_dof_index> dofs;
      std::vector<unsigned int>            component;

      Tensor<1, dim> g;
      g[dim - 1] = -gravity;
      // The same check on every rank: all have all materials.
      std::ostringstream gravity_text;
      gravity_text << gravity;
      // (Densities given as functions are at most 1e6 kg/m^3.)
      for (unsigned int i = 0; i < materials.n_materials(); ++i)
        AssertThrow(
          std::isfinite(
            (materials.given_as_functions(i) ? 1e6 : materials.get(i).density) *
            gravity),
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
              component[i] = fe.system_to_component_index(i).first -
                             u.first_vector_component;

            const types::material_id id = cell->material_id();
            const std::function<Material::ElasticConstants(const Point<dim> &)>
              local = [&](const Point<dim> &p) { return materials.at(id, p); };
            // The density at quadrature point q of @p values.
            const auto density = [&](const FEValues<dim> &values,
                                     const unsigned int   q) {
              return varying ?
                       materials.at(id, values.quadrature_point(q)).density :
                       m.density;
            };
            if (need_matrices)
              Operators::local_elasticity_matrices(fe_values,
                                                   u,
                                                   m,
                                                   k,
                                                   need_mass ? &mass : nullptr,
                                                   varying ? &local : nullptr);
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
                {
                  const double rho = density(fe_values, q);
                  for (unsigned int i = 0; i < n; ++i)
                    load(i) += rho *
                               (g[component[i]] * fe_values.shape_value(i, q)) *
                               fe_values.JxW(q);
                }

            if (use_lumped_mass)
              {
                // Gauss-Lobatto points coincide with the nodes, so this mass
                // is diagonal: the lumped mass.
                hp_lumped.reinit(cell);
                const FEValues<dim> &lv = hp_lumped.get_present_fe_values();
                lumped.reinit(n);
                for (const unsigned int q : lv.quadrature_point_indices())
                  {
                    const double rho = density(lv, q);
                    for (unsigned int i = 0; i < n; ++i)
                      lumped(i) += rho *
                                   dealii::Utilities::fixed_power<2>(
                                     lv.shape_value(i, q)) *
                                   lv.JxW(q);
                  }
                discretization.hanging_constraints().distribute_local_to_global(
                  lumped, dofs, lumped_mass_vector);
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
                if (has_absorbing() &&
                    std::find(boundary_conditions.absorbing.begin(),
                              boundary_conditions.absorbing.end(),
                              id) != boundary_conditions.absorbing.end())
                  {
                    // Lysmer-Kuhlemeyer dashpots, lumped to the nodes: the
                    // impedance Z = sqrt(rho Gamma(n)) per node (rho vp n n
                    // + rho vs (I - n n) if isotropic). Its diagonal goes
                    // to the vector, the rest couples a node's components
                    // (absorbing_blocks: entry k of DoF i couples it with
                    // the node's component k + 1 places further).
                    hp_faces.reinit(cell, f);
                    const FEFaceValues<dim> &fv =
                      hp_faces.get_present_fe_values();
                    absorbing.reinit(n);
                    for (auto &c : coupling)
                      c.reinit(n);
                    for (const unsigned int q : fv.quadrature_point_indices())
                      {
                        const SymmetricTensor<2, dim> z =
                          varying ?
                            materials
                              .at(cell->material_id(), fv.quadrature_point(q))
                              .template boundary_impedance<dim>(
                                fv.normal_vector(q)) :
                            m.template boundary_impedance<dim>(
                              fv.normal_vector(q));
                        for (unsigned int i = 0; i < n; ++i)
                          {
                            const unsigned int c =
                              cell->get_fe()
                                .system_to_component_index(i)
                                .first %
                              dim;
                            const double w =
                              fv[u].value(i, q).norm_square() * fv.JxW(q);
                            absorbing(i) += z[c][c] *
                                            fv[u].value(i, q).norm_square() *
                                            fv.JxW(q);
                            for (unsigned int k = 0; k + 1 < dim; ++k)
                              coupling[k](i) += z[c][(c + k + 1) % dim] * w;
                          }
                      }
                    for (unsigned int k = 0; k + 1 < dim; ++k)
                      discretization.hanging_constraints()
                        .distribute_local_to_global(
                          coupling[k], dofs, absorbing_blocks.coefficients(k));
                    discretization.hanging_constraints()
                      .distribute_local_to_global(absorbing,
                                                  dofs,
                                                  absorbing_vector);
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
        lumped_mass_vector.compress(VectorOperation::add);
      if (has_absorbing())
        {
          absorbing_vector.compress(VectorOperation::add);
          set_absorbing_siblings();
          absorbing_blocks.finalize(absorbing_vector);
        }
    }



    template <int dim>
    void
    System<dim>::set_absorbing_siblings()
    {
      // Every owned DoF of a cell with an absorbing face, ghost cells
      // included (a node's coefficients may come from another process's
      // faces).
      std::vector<types::global_dof_index> dofs;
      const IndexSet &owned = discretization.locally_owned_dofs();
      const auto     &ids   = boundary_conditions.absorbing;
      for (const auto &cell :
           discretization.dof_handler().active_cell_iterators())
        {
          if (cell->is_artificial() || !cell->at_boundary())
            continue;
          bool absorbing_face = false;
          for (const auto f : cell->face_indices())
            absorbing_face =
              absorbing_face ||
              (cell->face(f)->at_boundary() &&
               std::find(ids.begin(),
                         ids.end(),
                         cell->face(f)->boundary_id()) != ids.end());
          if (!absorbing_face)
            continue;
          const FiniteElement<dim> &fe    = cell->get_fe();
          const unsigned int        first = cell->active_fe_index() * dim;
          dofs.resize(fe.n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              const auto [component, index] = fe.system_to_component_index(i);
              if (component < first || component >= first + dim ||
                  !owned.is_element(dofs[i]))
                continue;
              const unsigned int c = component - first;
              for (unsigned int k = 0; k + 1 < dim; ++k)
                absorbing_blocks.set_sibling(
                  dofs[i],
                  k,
                  dofs[fe.component_to_system_index(first + (c + k + 1) % dim,
                                                    index)]);
            }
        }
    }



    template <int dim>
    void
    System<dim>::set_effective_stiffness(const double stiffness_factor,
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
                                use_lumped_mass ? lumped_mass_vector :
                                                  consistent_mass_diagonal);
          if (absorbing_factor != 0 && has_absorbing())
            system_diagonal.add(absorbing_factor, absorbing_vector);
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
          k *= stiffness_factor +
               ((zone_factor != 0 && fault_zone->contains(cell)) ? zone_factor :
                                                                   0.);
          if (with_mass)
            k.add(mass_factor, mass);
          discretization.increment_constraints().distribute_local_to_global(
            k, dofs, system_matrix);
        });
      system_matrix.compress(VectorOperation::add);

      // Diagonal parts: lumped mass and absorbing dashpots.
      if ((mass_factor != 0 && use_lumped_mass) ||
          (absorbing_factor != 0 && has_absorbing()))
        {
          for (const auto i : discretization.locally_owned_dofs())
            if (!discretization.increment_constraints().is_constrained(i))
              {
                double d = 0;
                if (mass_factor != 0 && use_lumped_mass)
                  d += mass_factor * lumped_mass_vector(i);
                if (absorbing_factor != 0 && has_absorbing())
                  d += absorbing_factor * absorbing_vector(i);
                system_matrix.add(i, i, d);
              }
          system_matrix.compress(VectorOperation::add);
        }
      if (absorbing_factor != 0 && has_absorbing() && !absorbing_blocks.empty())
        absorbing_blocks.add_to(system_matrix,
                                absorbing_factor,
                                discretization.increment_constraints());

      max_system_diagonal = 0;
      for (const auto i : discretization.locally_owned_dofs())
        max_system_diagonal = std::max(max_system_diagonal,
                                       std::abs(system_matrix.diag_element(i)));
      max_system_diagonal =
        dealii::Utilities::MPI::max(max_system_diagonal, communicator);

      linear_solver.initialize(system_matrix,
                               rigid_body_modes(),
                               true,
                               discretization.degree() > 1);
    }



    template <int dim>
    void
    System<dim>::assemble_load(const double time, VectorType &load) const
    {
      load = constant_load;
      if (!body_force_given)
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
            discretization.hanging_constraints().distribute_local_to_global(
              local, dofs, load);
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
    void
    System<dim>::for_each_cell_matrix(
      const bool with_mass,
      const std::function<
        void(const typename DoFHandler<dim>::active_cell_iterator &,
             const std::vector<types::global_dof_index> &,
             FullMatrix<double> &,
             const FullMatrix<double> &)> &action,
      const std::function<
        bool(const typename DoFHandler<dim>::active_cell_iterator &)> &selected)
      const
    {
      std::vector<types::global_dof_index> dofs;
      FullMatrix<double>                   k, mass;
      const hp::QCollection<dim>           q_cells(
        QGauss<dim>(discretization.degree() + 1));
      const bool        varying = materials.varies_in_space();
      hp::FEValues<dim> hp_values(discretization.fe_collection(),
                                  q_cells,
                                  update_values | update_gradients |
                                    update_JxW_values |
                                    (varying ? update_quadrature_points :
                                               update_default));
      for (const auto &cell :
           discretization.dof_handler().active_cell_iterators())
        if (cell->is_locally_owned() && (!selected || selected(cell)))
          {
            const types::material_id id = cell->material_id();
            const std::function<Material::ElasticConstants(const Point<dim> &)>
              local = [&](const Point<dim> &p) { return materials.at(id, p); };
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
              with_mass ? &mass : nullptr,
              varying ? &local : nullptr);
            action(cell, dofs, k, mass);
          }
    }



    template <int dim>
    std::vector<std::vector<double>>
    System<dim>::rigid_body_modes() const
    {
      const unsigned int               n_modes = dim * (dim + 1) / 2;
      std::vector<std::vector<double>> modes(
        n_modes,
        std::vector<double>(discretization.locally_owned_dofs().n_elements(),
                            0.));
      discretization.for_each_support_point(
        [](const auto &cell) { return cell->is_locally_owned(); },
        [&](const auto                                 &cell,
            const std::vector<types::global_dof_index> &dofs,
            const std::vector<Point<dim>>              &points) {
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              if (!discretization.locally_owned_dofs().is_element(dofs[i]))
                continue;
              const unsigned int k =
                discretization.locally_owned_dofs().index_within_set(dofs[i]);
              const unsigned int c =
                cell->get_fe().system_to_component_index(i).first % dim;
              const Point<dim> &x = points[i];
              modes[c][k]         = 1;
              if (dim == 2)
                modes[2][k] = (c == 0 ? -x[1] : x[0]);
              else
                {
                  // Rotations about the z, x and y axes.
                  const double rz[3] = {-x[1], x[0], 0};
                  const double rx[3] = {0, -x[2], x[1]};
                  const double ry[3] = {x[2], 0, -x[0]};
                  modes[3][k]        = rz[c];
                  modes[4][k]        = rx[c];
                  modes[5][k]        = ry[c];
                }
            }
        });
      return modes;
    }



    template class System<2>;
    template class System<3>;
  } // namespace Elasticity
} // namespace rupture
