#include <rupture/operators/element_frequency.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/lapack_support.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>

namespace rupture
{
  namespace Operators
  {
    template <int dim>
    BoxElementFrequency<dim>::BoxElementFrequency(const unsigned int degree)
    {
      // The integrals of the stiffness use the same Gauss rule as the
      // assembled element matrices; the lumped mass is the Gauss-Lobatto
      // rule on the nodes.
      const FE_Q<dim>          fe(degree);
      const QGauss<dim>        gauss(degree + 1);
      const QGaussLobatto<dim> lobatto(degree + 1);
      n_nodes = fe.n_dofs_per_cell();
      std::vector<double> mass(n_nodes, 0.);
      for (unsigned int q = 0; q < lobatto.size(); ++q)
        for (unsigned int i = 0; i < n_nodes; ++i)
          mass[i] += std::pow(fe.shape_value(i, lobatto.point(q)), 2) *
                     lobatto.weight(q);
      std::vector<std::vector<Tensor<1, dim>>> grad(
        gauss.size(), std::vector<Tensor<1, dim>>(n_nodes));
      for (unsigned int q = 0; q < gauss.size(); ++q)
        for (unsigned int i = 0; i < n_nodes; ++i)
          grad[q][i] = fe.shape_grad(i, gauss.point(q));
      for (unsigned int b = 0; b < dim; ++b)
        for (unsigned int d = 0; d < dim; ++d)
          {
            FullMatrix<double> &m = s[b][d];
            m.reinit(n_nodes, n_nodes);
            for (unsigned int q = 0; q < gauss.size(); ++q)
              for (unsigned int i = 0; i < n_nodes; ++i)
                for (unsigned int j = 0; j < n_nodes; ++j)
                  m(i, j) += grad[q][i][b] * grad[q][j][d] * gauss.weight(q);
            for (unsigned int i = 0; i < n_nodes; ++i)
              for (unsigned int j = 0; j < n_nodes; ++j)
                m(i, j) /= std::sqrt(mass[i] * mass[j]);
          }
    }



    template <int dim>
    void
    BoxElementFrequency<dim>::scaled_matrix(
      const Tensor<1, dim>             &h,
      const Material::ElasticConstants &material,
      LAPACKFullMatrix<double>         &a) const
    {
      Tensor<1, dim> inverse;
      for (unsigned int b = 0; b < dim; ++b)
        inverse[b] = 1. / h[b];
      a.reinit(dim * n_nodes, dim * n_nodes);
      for (unsigned int ca = 0; ca < dim; ++ca)
        for (unsigned int cc = 0; cc < dim; ++cc)
          {
            const double grad_div =
              inverse[ca] * inverse[cc] / material.density;
            const FullMatrix<double> &s_ac = s[ca][cc];
            const FullMatrix<double> &s_ca = s[cc][ca];
            for (unsigned int i = 0; i < n_nodes; ++i)
              for (unsigned int j = 0; j < n_nodes; ++j)
                {
                  double value = grad_div * (material.lambda * s_ac(i, j) +
                                             material.mu * s_ca(i, j));
                  if (ca == cc)
                    {
                      double laplace = 0;
                      for (unsigned int b = 0; b < dim; ++b)
                        laplace += inverse[b] * inverse[b] * s[b][b](i, j);
                      value += material.mu / material.density * laplace;
                    }
                  a(ca * n_nodes + i, cc * n_nodes + j) = value;
                }
          }
      a.set_property(LAPACKSupport::symmetric);
    }



    double
    gershgorin_bound(const LAPACKFullMatrix<double> &a)
    {
      double bound = 0;
      for (unsigned int i = 0; i < a.m(); ++i)
        {
          double row = 0;
          for (unsigned int j = 0; j < a.n(); ++j)
            row += std::abs(a(i, j));
          bound = std::max(bound, row);
        }
      return bound;
    }



    double
    largest_eigenvalue_above(LAPACKFullMatrix<double> &a, const double floor)
    {
      const double gershgorin = gershgorin_bound(a);
      if (!(gershgorin > floor))
        return floor;
      a.set_property(LAPACKSupport::symmetric);
      Vector<double>     eigenvalues;
      FullMatrix<double> eigenvectors;
      a.compute_eigenvalues_symmetric(
        floor, 1.01 * gershgorin, 0, eigenvalues, eigenvectors);
      double largest = floor;
      for (const double lambda : eigenvalues)
        largest = std::max(largest, lambda);
      return largest;
    }



    template <int dim>
    std::optional<Tensor<1, dim>>
    box_edges(const std::array<Point<dim>, (1u << dim)> &vertices)
    {
      Tensor<1, dim> h;
      double         size = 0;
      for (unsigned int b = 0; b < dim; ++b)
        {
          h[b] = vertices[1u << b][b] - vertices[0][b];
          size = std::max(size, std::abs(h[b]));
        }
      for (unsigned int b = 0; b < dim; ++b)
        if (!(h[b] > 1e-12 * size))
          return std::nullopt;
      for (unsigned int v = 0; v < vertices.size(); ++v)
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double expected = vertices[0][d] + ((v >> d) & 1u) * h[d];
            if (std::abs(vertices[v][d] - expected) > 1e-12 * size)
              return std::nullopt;
          }
      return h;
    }



    template class BoxElementFrequency<2>;
    template class BoxElementFrequency<3>;
    template std::optional<Tensor<1, 2>>
    box_edges<2>(const std::array<Point<2>, 4> &);
    template std::optional<Tensor<1, 3>>
    box_edges<3>(const std::array<Point<3>, 8> &);
  } // namespace Operators
} // namespace rupture
