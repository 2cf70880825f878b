#include <rupture/base/utilities.h>
#include <rupture/scene/box.h>

#include <deal.II/grid/grid_generator.h>

#include <algorithm>
#include <cmath>

namespace rupture
{
  namespace Scene
  {
    template <int dim>
    void
    Box<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scene");
      prm.enter_subsection("Box");
      {
        prm.declare_entry("Lower corner",
                          "0",
                          Patterns::Anything(),
                          "Coordinates of the lower corner (m): one number "
                          "per dimension, or a single number for all.");
        prm.declare_entry("Upper corner",
                          "1000",
                          Patterns::Anything(),
                          "Coordinates of the upper corner (m), each larger "
                          "than the lower corner's: one number per "
                          "dimension, or a single number for all.");
        prm.declare_entry("Number of cells",
                          "4",
                          Patterns::Anything(),
                          "Number of coarse cells in each direction, before "
                          "<Mesh/Initial global refinement>: one integer per "
                          "dimension, or a single one for all.");
        prm.declare_entry(
          "Layer interfaces",
          "",
          Patterns::Anything(),
          "Values of the last coordinate (m, the vertical one) where the "
          "material changes, e.g. '-2000, -10000'. Empty for a homogeneous "
          "box. The top layer is material id 0, the next one down 1, and so "
          "on. The mesh is built so that each interface is a mesh surface.");
      }
      prm.leave_subsection();
      prm.leave_subsection();
    }



    template <int dim>
    void
    Box<dim>::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scene");
      prm.enter_subsection("Box");
      {
        lower_corner = Point<dim>(Utilities::parse_vector<dim>(
          prm.get("Lower corner"), "Scene/Box/Lower corner", true));
        upper_corner = Point<dim>(Utilities::parse_vector<dim>(
          prm.get("Upper corner"), "Scene/Box/Upper corner", true));
        for (unsigned int d = 0; d < dim; ++d)
          AssertThrow(upper_corner[d] > lower_corner[d],
                      ExcMessage("<Scene/Box/Upper corner> must be larger "
                                 "than <Scene/Box/Lower corner> in every "
                                 "coordinate, but coordinate " +
                                 std::to_string(d) + " is not."));

        const Tensor<1, dim> cells =
          Utilities::parse_vector<dim>(prm.get("Number of cells"),
                                       "Scene/Box/Number of cells",
                                       true);
        n_cells.clear();
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double c = cells[d];
            AssertThrow(c >= 1 && c == std::floor(c) && c < 1e6,
                        ExcMessage("<Scene/Box/Number of cells> must hold "
                                   "positive integers, but contains " +
                                   std::to_string(c) + "."));
            n_cells.push_back(static_cast<unsigned int>(c));
          }

        layer_interfaces =
          Utilities::parse_doubles(prm.get("Layer interfaces"),
                                   "Scene/Box/Layer interfaces");
        std::sort(layer_interfaces.begin(),
                  layer_interfaces.end(),
                  std::greater<double>());
        for (const double z : layer_interfaces)
          AssertThrow(z > lower_corner[dim - 1] && z < upper_corner[dim - 1],
                      ExcMessage("<Scene/Box/Layer interfaces> contains " +
                                 std::to_string(z) +
                                 ", which is not strictly inside the box's "
                                 "vertical extent."));
        AssertThrow(layer_interfaces.size() + 1 <= n_cells[dim - 1],
                    ExcMessage("<Scene/Box/Layer interfaces> defines more "
                               "layers than there are cells in the vertical "
                               "direction; increase <Scene/Box/Number of "
                               "cells>."));
      }
      prm.leave_subsection();
      prm.leave_subsection();
    }



    template <int dim>
    void
    Box<dim>::create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      // Cell sizes per direction. In the vertical direction the layer
      // interfaces are mesh lines: each layer gets a share of the cells in
      // proportion to its thickness.
      std::vector<std::vector<double>> steps(dim);
      for (unsigned int d = 0; d + 1 < dim; ++d)
        steps[d].assign(n_cells[d],
                        (upper_corner[d] - lower_corner[d]) / n_cells[d]);

      std::vector<double> breaks = {upper_corner[dim - 1]};
      breaks.insert(breaks.end(),
                    layer_interfaces.begin(),
                    layer_interfaces.end());
      breaks.push_back(lower_corner[dim - 1]);
      const double       total = upper_corner[dim - 1] - lower_corner[dim - 1];
      const unsigned int n_layers = breaks.size() - 1;
      std::vector<unsigned int> layer_cells(n_layers);
      for (unsigned int l = 0; l < n_layers; ++l)
        {
          const double share =
            n_cells[dim - 1] * (breaks[l] - breaks[l + 1]) / total;
          layer_cells[l] =
            std::max(1u, static_cast<unsigned int>(std::round(share)));
        }
      // Steps go from the bottom up; layers were listed from the top down.
      for (int l = n_layers - 1; l >= 0; --l)
        for (unsigned int i = 0; i < layer_cells[l]; ++i)
          steps[dim - 1].push_back((breaks[l] - breaks[l + 1]) /
                                   layer_cells[l]);

      GridGenerator::subdivided_hyper_rectangle(
        triangulation, steps, lower_corner, upper_corner, true);

      for (const auto &cell : triangulation.active_cell_iterators())
        {
          const double       z  = cell->center()[dim - 1];
          types::material_id id = 0;
          for (const double interface : layer_interfaces)
            if (z < interface)
              ++id;
          cell->set_material_id(id);
        }
    }



    template <int dim>
    std::map<std::string, types::boundary_id>
    Box<dim>::get_boundary_names() const
    {
      return box_boundary_names<dim>();
    }

    RUPTURE_REGISTER_SCENE(
      Box,
      "box",
      "a rectangular box, optionally layered, with boundaries west/east, "
      "south/north (3-D) and bottom/top; for verification.")

  } // namespace Scene
} // namespace rupture


template class rupture::Scene::Box<2>;
template class rupture::Scene::Box<3>;
