#include <rupture/operators/fault_zone_damping.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>

namespace rupture
{
  namespace Operators
  {
    template <int dim>
    void
    FaultZoneDamping<dim>::reinit(
      const DoFHandler<dim>           &dof_handler,
      const AffineConstraints<double> &constraints,
      const std::function<bool(const std::vector<types::global_dof_index> &)>
                           &touches_fault,
      ElasticOperator<dim> *matrix_free_operator,
      const IndexSet       &owned_dofs,
      const IndexSet       &relevant_dofs,
      const MPI_Comm        communicator)
    {
      elastic = matrix_free_operator;
      in_zone.assign(dof_handler.get_triangulation().n_active_cells(), false);
      DynamicSparsityPattern dsp;
      if (!elastic)
        dsp.reinit(relevant_dofs.size(), relevant_dofs.size(), relevant_dofs);
      std::vector<types::global_dof_index> dofs;
      unsigned int                         n_local = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            dofs.resize(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_indices(dofs);
            if (!touches_fault(dofs))
              continue;
            in_zone[cell->active_cell_index()] = true;
            ++n_local;
            if (!elastic)
              constraints.add_entries_local_to_global(dofs, dsp, true);
          }
      n_zone_cells =
        Utilities::MPI::sum<types::global_cell_index>(n_local, communicator);
      diagonal.clear();
      product.reinit(owned_dofs, communicator);
      if (elastic)
        {
          matrix_free_operator->set_zone(
            [this](const typename DoFHandler<dim>::active_cell_iterator &cell) {
              return contains(cell);
            });
          elastic->initialize_dof_vector(source);
          elastic->initialize_dof_vector(result);
          zone_stiffness.clear();
          // The entries the product touches: the support of K_zone r for
          // values r without a pattern (C^T K C is symmetric, so the
          // entries it writes are those it reads).
          for (unsigned int i = 0; i < source.locally_owned_size(); ++i)
            source.local_element(i) =
              1. + ((owned_dofs.nth_index_in_set(i) * 7919) % 1009) / 1009.;
          elastic->vmult_zone(result, source, 1.);
          zone_entries.clear();
          for (unsigned int i = 0; i < result.locally_owned_size(); ++i)
            if (result.local_element(i) != 0)
              {
                zone_entries.push_back(i);
                result.local_element(i) = 0;
              }
          return;
        }
      SparsityTools::distribute_sparsity_pattern(dsp,
                                                 owned_dofs,
                                                 communicator,
                                                 relevant_dofs);
      zone_stiffness.reinit(owned_dofs, owned_dofs, dsp, communicator);
    }



    template <int dim>
    bool
    FaultZoneDamping<dim>::contains(
      const typename DoFHandler<dim>::active_cell_iterator &cell) const
    {
      return in_zone[cell->active_cell_index()];
    }



    template <int dim>
    bool
    FaultZoneDamping<dim>::stored() const
    {
      return elastic == nullptr;
    }



    template <int dim>
    TrilinosWrappers::SparseMatrix &
    FaultZoneDamping<dim>::matrix()
    {
      return zone_stiffness;
    }



    template <int dim>
    void
    FaultZoneDamping<dim>::vmult_add(const double      factor,
                                     const VectorType &x,
                                     VectorType       &y) const
    {
      if (!elastic)
        {
          zone_stiffness.vmult(product, x);
          y.add(factor, product);
          return;
        }
      // Both vectors number their owned entries in increasing global
      // order, so the owned parts copy one to one; only the zone's entries
      // are read and written (result is zero elsewhere, and is left so).
      const double *xs = x.trilinos_vector()[0];
      for (const unsigned int i : zone_entries)
        source.local_element(i) = xs[i];
      elastic->vmult_zone(result, source, factor);
      double *ys = y.trilinos_vector()[0];
      for (const unsigned int i : zone_entries)
        {
          ys[i] += result.local_element(i);
          result.local_element(i) = 0;
        }
    }



    template <int dim>
    void
    FaultZoneDamping<dim>::add_diagonal(const double factor,
                                        VectorType  &d) const
    {
      if (diagonal.size() == 0)
        {
          diagonal.reinit(d.locally_owned_elements(),
                          product.get_mpi_communicator());
          if (elastic)
            {
              LinearAlgebra::distributed::Vector<double> k;
              elastic->compute_zone_diagonal(k);
              std::copy(k.begin(),
                        k.begin() + k.locally_owned_size(),
                        diagonal.trilinos_vector()[0]);
            }
          else
            {
              for (const auto i : d.locally_owned_elements())
                diagonal(i) = zone_stiffness.el(i, i);
              diagonal.compress(VectorOperation::insert);
            }
        }
      d.add(factor, diagonal);
    }



    template <int dim>
    types::global_cell_index
    FaultZoneDamping<dim>::n_cells() const
    {
      return n_zone_cells;
    }



    template class FaultZoneDamping<2>;
    template class FaultZoneDamping<3>;
  } // namespace Operators
} // namespace rupture
