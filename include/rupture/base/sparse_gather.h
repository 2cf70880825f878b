#ifndef rupture_base_sparse_gather_h
#define rupture_base_sparse_gather_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/partitioner.h>

#include <memory>
#include <vector>

namespace rupture
{
  using namespace dealii;

  /**
   * Reads and adds to a fixed, small set of entries of distributed vectors
   * (the DoFs of the fault's node pairs, of receivers): locally owned
   * entries directly in the owned array, the others through an exchange of
   * just those entries with their owners. Whole-vector ghost copies are
   * never made, so the cost scales with the set, not with the mesh.
   *
   * The vectors are given as their locally owned arrays (entry i is global
   * DoF first_owned + i), which both Trilinos and deal.II vectors expose.
   */
  class SparseGather
  {
  public:
    /**
     * Set up for the global DoF @p indices (any order, repeats allowed) of
     * vectors whose locally owned DoFs are @p owned (contiguous).
     * Collective.
     */
    void
    reinit(const IndexSet                             &owned,
           const std::vector<types::global_dof_index> &indices,
           const MPI_Comm                              communicator);

    /// values[k] = the entry indices[k] of the vector whose owned array is
    /// @p owned_values. Collective.
    void
    gather(const double *owned_values, std::vector<double> &values) const;

    /// Add values[k] to the entry indices[k] of the vector whose owned
    /// array is @p owned_values, on its owner. Collective.
    void
    scatter_add(const std::vector<double> &values, double *owned_values) const;

    /// The owned entries (indices into the owned array, increasing) that
    /// gather() reads and scatter_add() may change on this rank: those of
    /// its own indices and those that other ranks read or add to.
    std::vector<unsigned int>
    owned_entries() const;

    /// Number of indices.
    std::size_t
    size() const
    {
      return source.size();
    }

  private:
    std::shared_ptr<const dealii::Utilities::MPI::Partitioner> partitioner;
    /// Local index of each entry: below n_owned an owned entry, else
    /// n_owned + its place among the ghosts.
    std::vector<unsigned int>        source;
    unsigned int                     n_owned = 0;
    mutable std::vector<double>      ghosts, buffer;
    mutable std::vector<MPI_Request> requests;
  };
} // namespace rupture

#endif
