#include <rupture/simulator/simulator.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>

namespace rupture
{
  template <int dim>
  std::vector<std::vector<double>>
  Simulator<dim>::rigid_body_modes() const
  {
    const unsigned int               n_modes = dim * (dim + 1) / 2;
    std::vector<std::vector<double>> modes(
      n_modes,
      std::vector<double>(discretization.locally_owned_dofs().n_elements(),
                          0.));
    discretization.for_each_support_point(
      [](const auto &cell) { return cell->is_locally_owned(); },
      [&](const auto                                 &cell,
          const std::vector<types::global_dof_index> &dofs,
          const std::vector<Point<dim>>              &points) {
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            if (!discretization.locally_owned_dofs().is_element(dofs[i]))
              continue;
            const unsigned int k =
              discretization.locally_owned_dofs().index_within_set(dofs[i]);
            const unsigned int c =
              cell->get_fe().system_to_component_index(i).first % dim;
            const Point<dim> &x = points[i];
            modes[c][k]         = 1;
            if (dim == 2)
              modes[2][k] = (c == 0 ? -x[1] : x[0]);
            else
              {
                // Rotations about the z, x and y axes.
                const double rz[3] = {-x[1], x[0], 0};
                const double rx[3] = {0, -x[2], x[1]};
                const double ry[3] = {x[2], 0, -x[0]};
                modes[3][k]        = rz[c];
                modes[4][k]        = rx[c];
                modes[5][k]        = ry[c];
              }
          }
      });
    return modes;
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace rupture
