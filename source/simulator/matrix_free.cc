// The matrix-free products (stiffness, effective system) and the block-
// Jacobi preconditioner.

#include <rupture/base/utilities.h>
#include <rupture/simulator/simulator.h>

#include <deal.II/base/partitioner.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

namespace rupture
{
  template <int dim>
  void
  Simulator<dim>::setup_matrix_free_stiffness()
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
            << " MB (" << elastic_operator->layout_summary() << " on rank 0)\n";
  }



  template <int dim>
  void
  Simulator<dim>::setup_multigrid()
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
  Simulator<dim>::use_multigrid_now() const
  {
    return multigrid &&
           (current_scheme() == TimeIntegration::Scheme::quasi_static ||
            linear_solver.multigrid_in_dynamic_steps());
  }



  template <int dim>
  void
  Simulator<dim>::apply_stiffness(const VectorType &x, VectorType &y) const
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
  Simulator<dim>::apply_stiffness_in_place(const VectorType &x) const
  {
    if (!stiffness_matrix_free)
      return nullptr;
    TimerOutput::Scope t(timer, "Stiffness product matrix-free");
    return apply_elastic_in_place(x, 1, 0);
  }



  template <int dim>
  const double *
  Simulator<dim>::apply_elastic_in_place(const VectorType &x,
                                         const double      stiffness_factor,
                                         const double      mass_factor) const
  {
    // Both vectors number their owned entries in increasing global order,
    // so the owned parts copy one to one.
    const unsigned int n_owned = operator_src.locally_owned_size();
    AssertDimension(static_cast<unsigned int>(x.locally_owned_size()), n_owned);
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
  Simulator<dim>::apply_elastic(const VectorType &x,
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
  const typename Simulator<dim>::VectorType &
  Simulator<dim>::ghosted_copy(const unsigned int slot,
                               const VectorType  &v) const
  {
    if (!ghosts)
      ghosts =
        std::make_unique<GhostedVectors>(discretization.locally_owned_dofs(),
                                         discretization.locally_relevant_dofs(),
                                         communicator,
                                         2);
    return ghosts->copy(slot, v);
  }



  template <int dim>
  void
  Simulator<dim>::apply_system(const VectorType &x, VectorType &y) const
  {
    TimerOutput::Scope   t(timer, "System product matrix-free");
    const SystemFactors &c = system_factors;
    const unsigned int   n = x.locally_owned_size();
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
        const double *m = lumped_mass.trilinos_vector()[0];
        for (unsigned int i = 0; i < n; ++i)
          ys[i] += c.mass * m[i] * xs[i];
      }
    if (c.absorbing != 0 && has_absorbing)
      {
        const double *a = absorbing_damping.trilinos_vector()[0];
        for (unsigned int i = 0; i < n; ++i)
          ys[i] += c.absorbing * a[i] * xs[i];
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
  Simulator<dim>::precondition_system(const VectorType &r, VectorType &z) const
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



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
