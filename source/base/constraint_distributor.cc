#include <rupture/base/constraint_distributor.h>

namespace rupture
{
  void
  ConstraintDistributor::reinit(const AffineConstraints<double> &constraints,
                                const IndexSet                  &owned,
                                const MPI_Comm                   communicator)
  {
    targets.clear();
    offsets.assign(1, 0);
    weights.clear();
    inhomogeneities.clear();
    first_owned = owned.n_elements() > 0 ? *owned.begin() : 0;
    std::vector<types::global_dof_index> indices;
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        {
          targets.push_back(line.index - first_owned);
          for (const auto &[index, weight] : line.entries)
            {
              indices.push_back(index);
              weights.push_back(weight);
            }
          offsets.push_back(indices.size());
          inhomogeneities.push_back(line.inhomogeneity);
        }
    any =
      dealii::Utilities::MPI::max(targets.empty() ? 0 : 1, communicator) > 0;
    sources.reinit(owned, indices, communicator);
  }



  void
  ConstraintDistributor::distribute(double *owned_values) const
  {
    if (!any)
      return;
    sources.gather(owned_values, values);
    for (std::size_t k = 0; k < targets.size(); ++k)
      {
        double v = inhomogeneities[k];
        for (unsigned int j = offsets[k]; j < offsets[k + 1]; ++j)
          v += weights[j] * values[j];
        owned_values[targets[k]] = v;
      }
  }
} // namespace rupture
