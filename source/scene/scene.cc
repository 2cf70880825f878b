#include <rupture/base/registry.h>
#include <rupture/base/utilities.h>
#include <rupture/scene/scene.h>

#include <vector>

namespace rupture
{
  namespace Scene
  {
    namespace
    {
      struct Factories
      {
        std::function<std::unique_ptr<Interface<2>>()> create_2d;
        std::function<std::unique_ptr<Interface<3>>()> create_3d;
      };

      Utilities::Registry<Factories> &
      registry()
      {
        static Utilities::Registry<Factories> entries;
        return entries;
      }

      std::unique_ptr<Interface<2>>
      make(const Factories &f, std::integral_constant<int, 2>)
      {
        return f.create_2d();
      }

      std::unique_ptr<Interface<3>>
      make(const Factories &f, std::integral_constant<int, 3>)
      {
        return f.create_3d();
      }
    } // namespace



    bool
    register_scene(
      const std::string                                    &name,
      const std::string                                    &description,
      const std::function<void(ParameterHandler &)>        &declare,
      const std::function<std::unique_ptr<Interface<2>>()> &create_2d,
      const std::function<std::unique_ptr<Interface<3>>()> &create_3d)
    {
      return registry().add(
        {name, description, declare, {create_2d, create_3d}});
    }



    void
    declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Scene");
      prm.declare_entry("Model",
                        "box",
                        Patterns::Selection(registry().selection()),
                        "The geometry with its material ids and named "
                        "boundaries. Available scenes:" +
                          registry().descriptions());
      prm.leave_subsection();
      registry().declare_all(prm);
    }



    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(ParameterHandler &prm)
    {
      prm.enter_subsection("Scene");
      const std::string name = prm.get("Model");
      prm.leave_subsection();
      auto scene = make(registry().find(name, "Scene/Model").create,
                        std::integral_constant<int, dim>());
      scene->parse_parameters(prm);
      return scene;
    }



    template <int dim>
    std::map<std::string, types::boundary_id>
    box_boundary_names()
    {
      // Colorized ids: 2d for the lower and 2d+1 for the upper face in
      // direction d.
      if (dim == 2)
        return {{"west", 0}, {"east", 1}, {"bottom", 2}, {"top", 3}};
      return {{"west", 0},
              {"east", 1},
              {"south", 2},
              {"north", 3},
              {"bottom", 4},
              {"top", 5}};
    }



    template std::map<std::string, types::boundary_id>
    box_boundary_names<2>();
    template std::map<std::string, types::boundary_id>
    box_boundary_names<3>();
    template std::unique_ptr<Interface<2>>
    create<2>(ParameterHandler &);
    template std::unique_ptr<Interface<3>>
    create<3>(ParameterHandler &);
  } // namespace Scene
} // namespace rupture
