#include <rupture/base/utilities.h>
#include <rupture/scene/scene.h>

#include <vector>

namespace rupture
{
  namespace Scene
  {
    namespace
    {
      struct Entry
      {
        std::string                                    name;
        std::string                                    description;
        std::function<void(ParameterHandler &)>        declare;
        std::function<std::unique_ptr<Interface<2>>()> create_2d;
        std::function<std::unique_ptr<Interface<3>>()> create_3d;
      };

      std::vector<Entry> &
      registry()
      {
        static std::vector<Entry> entries;
        return entries;
      }

      std::unique_ptr<Interface<2>>
      make(const Entry &e, std::integral_constant<int, 2>)
      {
        return e.create_2d();
      }

      std::unique_ptr<Interface<3>>
      make(const Entry &e, std::integral_constant<int, 3>)
      {
        return e.create_3d();
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
      registry().push_back({name, description, declare, create_2d, create_3d});
      return true;
    }



    void
    declare_parameters(ParameterHandler &prm)
    {
      std::string names, descriptions;
      for (const auto &e : registry())
        {
          names += (names.empty() ? "" : "|") + e.name;
          descriptions += "\n'" + e.name + "': " + e.description;
        }
      prm.enter_subsection("Scene");
      prm.declare_entry("Model",
                        "box",
                        Patterns::Selection(names),
                        "The geometry with its material ids and named "
                        "boundaries. Available scenes:" +
                          descriptions);
      prm.leave_subsection();
      for (const auto &e : registry())
        e.declare(prm);
    }



    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(ParameterHandler &prm)
    {
      prm.enter_subsection("Scene");
      const std::string name = prm.get("Model");
      prm.leave_subsection();
      for (const auto &e : registry())
        if (e.name == name)
          {
            auto scene = make(e, std::integral_constant<int, dim>());
            scene->parse_parameters(prm);
            return scene;
          }
      AssertThrow(false,
                  ExcMessage("Unknown scene <" + name + "> in <Scene/Model>."));
      return nullptr;
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
