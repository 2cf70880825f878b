#ifndef rupture_scene_gmsh_mesh_h
#define rupture_scene_gmsh_mesh_h

#include <rupture/scene/scene.h>

namespace rupture
{
  namespace Scene
  {
    /**
     * A hexahedral (3-D) or quadrilateral (2-D) mesh read from a Gmsh .msh
     * file (format 2.2 or 4.1, ASCII). The physical tag of each volume
     * (surface in 2-D) element gives its material: the distinct tags, in
     * ascending order, are material ids 0, 1, 2, ... The physical tag of each
     * boundary face is its boundary id, and the $PhysicalNames section of
     * the file names those boundaries.
     */
    template <int dim>
    class GmshMesh : public Interface<dim>
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

    private:
      std::string file_name;
      /// The file's format, "2.2" or "4.1" (checked when it is parsed).
      std::string                               version;
      std::map<std::string, types::boundary_id> boundary_names;
    };
  } // namespace Scene
} // namespace rupture

#endif
