// The elastic system: set-up of its operators, the matrix-free and
// stored products, damping, the mass solve and the preconditioners of the
// effective stiffness.

#include <rupture/base/utilities.h>
#include <rupture/discretization/discretization.h>
#include <rupture/elasticity/system.h>
#include <rupture/fault/fault.h>
#include <rupture/material/elastic_material.h>
#include <rupture/operators/elastic_operator.h>
#include <rupture/operators/fault_zone_damping.h>
#include <rupture/operators/multigrid.h>
#include <rupture/scene/boundary_conditions.h>
#include <rupture/solver/linear_solver.h>
#include <rupture/time_integration/time_state.h>

#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>

namespace rupture
{
  namespace Elasticity
  {
    namespace
    {
      /**
       * The consistent mass matrix restricted to the unconstrained DoFs, with
       * the identity on constrained ones: to compute initial accelerations.
       */
      struct ConstrainedMass
      {
        const std::function<void(const TrilinosWrappers::MPI::Vector &,
                                 TrilinosWrappers::MPI::Vector &)>
                                         mass;
        const AffineConstraints<double> &constraints;
        const IndexSet                  &owned;

        void
        vmult(TrilinosWrappers::MPI::Vector       &dst,
              const TrilinosWrappers::MPI::Vector &src) const
        {
          mass(src, dst);
          for (const auto i : owned)
            if (constraints.is_constrained(i))
              dst(i) = src(i);
          dst.compress(VectorOperation::insert);
        }
      };

      struct DiagonalPreconditioner
      {
        TrilinosWrappers::MPI::Vector inverse;

        void
        vmult(TrilinosWrappers::MPI::Vector       &dst,
              const TrilinosWrappers::MPI::Vector &src) const
        {
          dst = src;
          dst.scale(inverse);
        }
      };
    } // namespace



    template <int dim>
    System<dim>::System(
      const Discretization::Discretization<dim> &discretization,
      const Material::ElasticMaterials          &materials,
      const Scene::BoundaryConditions<dim>      &boundary_conditions,
      const TimeIntegration::Parameters         &time_parameters,
      const TimeIntegration::TimeState          &state,
      Solver::LinearSolver                      &linear_solver,
      TimerOutput                               &timer,
      ConditionalOStream                        &pcout,
      const MPI_Comm                             communicator)
      : discretization(discretization)
      , materials(materials)
      , boundary_conditions(boundary_conditions)
      , time_parameters(time_parameters)
      , state(state)
      , linear_solver(linear_solver)
      , timer(timer)
      , pcout(pcout)
      , communicator(communicator)
    {}



    template <int dim>
    System<dim>::~System() = default;



    template <int dim>
    void
    System<dim>::add_fault_zone_force(const double      factor,
                                      const VectorType &v,
                                      VectorType       &y) const
    {
      fault_zone->vmult_add(factor, v, y);
    }



    template <int dim>
    void
    System<dim>::parse_parameters(ParameterHandler &prm, const bool test_mode)
    {
      this->test_mode = test_mode;
      prm.enter_subsection("Discretization");
      use_lumped_mass       = (prm.get("Mass matrix") == "lumped");
      stiffness_matrix_free = (prm.get("Stiffness operator") == "matrix free");
      prm.leave_subsection();

      prm.enter_subsection("Damping");
      alpha               = prm.get_double("Rayleigh alpha");
      beta                = prm.get_double("Rayleigh beta");
      fault_zone_fraction = prm.get_double("Fault zone damping");
      prm.leave_subsection();

      prm.enter_subsection("Loads");
      gravity = prm.get_double("Gravity");
      body_force_given =
        !dealii::Utilities::trim(prm.get("Body force")).empty();
      body_force = Utilities::parse_function<dim>(prm.get("Body force"),
                                                  dim,
                                                  "Loads/Body force");
      prm.leave_subsection();
    }



    template <int dim>
    bool
    System<dim>::has_absorbing() const
    {
      return !boundary_conditions.absorbing.empty();
    }



