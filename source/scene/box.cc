#include <rupture/base/utilities.h>
#include <rupture/scene/box.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

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
                          "<Discretization/Initial global refinement>: one "
                          "integer per dimension, or a single one for all. "
                          "In a graded box (<Grading/Growth factor> above 1) "
                          "the number of uniform cells across the core.");
        prm.declare_entry(
          "Layer interfaces",
          "",
          Patterns::Anything(),
          "Values of the last coordinate (m, the vertical one) where the "
          "material changes, e.g. '-2000, -10000'. Empty for a homogeneous "
          "box. The top layer is material id 0, the next one down 1, and so "
          "on. The mesh is built so that each interface is a mesh surface.");
        prm.enter_subsection("Grading");
        {
          prm.declare_entry(
            "Growth factor",
            "1",
            Patterns::Double(1, 2),
            "1 (the default) gives uniform cells over the whole box (the "
            "core corners are then not used, so a graded box is switched off "
            "by this entry alone). Above 1 only the core "
            "(<Core lower corner> to <Core upper corner>) has uniform cells, "
            "<Number of cells> across it; outside the core each cell is this "
            "factor larger than its neighbour towards the core, up to the "
            "box faces (the outermost cells of each side are scaled "
            "together to end on the face). Values of 1.05-1.2 keep "
            "reflections from the change of size small. Not with <Layer "
            "interfaces>.");
          prm.declare_entry("Core lower corner",
                            "",
                            Patterns::Anything(),
                            "Lower corner of the uniform core (m), inside the "
                            "box; empty for the box's lower corner.");
          prm.declare_entry("Core upper corner",
                            "",
                            Patterns::Anything(),
                            "Upper corner of the uniform core (m), inside the "
                            "box; empty for the box's upper corner.");
        }
        prm.leave_subsection();
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
        prm.enter_subsection("Grading");
        {
          growth_factor           = prm.get_double("Growth factor");
          const std::string lower = prm.get("Core lower corner");
          const std::string upper = prm.get("Core upper corner");
          core_lower = lower.find_first_not_of(" \t") == std::string::npos ?
                         lower_corner :
                         Point<dim>(Utilities::parse_vector<dim>(
                           lower, "Scene/Box/Grading/Core lower corner", true));
          core_upper = upper.find_first_not_of(" \t") == std::string::npos ?
                         upper_corner :
                         Point<dim>(Utilities::parse_vector<dim>(
                           upper, "Scene/Box/Grading/Core upper corner", true));
        }
        prm.leave_subsection();
        for (unsigned int d = 0; d < dim; ++d)
          AssertThrow(lower_corner[d] <= core_lower[d] &&
                        core_lower[d] < core_upper[d] &&
                        core_upper[d] <= upper_corner[d],
                      ExcMessage(
                        "<Scene/Box/Grading/Core lower corner> and <Core "
                        "upper corner> must lie inside the box, the lower "
                        "below the upper, but coordinate " +
                        std::to_string(d) + " does not."));
        AssertThrow(growth_factor == 1 || layer_interfaces.empty(),
                    ExcMessage("<Scene/Box/Grading/Growth factor> above 1 "
                               "cannot be combined with <Scene/Box/Layer "
                               "interfaces>; use one or the other."));
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
    std::vector<double>
    Box<dim>::graded_steps(const unsigned int d) const
    {
      const double h = (core_upper[d] - core_lower[d]) / n_cells[d];
      // Cells growing by the factor from h r on, enough to cover the
      // distance, then scaled together to end exactly on the face.
      const auto outer = [&](const double distance) {
        std::vector<double> cells;
        double              size = h, sum = 0;
        while (sum < distance * (1 - 1e-12))
          {
            size *= growth_factor;
            cells.push_back(size);
            sum += size;
          }
        for (double &c : cells)
          c *= distance / sum;
        return cells;
      };
      std::vector<double> steps = outer(core_lower[d] - lower_corner[d]);
      std::reverse(steps.begin(), steps.end());
      steps.insert(steps.end(), n_cells[d], h);
      const std::vector<double> upper = outer(upper_corner[d] - core_upper[d]);
      steps.insert(steps.end(), upper.begin(), upper.end());
      return steps;
    }



    template <int dim>
    void
    Box<dim>::create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      if (growth_factor > 1)
        {
          std::vector<std::vector<double>> steps(dim);
          for (unsigned int d = 0; d < dim; ++d)
            steps[d] = graded_steps(d);
          GridGenerator::subdivided_hyper_rectangle(
            triangulation, steps, lower_corner, upper_corner, true);
          // The vertices are sums of the cell sizes from the lower corner,
          // so the round-off of the scaled outer cells shifts the core's
          // vertices by some 1e-12 m. Put them exactly on the core's grid:
          // a region given as "abs(x) <= 1500" must contain the vertex at
          // 1500 whatever the grading (TPV3's nucleation patch lost its
          // edge nodes at 250 m before).
          GridTools::transform(
            [this](const Point<dim> &p) {
              Point<dim> q = p;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  const double h = (core_upper[d] - core_lower[d]) / n_cells[d];
                  const double i = std::round((p[d] - core_lower[d]) / h);
                  if (i >= 0 && i <= n_cells[d] &&
                      std::abs(p[d] - (core_lower[d] + i * h)) <= 1e-6 * h)
                    q[d] =
                      (i == n_cells[d]) ? core_upper[d] : core_lower[d] + i * h;
                }
              return q;
            },
            triangulation);
          // Colorizing numbers the boundaries, but also sets material ids.
          for (const auto &cell : triangulation.active_cell_iterators())
            cell->set_material_id(0);
          return;
        }
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
