#include <rupture/base/sparse_gather.h>

#include <deal.II/base/array_view.h>

#include <algorithm>

namespace rupture
{
  void
  SparseGather::reinit(const IndexSet                             &owned,
                       const std::vector<types::global_dof_index> &indices,
                       const MPI_Comm                              communicator)
  {
    IndexSet ghost_set(owned.size());
    for (const auto i : indices)
      if (!owned.is_element(i))
        ghost_set.add_index(i);
    ghost_set.compress();
    partitioner =
      std::make_shared<dealii::Utilities::MPI::Partitioner>(owned,
                                                            ghost_set,
                                                            communicator);
    n_owned = partitioner->locally_owned_size();
    source.resize(indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k)
      source[k] = partitioner->global_to_local(indices[k]);
    ghosts.assign(partitioner->n_ghost_indices(), 0.);
    buffer.assign(partitioner->n_import_indices(), 0.);
  }



  std::vector<unsigned int>
  SparseGather::owned_entries() const
  {
    std::vector<unsigned int> entries;
    for (const unsigned int k : source)
      if (k < n_owned)
        entries.push_back(k);
    if (partitioner)
      for (const auto &range : partitioner->import_indices())
        for (unsigned int k = range.first; k < range.second; ++k)
          entries.push_back(k);
    std::sort(entries.begin(), entries.end());
    entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
    return entries;
  }



  void
  SparseGather::gather(const double        *owned_values,
                       std::vector<double> &values) const
  {
    if (!ghosts.empty() || partitioner->n_import_indices() > 0 ||
        dealii::Utilities::MPI::n_mpi_processes(
          partitioner->get_mpi_communicator()) > 1)
      {
        partitioner->export_to_ghosted_array_start<double>(
          0,
          make_array_view(owned_values, owned_values + n_owned),
          make_array_view(buffer),
          make_array_view(ghosts),
          requests);
        partitioner->export_to_ghosted_array_finish(make_array_view(ghosts),
                                                    requests);
      }
    values.resize(source.size());
    for (std::size_t k = 0; k < source.size(); ++k)
      values[k] = (source[k] < n_owned) ? owned_values[source[k]] :
                                          ghosts[source[k] - n_owned];
  }



  void
  SparseGather::scatter_add(const std::vector<double> &values,
                            double                    *owned_values) const
  {
    std::fill(ghosts.begin(), ghosts.end(), 0.);
    for (std::size_t k = 0; k < source.size(); ++k)
      if (source[k] < n_owned)
        owned_values[source[k]] += values[k];
      else
        ghosts[source[k] - n_owned] += values[k];
    if (dealii::Utilities::MPI::n_mpi_processes(
          partitioner->get_mpi_communicator()) > 1)
      {
        partitioner->import_from_ghosted_array_start<double>(
          VectorOperation::add,
          0,
          make_array_view(ghosts),
          make_array_view(buffer),
          requests);
        partitioner->import_from_ghosted_array_finish<double>(
          VectorOperation::add,
          ArrayView<const double>(buffer.data(), buffer.size()),
          make_array_view(owned_values, owned_values + n_owned),
          make_array_view(ghosts),
          requests);
      }
  }
} // namespace rupture
