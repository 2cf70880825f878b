#ifndef rupture_operators_local_elasticity_h
#define rupture_operators_local_elasticity_h

#include <rupture/material/elastic_material.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <functional>
#include <utility>
#include <vector>

namespace rupture
{
  namespace Operators
  {
    using namespace dealii;

    /**
     * The element stiffness and (consistent) mass matrix of linear
     * (isotropic or anisotropic) elasticity on the cell that @p fe_values was
     * reinit'ed on.
     * @p u extracts the side of the displacement that lives on this cell.
     * With @p local (constants that vary in space), the constants at each
     * quadrature point are those it returns there instead of @p m
     * (@p fe_values then needs update_quadrature_points).
     */
    template <int dim>
    inline void
    local_elasticity_matrices(
      const FEValues<dim>              &fe_values,
      const FEValuesExtractors::Vector &u,
      const Material::ElasticConstants &m,
      FullMatrix<double>               &k,
      FullMatrix<double>               *mass,
      const std::function<Material::ElasticConstants(const Point<dim> &)>
        *local = nullptr)
    {
      const unsigned int n = fe_values.dofs_per_cell;
      k                    = 0;
      if (mass)
        *mass = 0;
      std::vector<SymmetricTensor<2, dim>> eps(n);
      std::vector<double>                  div(n);
      std::vector<Tensor<1, dim>>          phi(n);
      SymmetricTensor<4, dim>              c = m.template stiffness<dim>();
      Material::ElasticConstants           at_q;
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const double JxW = fe_values.JxW(q);
          if (local)
            {
              at_q = (*local)(fe_values.quadrature_point(q));
              if (!at_q.isotropic())
                c = at_q.template stiffness<dim>();
            }
          const Material::ElasticConstants &mq = local ? at_q : m;
          for (unsigned int i = 0; i < n; ++i)
            {
              eps[i] = fe_values[u].symmetric_gradient(i, q);
              div[i] = fe_values[u].divergence(i, q);
              phi[i] = fe_values[u].value(i, q);
            }
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              {
                if (mq.isotropic())
                  k(i, j) += (mq.lambda * div[i] * div[j] +
                              2 * mq.mu * (eps[i] * eps[j])) *
                             JxW;
                else
                  k(i, j) += (eps[i] * (c * eps[j])) * JxW;
                if (mass)
                  (*mass)(i, j) += mq.density * (phi[i] * phi[j]) * JxW;
              }
        }
    }
  } // namespace Operators
} // namespace rupture

#endif