    template <int dim>
    void
    System<dim>::setup()
    {
      using Scheme            = TimeIntegration::Scheme;
      const Scheme run_scheme = time_parameters.scheme;
      // The matrix-free solver applies the system and the consistent mass
      // through the elastic operator instead.
      const bool matrix_free_system = linear_solver.matrix_free();
      AssertThrow(
        !matrix_free_system || stiffness_matrix_free,
        ExcMessage(
          "<Solver/Preconditioner> = block Jacobi or multigrid stores no "
          "matrix and needs <Discretization/Stiffness "
          "operator> = matrix free."));
      const bool needs_system_matrix =
        (run_scheme != Scheme::explicit_central_difference ||
         time_parameters.loading_phase) &&
        !matrix_free_system;
      const bool needs_mass_matrix =
        (run_scheme == Scheme::implicit_newmark && !use_lumped_mass) &&
        !matrix_free_system;

      // The sparsity pattern, only if some matrix is stored (an explicit run
      // with the matrix-free operator stores none).
      DynamicSparsityPattern dsp;
      if (!stiffness_matrix_free || needs_system_matrix || needs_mass_matrix)
        {
          dsp.reinit(discretization.locally_relevant_dofs().size(),
                     discretization.locally_relevant_dofs().size(),
                     discretization.locally_relevant_dofs());
          DoFTools::make_sparsity_pattern(discretization.dof_handler(),
                                          dsp,
                                          discretization.hanging_constraints(),
                                          true);
          if (fault)
            fault->add_sparsity(dsp, discretization.hanging_constraints());
          SparsityTools::distribute_sparsity_pattern(
            dsp,
            discretization.locally_owned_dofs(),
            communicator,
            discretization.locally_relevant_dofs());
        }
      // A scene pays only for what it uses: no mass matrix without inertia or
      // with lumping, no system matrix (hence no solver) in explicit runs.
      if (stiffness_matrix_free)
        {
          stiffness_matrix.clear();
          setup_matrix_free_stiffness();
        }
      else
        stiffness_matrix.reinit(discretization.locally_owned_dofs(),
                                discretization.locally_owned_dofs(),
                                dsp,
                                communicator);
      if (needs_mass_matrix)
        mass_matrix.reinit(discretization.locally_owned_dofs(),
                           discretization.locally_owned_dofs(),
                           dsp,
                           communicator);
      else
        mass_matrix.clear();
      // The preconditioner and the direct solver's factors refer to the old
      // matrix.
      linear_solver.clear();
      if (needs_system_matrix)
        system_matrix.reinit(discretization.locally_owned_dofs(),
                             discretization.locally_owned_dofs(),
                             dsp,
                             communicator);
      else
        system_matrix.clear();

      constant_load.reinit(discretization.locally_owned_dofs(), communicator);
      if (use_lumped_mass)
        lumped_mass_vector.reinit(discretization.locally_owned_dofs(),
                                  communicator);
      if (has_absorbing())
        absorbing_vector.reinit(discretization.locally_owned_dofs(),
                                communicator);
      for (VectorType *v : {&stiffness_diagonal,
                            &consistent_mass_diagonal,
                            &system_diagonal,
                            &free_dofs,
                            &system_work})
        v->clear();
      if (matrix_free_system &&
          (run_scheme != Scheme::explicit_central_difference ||
           time_parameters.loading_phase))
        {
          TimerOutput::Scope t(timer, "System diagonal");
          LinearAlgebra::distributed::Vector<double> k, m;
          elastic_operator->compute_diagonals(k, m);
          for (VectorType *v :
               {&stiffness_diagonal, &consistent_mass_diagonal, &free_dofs})
            v->reinit(discretization.locally_owned_dofs(), communicator);
          const unsigned int n = k.locally_owned_size();
          std::copy(k.begin(), k.begin() + n, stiffness_diagonal.begin());
          std::copy(m.begin(), m.begin() + n, consistent_mass_diagonal.begin());
          for (const auto i : discretization.locally_owned_dofs())
            free_dofs(i) =
              discretization.increment_constraints().is_constrained(i) ? 0. :
                                                                         1.;
          free_dofs.compress(VectorOperation::insert);
        }
      multigrid.reset();
      if (linear_solver.multigrid() &&
          (run_scheme == Scheme::quasi_static ||
           time_parameters.loading_phase ||
           (run_scheme == Scheme::implicit_newmark &&
            linear_solver.multigrid_in_dynamic_steps())))
        setup_multigrid();
      setup_fault_zone_damping();
      // The rigid-body modes are the near null space of the algebraic
      // multigrid: only runs with a system matrix need them.
      null_space.clear();
      if (needs_system_matrix)
        null_space = rigid_body_modes();
    }



