#ifndef rupture_scene_scene_h
#define rupture_scene_scene_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <deal.II/distributed/tria.h>

#include <functional>
#include <map>
#include <memory>
#include <string>

namespace rupture
{
  using namespace dealii;

  /**
   * A scene is a geometry with its material ids and named boundaries. The
   * materials' constants, the boundary conditions and the loads refer to
   * it by material id and boundary name.
   */
  namespace Scene
  {
    template <int dim>
    class Interface
    {
    public:
      virtual ~Interface() = default;

      /**
       * Read this scene's own subsection "Scene/<name>".
       */
      virtual void
      parse_parameters(ParameterHandler &prm) = 0;

      /**
       * Build the coarse mesh, with material ids and boundary ids set.
       * Global refinement is done afterwards by the simulator.
       */
      virtual void
      create_coarse_mesh(
        parallel::distributed::Triangulation<dim> &triangulation) const = 0;

      /**
       * The names a user may give to boundary conditions, with their ids.
       */
      virtual std::map<std::string, types::boundary_id>
      get_boundary_names() const = 0;

      /**
       * The number of cells of the coarse mesh if it is known before the
       * mesh is built (for the memory check before set-up), else 0.
       */
      virtual double
      n_coarse_cells() const
      {
        return 0;
      }
    };



    /**
     * The boundary names of a box-shaped scene built with colorized
     * subdivided_hyper_rectangle: west/east (x), south/north (y, 3-D) and
     * bottom/top (the last coordinate).
     */
    template <int dim>
    std::map<std::string, types::boundary_id>
    box_boundary_names();

    /**
     * Add a scene to the registry. Use RUPTURE_REGISTER_SCENE instead of
     * calling this directly.
     */
    bool
    register_scene(
      const std::string                                    &name,
      const std::string                                    &description,
      const std::function<void(ParameterHandler &)>        &declare,
      const std::function<std::unique_ptr<Interface<2>>()> &create_2d,
      const std::function<std::unique_ptr<Interface<3>>()> &create_3d);

    /**
     * Declare "Scene/Model" and the subsections of all registered scenes.
     */
    void
    declare_parameters(ParameterHandler &prm);

    /**
     * Create and parse the scene named in "Scene/Model".
     */
    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(ParameterHandler &prm);
  } // namespace Scene
} // namespace rupture

/**
 * Register a scene class template @p classname (instantiated for 2 and 3
 * dimensions, with a static declare_parameters()) under @p name.
 */
#define RUPTURE_REGISTER_SCENE(classname, name, description)               \
  namespace                                                                \
  {                                                                        \
    const bool dummy_scene_##classname = ::rupture::Scene::register_scene( \
      name,                                                                \
      description,                                                         \
      &classname<2>::declare_parameters,                                   \
      []() {                                                               \
        return std::unique_ptr<::rupture::Scene::Interface<2>>(            \
          new classname<2>());                                             \
      },                                                                   \
      []() {                                                               \
        return std::unique_ptr<::rupture::Scene::Interface<3>>(            \
          new classname<3>());                                             \
      });                                                                  \
  }

#endif
