#include <rupture/operators/node_coupling.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rupture
{
  namespace Operators
  {
    namespace
    {
      constexpr unsigned int none = std::numeric_limits<unsigned int>::max();
    }



    void
    NodeCoupling::reinit(const unsigned int dim,
                         const IndexSet    &owned,
                         const MPI_Comm     communicator)
    {
      AssertThrow(dim >= 2 && dim <= 3, ExcInternalError());
      owned_dofs       = owned;
      mpi_communicator = communicator;
      coefficient_vectors.resize(dim - 1);
      for (VectorType &v : coefficient_vectors)
        v.reinit(owned, communicator);
      siblings.assign(owned.n_elements(), {{none, none}});
      entries.clear();
      globally_empty = true;
    }



    NodeCoupling::VectorType &
    NodeCoupling::coefficients(const unsigned int k)
    {
      AssertIndexRange(k, coefficient_vectors.size());
      return coefficient_vectors[k];
    }



    void
    NodeCoupling::set_sibling(const types::global_dof_index row,
                              const unsigned int            k,
                              const types::global_dof_index column)
    {
      AssertIndexRange(k, coefficient_vectors.size());
      AssertThrow(owned_dofs.is_element(row) && owned_dofs.is_element(column),
                  ExcMessage("The components of a node have one owner."));
      siblings[owned_dofs.index_within_set(row)][k] =
        owned_dofs.index_within_set(column);
    }



    void
    NodeCoupling::finalize(const VectorType &diagonal)
    {
      entries.clear();
      for (VectorType &v : coefficient_vectors)
        v.compress(VectorOperation::add);
      const double *d = diagonal.trilinos_vector()[0];
      // Row by row (value() finds a row's entries by bisection).
      for (unsigned int i = 0; i < siblings.size(); ++i)
        for (unsigned int k = 0; k < coefficient_vectors.size(); ++k)
          {
            const double c = coefficient_vectors[k].trilinos_vector()[0][i];
            const unsigned int j = siblings[i][k];
            if (c == 0)
              continue;
            AssertThrow(j != none,
                        ExcMessage("A node coupling without its sibling "
                                   "(set_sibling() missing)."));
            if (std::abs(c) > 1e-13 * std::sqrt(std::abs(d[i] * d[j])))
              entries.push_back({i, j, c});
          }
      globally_empty =
        dealii::Utilities::MPI::sum(entries.size(), mpi_communicator) == 0;
      // The coefficients live on in the entries alone.
      for (VectorType &v : coefficient_vectors)
        v.clear();
    }



    double
    NodeCoupling::value(const unsigned int row, const unsigned int column) const
    {
      auto e = std::lower_bound(entries.begin(),
                                entries.end(),
                                row,
                                [](const Entry &a, const unsigned int r) {
                                  return a.row < r;
                                });
      for (; e != entries.end() && e->row == row; ++e)
        if (e->column == column)
          return e->value;
      return 0;
    }



    void
    NodeCoupling::vmult_add(const double  factor,
                            const double *x,
                            double       *y) const
    {
      for (const Entry &e : entries)
        y[e.row] += factor * e.value * x[e.column];
    }



    void
    NodeCoupling::vmult_add(const double      factor,
                            const VectorType &x,
                            VectorType       &y) const
    {
      vmult_add(factor,
                x.trilinos_vector()[0],
                const_cast<double *>(y.trilinos_vector()[0]));
    }



    NodeBlockInverse
    NodeCoupling::invert_blocks(const double *inverse_diagonal,
                                const double  factor,
                                const std::vector<unsigned int> &excluded) const
    {
      NodeBlockInverse   result;
      const unsigned int n = coefficient_vectors.size() + 1;
      result.n_components  = n;
      std::vector<bool> skip(siblings.size(), false);
      for (const unsigned int i : excluded)
        skip[i] = true;
      // A node per row of the entries, named by its first DoF.
      std::vector<bool> seen(siblings.size(), false);
      for (const Entry &e : entries)
        {
          std::array<unsigned int, 3> dofs = {{e.row, none, none}};
          for (unsigned int k = 0; k + 1 < n; ++k)
            dofs[k + 1] = siblings[e.row][k];
          const unsigned int first =
            *std::min_element(dofs.begin(), dofs.begin() + n);
          if (seen[first])
            continue;
          seen[first] = true;
          if (std::any_of(dofs.begin(), dofs.begin() + n, [&](unsigned int i) {
                return skip[i];
              }))
            continue;
          Tensor<2, 3>        block;
          std::array<bool, 3> moves = {{false, false, false}};
          for (unsigned int a = 0; a < 3; ++a)
            {
              moves[a]    = a < n && inverse_diagonal[dofs[a]] != 0;
              block[a][a] = moves[a] ? 1. / inverse_diagonal[dofs[a]] : 1.;
            }
          for (unsigned int a = 0; a < n; ++a)
            for (unsigned int b = 0; b < n; ++b)
              if (a != b && moves[a] && moves[b])
                block[a][b] = factor * value(dofs[a], dofs[b]);
          const Tensor<2, 3>    inverse = invert(block);
          std::array<double, 9> values;
          for (unsigned int a = 0; a < 3; ++a)
            for (unsigned int b = 0; b < 3; ++b)
              values[3 * a + b] = inverse[a][b];
          result.dofs.push_back(dofs);
          result.moves.push_back(moves);
          result.inverses.push_back(values);
        }
      return result;
    }



    void
    NodeBlockInverse::solve(const double *r, double *x) const
    {
      const unsigned int n = n_components;
      for (unsigned int k = 0; k < dofs.size(); ++k)
        {
          double rhs[3] = {0, 0, 0};
          for (unsigned int a = 0; a < n; ++a)
            rhs[a] = moves[k][a] ? r[dofs[k][a]] : 0.;
          for (unsigned int a = 0; a < n; ++a)
            {
              double result = 0;
              for (unsigned int b = 0; b < n; ++b)
                result += inverses[k][3 * a + b] * rhs[b];
              x[dofs[k][a]] = result;
            }
        }
    }



    void
    NodeCoupling::add_to(TrilinosWrappers::SparseMatrix  &matrix,
                         const double                     factor,
                         const AffineConstraints<double> &constraints) const
    {
      for (const Entry &e : entries)
        {
          const types::global_dof_index row =
                                          owned_dofs.nth_index_in_set(e.row),
                                        column =
                                          owned_dofs.nth_index_in_set(e.column);
          if (!constraints.is_constrained(row) &&
              !constraints.is_constrained(column))
            matrix.add(row, column, factor * e.value);
        }
      matrix.compress(VectorOperation::add);
    }
  } // namespace Operators
} // namespace rupture