    template <int dim>
    void
    System<dim>::setup_matrix_free_stiffness()
    {
      TimerOutput::Scope t(timer, "Matrix-free set-up");
      elastic_operator = std::make_unique<Operators::ElasticOperator<dim>>();
      elastic_operator->reinit(MappingQ1<dim>(),
                               discretization.dof_handler(),
                               discretization.hanging_constraints(),
                               materials,
                               discretization.degree());
      elastic_operator->initialize_dof_vector(operator_src);
      elastic_operator->initialize_dof_vector(operator_dst);
      if (!test_mode)
        pcout << "   Stiffness operator: matrix-free, "
              << dealii::Utilities::MPI::sum(
                   elastic_operator->memory_consumption(), communicator) /
                   1048576
              << " MB (" << elastic_operator->layout_summary()
              << " on rank 0)\n";
    }



    template <int dim>
    void
    System<dim>::setup_multigrid()
    {
      TimerOutput::Scope t(timer, "Multigrid set-up");
      typename Operators::Multigrid<dim>::Description description;
      description.triangulation = &discretization.triangulation();
      description.dof_handler   = &discretization.dof_handler();
      description.constraints   = &discretization.hanging_constraints();
      description.fine_operator = elastic_operator.get();
      description.fe_collection = &discretization.fe_collection();
      description.fe_degree     = discretization.degree();
      description.materials     = &materials;
      if (fault)
        {
          description.set_sides = [this](DoFHandler<dim> &level) {
            for (const auto &cell : level.active_cell_iterators())
              if (cell->is_locally_owned())
                cell->set_active_fe_index(fault->side(cell));
          };
          description.interface = [this](const DoFHandler<dim>     &level,
                                         AffineConstraints<double> &c) {
            return fault->level_interface(level, c);
          };
        }
      for (const auto &bc : boundary_conditions.kinematic)
        description.kinematic_boundaries.emplace_back(bc.id, bc.components);
      multigrid = std::make_unique<Operators::Multigrid<dim>>();
      try
        {
          multigrid->reinit(description, communicator);
        }
      catch (const ExceptionBase &e)
        {
          AssertThrow(false,
                      ExcMessage("While building the coarser mesh levels of "
                                 "<Solver/Preconditioner> = multigrid: " +
                                 Utilities::message_of(e) +
                                 " (the fault must lie on faces of the coarse "
                                 "mesh)"));
        }
      pcout << "   Multigrid: " << multigrid->summary();
      if (!test_mode)
        pcout << ", "
              << dealii::Utilities::MPI::sum(multigrid->memory_consumption(),
                                             communicator) /
                   1048576
              << " MB";
      pcout << "\n";
    }



    template <int dim>
    bool
    System<dim>::use_multigrid_now() const
    {
      return multigrid && (scheme == TimeIntegration::Scheme::quasi_static ||
                           linear_solver.multigrid_in_dynamic_steps());
    }



    template <int dim>
    void
    System<dim>::apply_stiffness(const VectorType &x, VectorType &y) const
    {
      if (!stiffness_matrix_free)
        {
          stiffness_matrix.vmult(y, x);
          return;
        }
      TimerOutput::Scope t(timer, "Stiffness product matrix-free");
      apply_elastic(x, y, 1, 0);
    }



