#include <rupture/operators/mesh_transfer.h>

#include <deal.II/base/geometry_info.h>
#include <deal.II/grid/tria.h>

#include <algorithm>

namespace rupture
{
  namespace Operators
  {
    namespace
    {
      /// Copy the owned entries of @p src into @p dst (same owned range).
      void
      copy_owned(const LinearAlgebra::distributed::Vector<double> &src,
                 LinearAlgebra::distributed::Vector<double>       &dst)
      {
        AssertDimension(src.locally_owned_size(), dst.locally_owned_size());
        std::copy(src.begin(),
                  src.begin() + src.locally_owned_size(),
                  dst.begin());
      }
    } // namespace



    template <int dim>
    void
    MeshTransfer<dim>::reinit(
      const DoFHandler<dim>                                    &cdh,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &coarse_relevant,
      const AffineConstraints<double> &coarse_constraints,
      const DoFHandler<dim>           &fdh,
      const std::shared_ptr<const Utilities::MPI::Partitioner> &fine_relevant,
      const std::vector<std::vector<FullMatrix<double>>>       &prolongation)
    {
      const Triangulation<dim> &ftria = fdh.get_triangulation();
      blocks.clear();
      coarse_dofs.clear();
      fine_dofs.clear();
      coarse_lines.clear();
      weights.reinit(fine_relevant);
      coarse_ghosted.reinit(coarse_relevant);
      fine_ghosted.reinit(fine_relevant);
      const unsigned int n_children = GeometryInfo<dim>::max_children_per_cell;

      std::vector<types::global_dof_index> cd, fd;
      for (const auto &cell : cdh.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const unsigned int fe_index = cell->active_fe_index();
            cd.resize(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_indices(cd);
            const unsigned int coarse_first = coarse_dofs.size();
            for (const auto g : cd)
              coarse_dofs.push_back(coarse_relevant->global_to_local(g));
            const auto tria_cell = ftria.create_cell_iterator(cell->id());
            const typename DoFHandler<dim>::cell_iterator fine_cell(
              &ftria, tria_cell->level(), tria_cell->index(), &fdh);
            const auto add =
              [&](const typename DoFHandler<dim>::cell_iterator &fc,
                  const FullMatrix<double>                      &matrix) {
                AssertThrow(fc->is_active() && !fc->is_artificial() &&
                              fc->active_fe_index() == fe_index,
                            ExcInternalError());
                fd.resize(fc->get_fe().n_dofs_per_cell());
                fc->get_dof_indices(fd);
                AssertThrow(matrix.m() == fd.size() && matrix.n() == cd.size(),
                            ExcInternalError());
                blocks.push_back({coarse_first,
                                  static_cast<unsigned int>(fine_dofs.size()),
                                  static_cast<unsigned int>(cd.size()),
                                  static_cast<unsigned int>(fd.size()),
                                  &matrix});
                for (const auto g : fd)
                  fine_dofs.push_back(fine_relevant->global_to_local(g));
              };
            if (fine_cell->is_active())
              add(fine_cell, prolongation[fe_index][n_children]);
            else
              for (unsigned int c = 0; c < n_children; ++c)
                add(fine_cell->child(c), prolongation[fe_index][c]);
          }

      // Each fine DoF gets the mean of what its cells give it.
      weights = 0;
      for (const auto &b : blocks)
        for (unsigned int i = 0; i < b.n_fine; ++i)
          weights.local_element(fine_dofs[b.fine_first + i]) += 1;
      weights.compress(VectorOperation::add);
      for (unsigned int i = 0; i < weights.locally_owned_size(); ++i)
        if (weights.local_element(i) > 0)
          weights.local_element(i) = 1 / weights.local_element(i);
      weights.update_ghost_values();

      for (const auto &line : coarse_constraints.get_lines())
        if (coarse_relevant->in_local_range(line.index) ||
            coarse_relevant->is_ghost_entry(line.index))
          {
            std::vector<std::pair<unsigned int, double>> entries;
            for (const auto &[j, w] : line.entries)
              entries.emplace_back(coarse_relevant->global_to_local(j), w);
            coarse_lines.emplace_back(
              coarse_relevant->global_to_local(line.index), entries);
          }
    }



    template <int dim>
    void
    MeshTransfer<dim>::distribute_coarse() const
    {
      double *c = coarse_ghosted.begin();
      for (const auto &[i, entries] : coarse_lines)
        {
          double value = 0;
          for (const auto &[j, w] : entries)
            value += w * c[j];
          c[i] = value;
        }
    }



    template <int dim>
    void
    MeshTransfer<dim>::condense_coarse() const
    {
      double *c = coarse_ghosted.begin();
      for (auto line = coarse_lines.rbegin(); line != coarse_lines.rend();
           ++line)
        {
          const double value = c[line->first];
          c[line->first]     = 0;
          for (const auto &[j, w] : line->second)
            c[j] += w * value;
        }
    }



    template <int dim>
    void
    MeshTransfer<dim>::prolongate(const VectorType &coarse,
                                  VectorType       &fine) const
    {
      coarse_ghosted.zero_out_ghost_values();
      copy_owned(coarse, coarse_ghosted);
      coarse_ghosted.update_ghost_values();
      distribute_coarse();
      fine_ghosted = 0;
      // Raw arrays (owned and ghost entries in local numbering, the
      // matrices row by row): the V-cycle's loops stay fast in the Debug
      // build.
      const double *c = coarse_ghosted.begin(), *w = weights.begin();
      double       *f = fine_ghosted.begin();
      for (const Block &b : blocks)
        {
          const double       *m  = &(*b.matrix)(0, 0);
          const unsigned int *cd = coarse_dofs.data() + b.coarse_first;
          for (unsigned int i = 0; i < b.n_fine; ++i)
            {
              double             value = 0;
              const unsigned int fi    = fine_dofs[b.fine_first + i];
              for (unsigned int j = 0; j < b.n_coarse; ++j)
                value += m[i * b.n_coarse + j] * c[cd[j]];
              f[fi] += w[fi] * value;
            }
        }
      fine_ghosted.compress(VectorOperation::add);
      copy_owned(fine_ghosted, fine);
    }



    template <int dim>
    void MeshTransfer<dim>::restrict(const VectorType &fine,
                                     VectorType       &coarse) const
    {
      fine_ghosted.zero_out_ghost_values();
      copy_owned(fine, fine_ghosted);
      fine_ghosted.update_ghost_values();
      coarse_ghosted  = 0;
      const double *f = fine_ghosted.begin(), *w = weights.begin();
      double       *c = coarse_ghosted.begin();
      for (const Block &b : blocks)
        {
          const double       *m  = &(*b.matrix)(0, 0);
          const unsigned int *cd = coarse_dofs.data() + b.coarse_first;
          for (unsigned int i = 0; i < b.n_fine; ++i)
            {
              const unsigned int fi    = fine_dofs[b.fine_first + i];
              const double       value = w[fi] * f[fi];
              if (value != 0)
                for (unsigned int j = 0; j < b.n_coarse; ++j)
                  c[cd[j]] += m[i * b.n_coarse + j] * value;
            }
        }
      condense_coarse();
      coarse_ghosted.compress(VectorOperation::add);
      copy_owned(coarse_ghosted, coarse);
    }



    template <int dim>
    std::size_t
    MeshTransfer<dim>::memory_consumption() const
    {
      return (coarse_dofs.size() + fine_dofs.size()) * sizeof(unsigned int) +
             blocks.size() * sizeof(Block) + weights.memory_consumption() +
             coarse_ghosted.memory_consumption() +
             fine_ghosted.memory_consumption();
    }



    template class MeshTransfer<2>;
    template class MeshTransfer<3>;
  } // namespace Operators
} // namespace rupture
