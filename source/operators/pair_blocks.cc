// The split node pairs' contact blocks: product and block Jacobi.

#include <rupture/operators/pair_blocks.h>

#include <deal.II/lac/full_matrix.h>

#include <algorithm>

namespace rupture
{
  namespace Operators
  {
    template <int dim>
    void
    PairBlocks<dim>::reinit(const std::vector<PairDofs> &pairs,
                            const IndexSet              &owned,
                            const MPI_Comm               communicator)
    {
      pair_dofs = pairs;
      blocks.assign(pairs.size(), Tensor<2, dim>());
      std::vector<types::global_dof_index> indices;
      for (const auto &[minus, plus] : pairs)
        {
          indices.insert(indices.end(), minus.begin(), minus.end());
          indices.insert(indices.end(), plus.begin(), plus.end());
        }
      exchange.reinit(owned, indices, communicator);
      inverses.clear();
      point_inverses.clear();
      hanging_slots.clear();
      hanging_active = false;
    }



    template <int dim>
    void
    PairBlocks<dim>::set_hanging(
      const std::vector<
        std::tuple<unsigned int, types::global_dof_index, double>> &entries,
      const IndexSet                                               &owned,
      const MPI_Comm communicator)
    {
      hanging_slots.clear();
      std::vector<types::global_dof_index> masters;
      for (const auto &[slot, master, weight] : entries)
        {
          hanging_slots.emplace_back(slot, weight);
          masters.push_back(master);
        }
      hanging_exchange.reinit(owned, masters, communicator);
      hanging_active = true;
    }



    template <int dim>
    void
    PairBlocks<dim>::apply(const double *x, double *y) const
    {
      exchange.gather(x, values);
      const bool hanging = hanging_active;
      if (hanging)
        {
          // A hanging entry's value is its masters' (x is zero there).
          hanging_exchange.gather(x, hanging_values);
          for (unsigned int i = 0; i < hanging_slots.size(); ++i)
            values[hanging_slots[i].first] = 0;
          for (unsigned int i = 0; i < hanging_slots.size(); ++i)
            values[hanging_slots[i].first] +=
              hanging_slots[i].second * hanging_values[i];
        }
      for (unsigned int k = 0; k < pair_dofs.size(); ++k)
        {
          // [D, -D; -D, D] (x-, x+): -D j and D j, with the jump
          // j = x+ - x-.
          Tensor<1, dim> jump;
          for (unsigned int d = 0; d < dim; ++d)
            jump[d] = values[n * k + dim + d] - values[n * k + d];
          const Tensor<1, dim> f = blocks[k] * jump;
          for (unsigned int d = 0; d < dim; ++d)
            {
              values[n * k + d]       = -f[d];
              values[n * k + dim + d] = f[d];
            }
        }
      if (hanging)
        {
          // Its product goes to its masters (its own row is the
          // identity's, set by the caller).
          for (unsigned int i = 0; i < hanging_slots.size(); ++i)
            hanging_values[i] =
              hanging_slots[i].second * values[hanging_slots[i].first];
          for (unsigned int i = 0; i < hanging_slots.size(); ++i)
            values[hanging_slots[i].first] = 0;
          hanging_exchange.scatter_add(hanging_values, y);
        }
      exchange.scatter_add(values, y);
    }



    template <int dim>
    void
    PairBlocks<dim>::prepare(const double *diagonal, const double *free)
    {
      std::vector<double> ds, fs;
      exchange.gather(diagonal, ds);
      exchange.gather(free, fs);
      inverses.resize(pair_dofs.size() * n * n);
      point_inverses.resize(pair_dofs.size() * n);
      FullMatrix<double> block(n, n), inverse(n, n);
      for (unsigned int k = 0; k < pair_dofs.size(); ++k)
        {
          const unsigned int first = n * k;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              {
                const double d          = blocks[k][i][j];
                block(i, j)             = d;
                block(i, dim + j)       = -d;
                block(dim + i, j)       = -d;
                block(dim + i, dim + j) = d;
              }
          // Constrained DoFs: identity rows and columns.
          for (unsigned int i = 0; i < n; ++i)
            if (fs[first + i] == 0)
              for (unsigned int j = 0; j < n; ++j)
                block(i, j) = block(j, i) = 0;
          for (unsigned int i = 0; i < n; ++i)
            {
              const bool   is_free = (fs[first + i] != 0);
              const double d       = ds[first + i];
              block(i, i) += (is_free ? d : 1);
              // What the point-Jacobi part put into z at this entry.
              point_inverses[first + i] = (is_free && d > 0) ? 1 / d : 1;
            }
          inverse.invert(block);
          std::copy(&inverse(0, 0),
                    &inverse(0, 0) + n * n,
                    inverses.begin() + n * first);
        }
    }



    template <int dim>
    void
    PairBlocks<dim>::precondition(const double *r, double *z) const
    {
      Assert(inverses.size() == pair_dofs.size() * n * n,
             ExcMessage("prepare() must come first."));
      exchange.gather(r, values);
      results.resize(values.size());
      for (unsigned int k = 0; k < pair_dofs.size(); ++k)
        {
          const unsigned int first   = n * k;
          const double      *inverse = inverses.data() + n * first;
          for (unsigned int i = 0; i < n; ++i)
            {
              double solution = 0;
              for (unsigned int j = 0; j < n; ++j)
                solution += inverse[i * n + j] * values[first + j];
              // z holds the point-Jacobi value here: add the difference.
              results[first + i] =
                solution - point_inverses[first + i] * values[first + i];
            }
        }
      exchange.scatter_add(results, z);
    }
  } // namespace Operators
} // namespace rupture


template class rupture::Operators::PairBlocks<2>;
template class rupture::Operators::PairBlocks<3>;
