#ifndef rupture_base_constraint_distributor_h
#define rupture_base_constraint_distributor_h

#include <rupture/base/sparse_gather.h>

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>

#include <vector>

namespace rupture
{
  using namespace dealii;

  /**
   * Sets the constrained entries of a distributed vector from their
   * constraints (hanging nodes, welded fault nodes), as
   * AffineConstraints::distribute() does, but with the sources of the
   * constraints exchanged alone: the cost scales with the number of
   * constraints, and no ghosted copy of the whole vector is made.
   */
  class ConstraintDistributor
  {
  public:
    /**
     * Set up for the locally owned constrained DoFs of @p constraints
     * (closed) in vectors whose owned DoFs are @p owned. Collective.
     */
    void
    reinit(const AffineConstraints<double> &constraints,
           const IndexSet                  &owned,
           const MPI_Comm                   communicator);

    /// Set the constrained entries of the vector whose owned array is
    /// @p owned_values. Collective.
    void
    distribute(double *owned_values) const;

    /// Whether any rank has a constraint.
    bool
    empty() const
    {
      return !any;
    }

  private:
    bool                      any         = false;
    types::global_dof_index   first_owned = 0;
    std::vector<unsigned int> targets;
    /// Entries of target k: [offsets[k], offsets[k + 1]).
    std::vector<unsigned int>   offsets;
    std::vector<double>         weights;
    std::vector<double>         inhomogeneities;
    SparseGather                sources;
    mutable std::vector<double> values;
  };
} // namespace rupture

#endif
