#include <rupture/scene/northeast_japan.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <cmath>

namespace rupture
{
  namespace Scene
  {
    template <int dim>
    void
    NortheastJapan<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scene");
      prm.enter_subsection("Northeast Japan");
      {
        prm.declare_entry("Length",
                          "620000",
                          Patterns::Double(0),
                          "East-west extent (m), the x direction.");
        prm.declare_entry("Width",
                          "200000",
                          Patterns::Double(0),
                          "North-south extent (m), the y direction (3-D "
                          "only).");
        prm.declare_entry("Depth",
                          "200000",
                          Patterns::Double(0),
                          "Depth of the block (m); the surface is at z = 0.");
        prm.declare_entry("Dip",
                          "28.5",
                          Patterns::Double(1, 89),
                          "Dip of the plate interface (degrees), downward "
                          "to the west.");
        prm.declare_entry("Trench position",
                          "500000",
                          Patterns::Double(0),
                          "x-coordinate (m) where the plate interface meets "
                          "the surface. The interface must reach the bottom "
                          "inside the block: Trench position > Depth / "
                          "tan(Dip).");
        prm.declare_entry("Crust thickness",
                          "30000",
                          Patterns::Double(0),
                          "Thickness (m) of the crust above the mantle, "
                          "west of the plate interface.");
        prm.declare_entry("Plate thickness",
                          "0",
                          Patterns::Double(0),
                          "Thickness (m) of the plate measured normal to "
                          "the interface; below it lies mantle. 0 means "
                          "everything below the interface is plate.");
        prm.declare_entry("Coarse cell size",
                          "20000",
                          Patterns::Double(0),
                          "Target edge length (m) of the coarse cells. Each "
                          "global refinement halves it: 20 km with 3 "
                          "refinements gives the paper's 2.5 km.");
      }
      prm.leave_subsection();
      prm.leave_subsection();
    }



    template <int dim>
    void
    NortheastJapan<dim>::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scene");
      prm.enter_subsection("Northeast Japan");
      {
        length          = prm.get_double("Length");
        width           = prm.get_double("Width");
        depth           = prm.get_double("Depth");
        dip             = prm.get_double("Dip") * numbers::PI / 180.;
        trench_x        = prm.get_double("Trench position");
        crust_thickness = prm.get_double("Crust thickness");
        plate_thickness = prm.get_double("Plate thickness");
        cell_size       = prm.get_double("Coarse cell size");
      }
      prm.leave_subsection();
      prm.leave_subsection();