    template <int dim>
    const double *
    System<dim>::apply_stiffness_in_place(const VectorType &x) const
    {
      if (!stiffness_matrix_free)
        return nullptr;
      TimerOutput::Scope t(timer, "Stiffness product matrix-free");
      return apply_elastic_in_place(x, 1, 0);
    }



    template <int dim>
    const double *
    System<dim>::apply_elastic_in_place(const VectorType &x,
                                        const double      stiffness_factor,
                                        const double      mass_factor) const
    {
      // Both vectors number their owned entries in increasing global order,
      // so the owned parts copy one to one.
      const unsigned int n_owned = operator_src.locally_owned_size();
      AssertDimension(static_cast<unsigned int>(x.locally_owned_size()),
                      n_owned);
      const double *xs = x.trilinos_vector()[0];
      std::copy(xs, xs + n_owned, operator_src.begin());
      elastic_operator->vmult(operator_dst,
                              operator_src,
                              stiffness_factor,
                              mass_factor);
      return operator_dst.begin();
    }



    template <int dim>
    void
    System<dim>::apply_elastic(const VectorType &x,
                               VectorType       &y,
                               const double      stiffness_factor,
                               const double      mass_factor) const
    {
      const double *result =
        apply_elastic_in_place(x, stiffness_factor, mass_factor);
      std::copy(result,
                result + operator_src.locally_owned_size(),
                y.trilinos_vector()[0]);
    }



    template <int dim>
    void
    System<dim>::apply_system(const VectorType &x, VectorType &y) const
    {
      TimerOutput::Scope t(timer, "System product matrix-free");
      const Factors     &c = system_factors;
      const unsigned int n = x.locally_owned_size();
      if (system_work.size() != x.size())
        system_work.reinit(x);
      system_work      = x;
      double       *xs = system_work.trilinos_vector()[0];
      const double *fr = free_dofs.trilinos_vector()[0];
      for (unsigned int i = 0; i < n; ++i)
        xs[i] *= fr[i];
      const bool consistent = (c.mass != 0 && !use_lumped_mass);
      apply_elastic(system_work, y, c.stiffness, consistent ? c.mass : 0.);
      double *ys = y.trilinos_vector()[0];
      if (c.mass != 0 && use_lumped_mass)
        {
          const double *m = lumped_mass_vector.trilinos_vector()[0];
          for (unsigned int i = 0; i < n; ++i)
            ys[i] += c.mass * m[i] * xs[i];
        }
      if (c.absorbing != 0 && has_absorbing())
        {
          const double *a = absorbing_vector.trilinos_vector()[0];
          for (unsigned int i = 0; i < n; ++i)
            ys[i] += c.absorbing * a[i] * xs[i];
          absorbing_blocks.vmult_add(c.absorbing, xs, ys);
        }
      if (c.absorbing != 0 && fault_zone_viscosity() != 0)
        fault_zone->vmult_add(c.absorbing * fault_zone_viscosity(),
                              system_work,
                              y);
      if (fault)
        fault->apply_tangent(system_work, y);
      // The identity on constrained rows.
      const double *x0 = x.trilinos_vector()[0];
      for (unsigned int i = 0; i < n; ++i)
        if (fr[i] == 0)
          ys[i] = x0[i];
    }



    template <int dim>
    void
    System<dim>::precondition_system(const VectorType &r, VectorType &z) const
    {
      if (use_multigrid_now())
        {
          TimerOutput::Scope t(timer, "Multigrid V-cycle");
          multigrid->vmult(r.trilinos_vector()[0],
                           z.trilinos_vector()[0],
                           free_dofs.trilinos_vector()[0]);
          return;
        }
      TimerOutput::Scope t(timer, "Block Jacobi");
      const unsigned int n  = r.locally_owned_size();
      const double      *rs = r.trilinos_vector()[0];
      const double      *ds = system_diagonal.trilinos_vector()[0];
      const double      *fr = free_dofs.trilinos_vector()[0];
      double            *zs = z.trilinos_vector()[0];
      for (unsigned int i = 0; i < n; ++i)
        zs[i] = (fr[i] != 0 && ds[i] > 0) ? rs[i] / ds[i] : rs[i];
      if (fault)
        fault->precondition_pairs(r, z);
    }



