#include <rupture/operators/element_frequency.h>
#include <rupture/operators/local_elasticity.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/lapack_support.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rupture
{
  namespace Operators
  {
    namespace
    {
      /**
       * What makes two cells have the same element matrices: material, FE
       * (side of the fault) and the vertex offsets from vertex 0, rounded to
       * multiples of @p unit. Cells that are translates of each other share a
       * key.
       */
      template <typename CellIterator>
      std::vector<std::int64_t>
      cell_shape_key(const CellIterator &cell, const double unit)
      {
        std::vector<std::int64_t> key = {
          static_cast<std::int64_t>(cell->material_id()),
          static_cast<std::int64_t>(cell->active_fe_index())};
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int d = 0; d < CellIterator::AccessorType::dimension;
               ++d)
            key.push_back(
              std::llround((cell->vertex(v)[d] - cell->vertex(0)[d]) / unit));
        return key;
      }

      /// The edge lengths of @p cell if it is an axis-aligned box.
      template <typename CellIterator>
      auto
      cell_box_edges(const CellIterator &cell)
      {
        constexpr int dim = CellIterator::AccessorType::dimension;
        std::array<Point<dim>, (1u << dim)> vertices;
        for (const unsigned int v : cell->vertex_indices())
          vertices[v] = cell->vertex(v);
        return Operators::box_edges<dim>(vertices);
      }
    } // namespace



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
      if (!material.isotropic())
        {
          // The block (a, c) is sum_bd a_abcd d_b d_d S^bd / rho.
          const SymmetricTensor<4, dim> t = material.stiffness<dim>();
          for (unsigned int ca = 0; ca < dim; ++ca)
            for (unsigned int cc = 0; cc < dim; ++cc)
              for (unsigned int i = 0; i < n_nodes; ++i)
                for (unsigned int j = 0; j < n_nodes; ++j)
                  {
                    double value = 0;
                    for (unsigned int b = 0; b < dim; ++b)
                      for (unsigned int d = 0; d < dim; ++d)
                        value += t[ca][b][cc][d] * inverse[b] * inverse[d] *
                                 s[b][d](i, j);
                    a(ca * n_nodes + i, cc * n_nodes + j) =
                      value / material.density;
                  }
          a.set_property(LAPACKSupport::symmetric);
          return;
        }
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



    template <int dim>
    double
    ElementFrequencies<dim>::highest(
      const DoFHandler<dim>            &dof_handler,
      const Material::ElasticMaterials &materials,
      const unsigned int                fe_degree,
      const MPI_Comm                    communicator)
    {
      const hp::FECollection<dim> &fe_collection =
        dof_handler.get_fe_collection();
      const hp::QCollection<dim> q_cells(QGauss<dim>(fe_degree + 1));
      const hp::QCollection<dim> q_lumped(QGaussLobatto<dim>(fe_degree + 1));
      hp::FEValues<dim>          hp_values(fe_collection,
                                  q_cells,
                                  update_values | update_gradients |
                                    update_JxW_values);
      hp::FEValues<dim>          hp_lumped(fe_collection,
                                  q_lumped,
                                  update_values | update_JxW_values);
      // Axis-aligned boxes are assembled from the unit cell's matrices.
      const BoxElementFrequency<dim> boxes(fe_degree);
      FullMatrix<double>             k;
      LAPACKFullMatrix<double>       a;
      double                         omega2_max = 0;
      // A cell that is a translate of one already seen (same material, same
      // side, same vertex offsets) has the same eigenvalues: structured
      // meshes have few distinct cells, and a dense eigenvalue problem per
      // cell took minutes on the full Northeast-Japan mesh. The offsets are
      // compared to 1e-7 of the smallest cell (a relative change of the
      // eigenvalue of that order).
      // The shapes are remembered from one call to the next (a changed mesh
      // keeps most of its cells); the unit of the first mesh stays. A
      // shape's value is an upper bound of its largest eigenvalue, so a
      // later mesh's step is safe, if perhaps smaller than its own cells
      // need.
      auto &seen = omega2;
      // (A cache: where constants vary, the keys carry the cells' rounded
      // constants, and an adaptive run would add keys with every mesh.
      // Emptied when large, it is only computed again.)
      if (seen.size() > 200000)
        seen.clear();
      if (unit == 0)
        unit = 1e-7 * GridTools::minimal_cell_diameter(
                        dof_handler.get_triangulation());

      // Constants that vary in space: a cell's eigenvalues are at most
      // (largest stiffness ratio / smallest density ratio) over its points
      // times those of its shape with the material's reference constants
      // (K grows at most by the one, the lumped M shrinks at most by the
      // other; ElasticMaterials::reference_ratios()). Each shape takes the
      // largest such ratio of its cells. Where isotropic constants are
      // functions, the reference's lambda / mu is the cell's largest lambda
      // over its largest mu, rounded up to a bin of 1 % in (lambda + 2 mu)
      // / mu: the bin joins the shape's key.
      const bool   varying   = materials.varies_in_space();
      const double bin_width = std::log(1.01);
      const auto   kappa_of  = [&](const std::int64_t bin) {
        return std::exp(bin * bin_width) - 2;
      };
      // Where anisotropic constants are functions, the reference is the
      // cell's own tensor at its centre, rounded (ElasticMaterials::
      // rounded_tensor(), 22 integers that join the key), or the
      // material's reference where the rounded tensor is not positive
      // definite enough: tight where the tensor's shape varies, and the
      // same on every process.
      const std::size_t shape_key_size = 2 + dim * (1u << dim);
      const auto        key_of = [&](const auto                      &cell,
                              const double                     kappa,
                              const std::vector<std::int64_t> &tensor) {
        auto key = cell_shape_key(cell, unit);
        if (!std::isnan(kappa))
          key.push_back(static_cast<std::int64_t>(
            std::ceil(std::log(kappa + 2) / bin_width)));
        key.insert(key.end(), tensor.begin(), tensor.end());
        return key;
      };

      // The matrix M^-1/2 K M^-1/2 of one cell (with the reference
      // constants of its key where its constants vary).
      const auto scaled_matrix = [&](const auto                      &cell,
                                     const std::vector<std::int64_t> &key) {
        // (A release build checks too: an invalid id would read beyond the
        // materials, as a three-level TPV3 run on two ranks did once.)
        if (cell->material_id() >= materials.n_materials())
          {
            std::ostringstream text;
            text << "Internal error: the cell at (" << cell->center()
                 << "), level " << cell->level() << ", has material id "
                 << static_cast<unsigned int>(cell->material_id()) << ", but "
                 << materials.n_materials()
                 << " materials are defined. Please report it with the "
                    "parameter file.";
            // Raised on this process only: the run ends by
            // run_program()'s agreement on such errors (an abort).
            throw std::logic_error(text.str());
          }
        const bool local_tensor =
          materials.tensor_given_as_functions(cell->material_id()) &&
          key.size() > shape_key_size;
        const Material::ElasticConstants m =
          local_tensor ? materials.local_reference(
                           cell->material_id(),
                           Material::ElasticMaterials::rounded_tensor_value(
                             key, shape_key_size)) :
                         materials.reference(cell->material_id(),
                                             materials.given_as_functions(
                                               cell->material_id()) ?
                                               kappa_of(key.back()) :
                                               0.);
        if (const auto h = cell_box_edges(cell))
          return boxes.scaled_matrix(*h, m, a);
        const FEValuesExtractors::Vector u(cell->active_fe_index() * dim);
        hp_values.reinit(cell);
        hp_lumped.reinit(cell);
        const FEValues<dim> &fe_values = hp_values.get_present_fe_values();
        const FEValues<dim> &lv        = hp_lumped.get_present_fe_values();
        const unsigned int   n         = fe_values.dofs_per_cell;
        k.reinit(n, n);
        local_elasticity_matrices(fe_values, u, m, k, nullptr);
        std::vector<double> mass(n, 0.);
        for (const unsigned int q : lv.quadrature_point_indices())
          for (unsigned int i = 0; i < n; ++i)
            mass[i] += m.density * lv[u].value(i, q).norm_square() * lv.JxW(q);
        a.reinit(n, n);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            a(i, j) = k(i, j) / std::sqrt(mass[i] * mass[j]);
      };

      // The shapes not seen before, each with an upper bound of its largest
      // eigenvalue that is cheap for boxes (Gershgorin's, of the matrix
      // assembled without quadrature; infinite for other cells). Taken from
      // the largest bound down, the first few shapes fix the maximum and
      // the others are passed over by their bound, without an eigenvalue
      // problem: on a graded mesh most shapes are larger than the smallest.
      struct NewShape
      {
        std::vector<std::int64_t>                      key;
        typename DoFHandler<dim>::active_cell_iterator cell;
        double                                         bound;
      };
      std::map<std::vector<std::int64_t>, double> shape_ratio;
      const MappingQ1<dim>                        mapping;
      // The ratio of a cell and the lambda / mu of its reference (NaN
      // where the constants are not functions).
      const auto cell_ratio = [&](const auto                      &cell,
                                  const std::vector<std::int64_t> &tensor) {
        double s_max = 0, r_min = 1e300,
               lambda_max           = std::numeric_limits<double>::quiet_NaN();
        const types::material_id id = cell->material_id();
        if (materials.tensor_given_as_functions(id))
          {
            std::vector<Point<dim>> points;
            for (const Quadrature<dim> *q :
                 {&q_cells[0],
                  static_cast<const Quadrature<dim> *>(&q_lumped[0])})
              for (const Point<dim> &xi : q->get_points())
                points.push_back(mapping.transform_unit_to_real_cell(cell, xi));
            const Material::EnergyRatio local =
              tensor.empty() ?
                Material::EnergyRatio() :
                Material::EnergyRatio(
                  Material::ElasticMaterials::rounded_tensor_value(tensor, 0),
                  dim);
            const auto [s, r] =
              materials.extreme_ratios(id,
                                       points,
                                       tensor.empty() ? nullptr : &local);
            return std::make_pair(s / r, lambda_max / s);
          }
        for (const Quadrature<dim> *q :
             {&q_cells[0], static_cast<const Quadrature<dim> *>(&q_lumped[0])})
          for (const Point<dim> &xi : q->get_points())
            {
              const Point<dim> p =
                mapping.transform_unit_to_real_cell(cell, xi);
              const auto [s, r, lambda] = materials.reference_ratios(id, p);
              s_max                     = std::max(s_max, s);
              r_min                     = std::min(r_min, r);
              if (!std::isnan(lambda))
                lambda_max = std::isnan(lambda_max) ?
                               lambda :
                               std::max(lambda_max, lambda);
            }
        return std::make_pair(s_max / r_min, lambda_max / s_max);
      };
      const auto ratio_of = [&](const std::vector<std::int64_t> &key) {
        return varying ? shape_ratio[key] : 1.;
      };
      // The keys of the locally owned cells, in the order of the loop.
      std::vector<std::vector<std::int64_t>> keys;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            if (!varying)
              {
                keys.push_back(cell_shape_key(cell, unit));
                continue;
              }
            const std::vector<std::int64_t> tensor =
              materials.tensor_given_as_functions(cell->material_id()) ?
                materials.rounded_tensor(cell->material_id(), cell->center()) :
                std::vector<std::int64_t>();
            const auto [ratio, kappa] = cell_ratio(cell, tensor);
            keys.push_back(key_of(cell, kappa, tensor));
            double &r = shape_ratio[keys.back()];
            r         = std::max(r, ratio);
          }
      std::vector<NewShape>               new_shapes;
      std::set<std::vector<std::int64_t>> queued;
      unsigned int                        index = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            auto key = std::move(keys[index++]);
            if (const auto known = seen.find(key); known != seen.end())
              omega2_max = std::max(omega2_max, known->second * ratio_of(key));
            else if (queued.insert(key).second)
              {
                double bound = std::numeric_limits<double>::infinity();
                if (cell_box_edges(cell))
                  {
                    scaled_matrix(cell, key);
                    bound = gershgorin_bound(a);
                  }
                new_shapes.push_back({std::move(key), cell, bound});
              }
          }
      std::stable_sort(new_shapes.begin(),
                       new_shapes.end(),
                       [&](const NewShape &x, const NewShape &y) {
                         return x.bound * ratio_of(x.key) >
                                y.bound * ratio_of(y.key);
                       });
      for (const NewShape &shape : new_shapes)
        {
          const double ratio = ratio_of(shape.key);
          if (shape.bound * ratio <= omega2_max)
            seen.emplace(shape.key, shape.bound);
          else
            {
              scaled_matrix(shape.cell, shape.key);
              const double largest =
                largest_eigenvalue_above(a, omega2_max / ratio);
              omega2_max = std::max(omega2_max, largest * ratio);
              // The shape's largest eigenvalue is at most this.
              seen.emplace(shape.key, largest);
            }
        }
      omega2_max = dealii::Utilities::MPI::max(omega2_max, communicator);
      return std::sqrt(omega2_max);
    }



    template class BoxElementFrequency<2>;
    template class BoxElementFrequency<3>;
    template class ElementFrequencies<2>;
    template class ElementFrequencies<3>;
    template std::optional<Tensor<1, 2>>
    box_edges<2>(const std::array<Point<2>, 4> &);
    template std::optional<Tensor<1, 3>>
    box_edges<3>(const std::array<Point<3>, 8> &);
  } // namespace Operators
} // namespace rupture
