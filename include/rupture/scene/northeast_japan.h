#ifndef rupture_scene_northeast_japan_h
#define rupture_scene_northeast_japan_h

#include <rupture/scene/scene.h>

namespace rupture
{
  namespace Scene
  {
    /**
     * The Northeast-Japan block of the GeoFEM paper: a box 620 km east-west
     * (x) by 200 km north-south (y) by 200 km deep (the last coordinate,
     * z = 0 at the surface and negative below). A plane dipping westward at
     * 28.5 degrees from the trench (where it meets the surface) separates
     * the subducting plate (below and east of it) from the crust and mantle
     * (above it); that plane becomes the fault in the fault issue.
     *
     * Material ids: 0 = crust (above the fault and shallower than the crust
     * thickness), 1 = mantle, 2 = plate. In 2-D the scene is the east-west
     * cross-section (x, z).
     *
     * The hexahedral mesh is structured: its vertical grid lines bend at the
     * dipping plane so that the plane is a surface of mesh faces on every
     * refinement level, and the crust-mantle boundary is a mesh surface.
     * Boundaries are named west, east, south, north (3-D), bottom and top.
     */
    template <int dim>
    class NortheastJapan : public Interface<dim>
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

      /**
       * x-coordinate of the dipping plane at depth -z (z <= 0).
       */
      double
      fault_x(const double z) const;

    private:
      double length;
      double width;
      double depth;
      double dip;
      double trench_x;
      double crust_thickness;
      double plate_thickness;
      double cell_size;
    };
  } // namespace Scene
} // namespace rupture

#endif
