#include <rupture/base/utilities.h>
#include <rupture/scene/box.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold.h>

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
        prm.declare_entry(
          "Tree levels",
          "auto",
          Patterns::Anything(),
          "The box is built as a coarse mesh of blocks of 2^n cells in each "
          "direction, refined n times; the cells are the same whatever n. "
          "Every coarse cell is a tree of the distributed mesh (p4est), "
          "stored on every rank, so a large box built of coarse cells only "
          "needs several times the memory of its DoFs, on each rank. 'auto' "
          "(the default) takes n = 3 for boxes of more than 32768 cells and "
          "n = 0 otherwise; or give n from 0 to 4. A uniform or layered box "
          "uses the largest n up to this one that divides its numbers of "
          "cells (a layered box: also the cells below each interface, "
          "counted from the bottom, so that no coarse cell spans two "
          "layers); a graded box halves its largest outer cells where needed "
          "to make the numbers of cells divisible by 2^n.");
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
          {
            AssertThrow(upper_corner[d] > lower_corner[d],
                        ExcMessage("<Scene/Box/Upper corner> must be larger "
                                   "than <Scene/Box/Lower corner> in every "
                                   "coordinate, but coordinate " +
                                   std::to_string(d) + " is not."));
            // In metres: the mesh's Jacobians under- or overflow long
            // before the limits of a double.
            std::ostringstream message;
            message << "<Scene/Box/Lower corner> and <Scene/Box/Upper "
                       "corner> give coordinate "
                    << d << " the range [" << lower_corner[d] << ", "
                    << upper_corner[d]
                    << "] m. Allowed: coordinates within +-1e9 m and an "
                       "extent of at least 1e-3 m (SI units).";
            AssertThrow(std::abs(lower_corner[d]) <= 1e9 &&
                          std::abs(upper_corner[d]) <= 1e9 &&
                          upper_corner[d] - lower_corner[d] >= 1e-3,
                        ExcMessage(message.str()));
          }

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

        {
          const std::string levels = prm.get("Tree levels");
          if (levels.find_first_not_of(" \t") == std::string::npos ||
              levels.find("auto") != std::string::npos)
            tree_levels = -1;
          else
            {
              const std::vector<double> v =
                Utilities::parse_doubles(levels, "Scene/Box/Tree levels");
              const double n = v.size() == 1 ? v[0] : -1;
              AssertThrow(n >= 0 && n <= 4 && n == std::floor(n),
                          ExcMessage("<Scene/Box/Tree levels> must be 'auto' "
                                     "or an integer from 0 to 4, but is '" +
                                     levels + "'."));
              tree_levels = static_cast<int>(n);
            }
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
    Box<dim>::graded_steps(const unsigned int d,
                           const unsigned int multiple) const
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
      std::vector<double> lower = outer(core_lower[d] - lower_corner[d]);
      std::vector<double> upper = outer(upper_corner[d] - core_upper[d]);
      // Halve the largest outer cells until the number of cells is a
      // multiple of @p multiple (the outermost cells, far from the core).
      while ((lower.size() + n_cells[d] + upper.size()) % multiple != 0 &&
             !(lower.empty() && upper.empty()))
        {
          std::vector<double> &side =
            (lower.empty() ||
             (!upper.empty() && upper.back() >= lower.back())) ?
              upper :
              lower;
          const auto   largest = std::max_element(side.begin(), side.end());
          const double half    = (*largest /= 2);
          side.insert(largest, half);
        }
      std::vector<double> steps(lower.rbegin(), lower.rend());
      steps.insert(steps.end(), n_cells[d], h);
      steps.insert(steps.end(), upper.begin(), upper.end());
      return steps;
    }



    template <int dim>
    unsigned int
    Box<dim>::n_tree_levels() const
    {
      unsigned int n_total = 1;
      for (unsigned int d = 0; d < dim; ++d)
        n_total *= (growth_factor > 1 ? graded_steps(d, 1).size() : n_cells[d]);
      unsigned int levels =
        tree_levels >= 0 ? tree_levels : (n_total > 32768 ? 3 : 0);
      for (unsigned int d = 0; d < dim; ++d)
        {
          const bool has_outer =
            growth_factor > 1 && (core_lower[d] > lower_corner[d] ||
                                  core_upper[d] < upper_corner[d]);
          const unsigned int n =
            (growth_factor > 1 ? graded_steps(d, 1).size() : n_cells[d]);
          // At least one coarse cell in each direction; without outer
          // cells to halve, a number of levels that divides the cells.
          while (levels > 0 && ((1u << levels) > n ||
                                (!has_outer && n % (1u << levels) != 0)))
            --levels;
        }
      return levels;
    }



    namespace
    {
      /**
       * Where the cells of a box built as refined blocks lie: per
       * direction, the chart is the coordinate in which each block is cut
       * into equal parts (as refinement cuts it), and the map takes it to
       * the vertex coordinates @p x asked for (piecewise linear in the
       * index of the vertex). Refinement then puts new vertices where the
       * box put them, also when p4est refines a coarse cell again after
       * moving cells between processes or loading a checkpoint.
       */
      template <int dim>
      class BlockManifold : public ChartManifold<dim, dim, dim>
      {
      public:
        BlockManifold(const std::vector<std::vector<double>> &x,
                      const std::vector<std::vector<double>> &coarse_x,
                      const unsigned int                      m)
          : x(x)
          , coarse_x(coarse_x)
          , m(m)
        {}

        std::unique_ptr<Manifold<dim, dim>>
        clone() const override
        {
          return std::make_unique<BlockManifold<dim>>(*this);
        }

        Point<dim>
        pull_back(const Point<dim> &q) const override
        {
          Point<dim> c;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double index = position(x[d], q[d]);
              const auto   n     = coarse_x[d].size() - 1;
              const auto   k     = std::min<std::size_t>(
                static_cast<std::size_t>(std::max(index, 0.) / m), n - 1);
              c[d] = coarse_x[d][k] + (index - double(k * m)) / m *
                                        (coarse_x[d][k + 1] - coarse_x[d][k]);
            }
          return c;
        }

        Point<dim>
        push_forward(const Point<dim> &c) const override
        {
          Point<dim> q;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double block = position(coarse_x[d], c[d]);
              q[d]               = value(x[d], block * m);
            }
          return q;
        }

      private:
        /// The (fractional) index at which the increasing @p v takes @p y.
        static double
        position(const std::vector<double> &v, const double y)
        {
          const std::size_t i = std::min<std::size_t>(
            std::max<std::ptrdiff_t>(std::upper_bound(v.begin(), v.end(), y) -
                                       v.begin() - 1,
                                     0),
            v.size() - 2);
          return i + (y - v[i]) / (v[i + 1] - v[i]);
        }

        /// @p v at the fractional index @p index (exactly v[i] near i).
        static double
        value(const std::vector<double> &v, const double index)
        {
          const double nearest = std::round(index);
          if (std::abs(index - nearest) < 1e-9 && nearest >= 0 &&
              nearest <= v.size() - 1)
            return v[static_cast<std::size_t>(nearest)];
          const std::size_t i =
            std::min<std::size_t>(static_cast<std::size_t>(std::max(index, 0.)),
                                  v.size() - 2);
          return v[i] + (index - i) * (v[i + 1] - v[i]);
        }

        std::vector<std::vector<double>> x, coarse_x;
        unsigned int                     m;
      };
    } // namespace



    template <int dim>
    double
    Box<dim>::on_core_grid(const unsigned int d, const double v) const
    {
      if (!(growth_factor > 1))
        return v;
      const double h = (core_upper[d] - core_lower[d]) / n_cells[d];
      const double i = std::round((v - core_lower[d]) / h);
      if (i >= 0 && i <= n_cells[d] &&
          std::abs(v - (core_lower[d] + i * h)) <= 1e-6 * h)
        return (i == n_cells[d]) ? core_upper[d] : core_lower[d] + i * h;
      return v;
    }



    template <int dim>
    void
    Box<dim>::build_tensor_mesh(
      parallel::distributed::Triangulation<dim> &triangulation,
      const std::vector<std::vector<double>>    &steps,
      const unsigned int                         levels) const
    {
      // The vertex coordinates along each direction, and the coarse cells:
      // blocks of 2^levels cells, refined levels times below; the refined
      // vertices are then moved to the coordinates of the cells asked for.
      const unsigned int               m = 1u << levels;
      std::vector<std::vector<double>> x(dim), coarse(dim), coarse_x(dim);
      for (unsigned int d = 0; d < dim; ++d)
        {
          Assert(steps[d].size() % m == 0, ExcInternalError());
          x[d].push_back(lower_corner[d]);
          for (const double step : steps[d])
            x[d].push_back(x[d].back() + step);
          x[d].back() = upper_corner[d];
          for (unsigned int k = 0; k * m < steps[d].size(); ++k)
            {
              coarse[d].push_back(x[d][(k + 1) * m] - x[d][k * m]);
              coarse_x[d].push_back(x[d][k * m]);
            }
          coarse_x[d].push_back(upper_corner[d]);
          // The refined vertices go exactly onto a graded core's grid.
          for (double &v : x[d])
            v = on_core_grid(d, v);
        }
      GridGenerator::subdivided_hyper_rectangle(
        triangulation, coarse, lower_corner, upper_corner, true);
      if (levels == 0)
        return;
      const types::manifold_id blocks = 1;
      triangulation.set_all_manifold_ids(blocks);
      triangulation.set_manifold(blocks, BlockManifold<dim>(x, coarse_x, m));
      triangulation.refine_global(levels);
      // The manifold put the refined vertices on the coordinates asked for;
      // the coarse cells' vertices (sums of the blocks' sizes) go there
      // too, to the nearest one.
      GridTools::transform(
        [&](const Point<dim> &p) {
          Point<dim> q;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const auto above =
                std::lower_bound(x[d].begin(), x[d].end(), p[d]);
              const auto below = (above == x[d].begin()) ? above : above - 1;
              q[d]             = (above == x[d].end() ||
                      std::abs(*below - p[d]) <= std::abs(*above - p[d])) ?
                                   *below :
                                   *above;
            }
          return q;
        },
        triangulation);
    }



    template <int dim>
    void
    Box<dim>::create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      const unsigned int levels = n_tree_levels();
      if (growth_factor > 1)
        {
          std::vector<std::vector<double>> steps(dim);
          for (unsigned int d = 0; d < dim; ++d)
            steps[d] = graded_steps(d, 1u << levels);
          build_tensor_mesh(triangulation, steps, levels);
          // The vertices are sums of the cell sizes from the lower corner,
          // so the round-off of the scaled outer cells shifts the core's
          // vertices by some 1e-12 m. Put them exactly on the core's grid:
          // a region given as "abs(x) <= 1500" must contain the vertex at
          // 1500 whatever the grading (TPV3's nucleation patch lost its
          // edge nodes at 250 m before).
          GridTools::transform(
            [this](const Point<dim> &p) {
              Point<dim> q;
              for (unsigned int d = 0; d < dim; ++d)
                q[d] = on_core_grid(d, p[d]);
              return q;
            },
            triangulation);
          // Colorizing numbers the boundaries, but also sets material ids
          // by octant.
          set_materials(triangulation);
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

      // A coarse cell lies in one layer: each layer's cells (counted from
      // the bottom) fill whole blocks of 2^levels.
      const auto aligned = [&](const unsigned int l) {
        const unsigned int m = 1u << l;
        unsigned int       n = 0;
        for (int k = n_layers - 1; k >= 0; --k)
          {
            n += layer_cells[k];
            if (n % m != 0)
              return false;
          }
        return true;
      };
      unsigned int layered_levels = levels;
      while (layered_levels > 0 && !aligned(layered_levels))
        --layered_levels;
      build_tensor_mesh(triangulation, steps, layered_levels);
      set_materials(triangulation);
    }



    template <int dim>
    void
    Box<dim>::set_materials(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      // Every cell, not the active ones alone: a process that refines a
      // coarse cell later (p4est moves cells between processes, a
      // checkpoint is loaded onto the coarse mesh) gives the children
      // their parent's material.
      for (const auto &cell : triangulation.cell_iterators())
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

    template <int dim>
    double
    Box<dim>::n_coarse_cells() const
    {
      double n = 1;
      for (const unsigned int c : n_cells)
        n *= c;
      return n;
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
