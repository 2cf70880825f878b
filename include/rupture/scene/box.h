#ifndef rupture_scene_box_h
#define rupture_scene_box_h

#include <rupture/scene/scene.h>

#include <deal.II/base/point.h>

#include <vector>

namespace rupture
{
  namespace Scene
  {
    /**
     * A rectangular box, optionally cut into horizontal layers of different
     * material. Boundaries are named west/east (x), south/north (y, 3-D
     * only) and bottom/top (the last coordinate, which points up). Layers
     * are numbered from the top: material id 0 is the top layer.
     *
     * A graded box has uniform cells only in a core (around a fault, say)
     * and cells that grow geometrically from the core to the box faces, so
     * that absorbing boundaries can be far away at little cost.
     */
    template <int dim>
    class Box : public Interface<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      void
      create_coarse_mesh(parallel::distributed::Triangulation<dim>
                           &triangulation) const override;

      std::map<std::string, types::boundary_id>
      get_boundary_names() const override;

      double
      n_coarse_cells() const override;

    private:
      Point<dim>                lower_corner;
      Point<dim>                upper_corner;
      std::vector<unsigned int> n_cells;
      /// Interfaces between layers, as values of the last coordinate.
      std::vector<double> layer_interfaces;
      /// Grading: growth factor (1: uniform) and the uniform core.
      double     growth_factor;
      Point<dim> core_lower;
      Point<dim> core_upper;

      /// Tree levels asked for: -1 for 'auto'.
      int tree_levels;

      /**
       * Cell sizes along direction d of a graded box, with the largest
       * outer cells halved until their number is a multiple of
       * @p multiple.
       */
      std::vector<double>
      graded_steps(const unsigned int d, const unsigned int multiple) const;

      /// The number of refinements between the coarse mesh and the cells.
      unsigned int
      n_tree_levels() const;

      /**
       * The tensor-product mesh with cell sizes @p steps in each direction,
       * built as blocks of 2^levels cells refined @p levels times.
       */
      void
      build_tensor_mesh(
        parallel::distributed::Triangulation<dim> &triangulation,
        const std::vector<std::vector<double>>    &steps,
        const unsigned int                         levels) const;

      /// @p v on direction @p d's grid of the graded box's core, if it
      /// lies within round-off of it (else @p v).
      double
      on_core_grid(const unsigned int d, const double v) const;

      /// The material id of every cell, active or not: its layer.
      void
      set_materials(
        parallel::distributed::Triangulation<dim> &triangulation) const;
    };
  } // namespace Scene
} // namespace rupture

#endif