      // Lengths in metres: from a millimetre to a million kilometres (the
      // mesh's Jacobians under- or overflow long before the limits of a
      // double).
      const auto check_length = [](const std::string &name,
                                   const double       value,
                                   const bool         zero_allowed) {
        std::ostringstream message;
        message << "<Scene/Northeast Japan/" << name << "> = " << value
                << " m is out of range. Allowed: "
                << (zero_allowed ? "0 or " : "")
                << "lengths from 1e-3 to 1e9 m (SI units).";
        AssertThrow((zero_allowed && value == 0) ||
                      (value >= 1e-3 && value <= 1e9),
                    ExcMessage(message.str()));
      };
      check_length("Length", length, false);
      check_length("Width", width, false);
      check_length("Depth", depth, false);
      check_length("Coarse cell size", cell_size, false);
      check_length("Trench position", trench_x, true);
      check_length("Crust thickness", crust_thickness, false);
      check_length("Plate thickness", plate_thickness, true);
      {
        std::ostringstream message;
        message << "<Scene/Northeast Japan/Trench position> = " << trench_x
                << " m must lie inside the block (< Length = " << length
                << " m).";
        AssertThrow(trench_x < length, ExcMessage(message.str()));
      }
      AssertThrow(fault_x(-depth) > 0,
                  ExcMessage("<Scene/Northeast Japan>: the plate interface "
                             "leaves the block through the west side. Allowed "
                             "is Trench position > Depth / tan(Dip) = " +
                             std::to_string(depth / std::tan(dip)) + " m."));
      AssertThrow(crust_thickness > 0 && crust_thickness < depth,
                  ExcMessage("<Scene/Northeast Japan/Crust thickness> must "
                             "lie in (0, Depth)."));
      AssertThrow(cell_size <= depth / 2,
                  ExcMessage("<Scene/Northeast Japan/Coarse cell size> must "
                             "be at most half the Depth."));
    }



    template <int dim>
    double
    NortheastJapan<dim>::fault_x(const double z) const
    {
      return trench_x + z / std::tan(dip);
    }



    template <int dim>
    void
    NortheastJapan<dim>::create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      // Build a unit-spaced structured grid in (xi, [eta,] zeta) and map it.
      // Columns 0..n_west are west of the interface, n_west..n_x east of it;
      // rows 0..n_mantle are below the crust-mantle boundary.
      const double       mean_west = 0.5 * (fault_x(0) + fault_x(-depth));
      const unsigned int n_west =
        std::max(1u,
                 static_cast<unsigned int>(std::round(mean_west / cell_size)));
      const unsigned int n_east =
        std::max(1u,
                 static_cast<unsigned int>(
                   std::round((length - mean_west) / cell_size)));
      const unsigned int n_crust = std::max(
        1u, static_cast<unsigned int>(std::round(crust_thickness / cell_size)));
      const unsigned int n_mantle =
        std::max(1u,
                 static_cast<unsigned int>(
                   std::round((depth - crust_thickness) / cell_size)));
      const unsigned int n_y =
        std::max(1u, static_cast<unsigned int>(std::round(width / cell_size)));

      std::vector<unsigned int> repetitions(dim, 1);
      repetitions[0]       = n_west + n_east;
      repetitions[dim - 1] = n_mantle + n_crust;
      if (dim == 3)
        repetitions[1] = n_y;

      Triangulation<dim> serial;
      Point<dim>         p1, p2;
      for (unsigned int d = 0; d < dim; ++d)
        p2[d] = repetitions[d];
      GridGenerator::subdivided_hyper_rectangle(
        serial, repetitions, p1, p2, true);

      const double crust_base = -crust_thickness;
      GridTools::transform(
        [&](const Point<dim> &p) {
          Point<dim> q;
          // Depth: piecewise linear, so that the crust base is a grid line.
          const double zeta = p[dim - 1];
          const double z =
            (zeta <= n_mantle) ?
              -depth + zeta / n_mantle * (depth - crust_thickness) :
              crust_base + (zeta - n_mantle) / n_crust * crust_thickness;
          // East-west: piecewise linear with the interface as a grid line.
          const double xi = p[0];
          const double xf = fault_x(z);
          q[0]            = (xi <= n_west) ? xi / n_west * xf :
                                             xf + (xi - n_west) / n_east * (length - xf);
          if (dim == 3)
            q[1] = p[1] / n_y * width;
          q[dim - 1] = z;
          return q;
        },
        serial);

      for (const auto &cell : serial.active_cell_iterators())
        {
          const Point<dim> c = cell->center();
          const double     z = c[dim - 1];
          // Signed distance below the interface z = (x - trench) tan(dip),
          // measured along its normal.
          const double below =
            ((c[0] - trench_x) * std::tan(dip) - z) * std::cos(dip);
          types::material_id id;
          if (below > 0 && (plate_thickness <= 0 || below < plate_thickness))
            id = 2;
          else if (below <= 0 && z > crust_base)
            id = 0;
          else
            id = 1;
          cell->set_material_id(id);
        }

      triangulation.copy_triangulation(serial);
    }



    template <int dim>
    std::map<std::string, types::boundary_id>
    NortheastJapan<dim>::get_boundary_names() const
    {
      return box_boundary_names<dim>();
    }

    RUPTURE_REGISTER_SCENE(
      NortheastJapan,
      "northeast japan",
      "the GeoFEM paper's 620 x 200 x 200 km block of Northeast Japan with "
      "crust (id 0), mantle (id 1) and a plate (id 2) below a plane dipping "
      "28.5 degrees; boundaries west/east, south/north (3-D), bottom/top.")

  } // namespace Scene
} // namespace rupture


template class rupture::Scene::NortheastJapan<2>;
template class rupture::Scene::NortheastJapan<3>;