    template <int dim>
    void
    System<dim>::setup_fault_zone_damping()
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
    System<dim>::fault_zone_viscosity() const
    {
      return fault_zone ? fault_zone_fraction * state.time_step : 0.;
    }



    template <int dim>
    const typename System<dim>::VectorType &
    System<dim>::load(const double time)
    {
      if (!body_force_given)
        return constant_load;
      if (step_load.size() != constant_load.size())
        step_load.reinit(constant_load);
      assemble_load(time, step_load);
      return step_load;
    }



    template <int dim>
    void
    System<dim>::apply_mass(const VectorType &x, VectorType &y) const
    {
      if (use_lumped_mass)
        {
          y = x;
          y.scale(lumped_mass_vector);
        }
      else if (mass_matrix.m() == 0)
        apply_elastic(x, y, 0, 1);
      else
        mass_matrix.vmult(y, x);
    }



    template <int dim>
    void
    System<dim>::damping_force(const VectorType &v, VectorType &y) const
    {
      y = 0;
      if (scheme == TimeIntegration::Scheme::quasi_static)
        return;
      VectorType tmp(v);
      if (alpha != 0)
        {
          apply_mass(v, tmp);
          y.add(alpha, tmp);
        }
      if (beta != 0)
        {
          apply_stiffness(v, tmp);
          y.add(beta, tmp);
        }
      if (fault_zone_viscosity() != 0)
        fault_zone->vmult_add(fault_zone_viscosity(), v, y);
      if (has_absorbing())
        {
          tmp = v;
          tmp.scale(absorbing_vector);
          absorbing_blocks.vmult_add(1., v, tmp);
          y += tmp;
        }
      // Constrained DoFs have placeholder rows in M and K.
      discretization.hanging_constraints().set_zero(y);
    }



    template <int dim>
    void
    System<dim>::absorbing_force(const VectorType &v, VectorType &y) const
    {
      y = v;
      y.scale(absorbing_vector);
      absorbing_blocks.vmult_add(1., v, y);
      discretization.hanging_constraints().set_zero(y);
    }



    template <int dim>
    void
    System<dim>::solve_mass(const VectorType &r, VectorType &a) const
    {
      if (use_lumped_mass)
        {
          a = r;
          for (const auto i : discretization.locally_owned_dofs())
            a(i) = (lumped_mass_vector(i) > 0 &&
                    !discretization.increment_constraints().is_constrained(i)) ?
                     r(i) / lumped_mass_vector(i) :
                     0.;
          a.compress(VectorOperation::insert);
        }
      else if (r.l2_norm() > 0)
        {
          ConstrainedMass        op{[this](const VectorType &x, VectorType &y) {
                               apply_mass(x, y);
                             },
                             discretization.increment_constraints(),
                             discretization.locally_owned_dofs()};
          DiagonalPreconditioner jacobi;
          jacobi.inverse.reinit(discretization.locally_owned_dofs(),
                                communicator);
          for (const auto i : discretization.locally_owned_dofs())
            {
              const double d    = (mass_matrix.m() == 0) ?
                                    consistent_mass_diagonal(i) :
                                    mass_matrix.diag_element(i);
              jacobi.inverse(i) = d > 0 ? 1. / d : 1.;
            }
          jacobi.inverse.compress(VectorOperation::insert);
          SolverControl        control(1000, 1e-14 * r.l2_norm());
          SolverCG<VectorType> cg(control);
          a = 0;
          cg.solve(op, a, r, jacobi);
          discretization.distribute_hanging(a);
        }
      else
        a = 0;
    }



    template class System<2>;
    template class System<3>;
  } // namespace Elasticity
} // namespace rupture
