#include <rupture/friction/interface.h>

namespace rupture
{
  namespace Friction
  {
    void
    Interface::initialize_state(const Point<3> &, State &state) const
    {
      state = State();
    }



    void
    Interface::update_state(const Point<3> &,
                            const State &old,
                            const double slip_increment,
                            const double dt,
                            State       &updated) const
    {
      updated           = old;
      updated.slip_path = old.slip_path + slip_increment;
      updated.slip_rate = slip_increment / dt;
    }



    void
    Interface::set_time(const double time)
    {
      current_time = time;
    }



    void
    Interface::start_dynamic_phase(const double time)
    {
      dynamic_start = time;
    }



    void
    Interface::enable_weakening(const bool enable)
    {
      weakening_enabled = enable;
    }



    bool
    Interface::can_weaken(const Point<3> &, const State &) const
    {
      return false;
    }



    namespace
    {
      struct Entry
      {
        std::string                                 name;
        std::string                                 description;
        std::function<void(ParameterHandler &)>     declare;
        std::function<std::unique_ptr<Interface>()> create;
      };

      std::vector<Entry> &
      registry()
      {
        static std::vector<Entry> entries;
        return entries;
      }
    } // namespace



    bool
    register_law(const std::string                                 &name,
                 const std::string                                 &description,
                 const std::function<void(ParameterHandler &)>     &declare,
                 const std::function<std::unique_ptr<Interface>()> &create)
    {
      registry().push_back({name, description, declare, create});
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
      prm.declare_entry("Friction law",
                        registry().empty() ? "" : registry().front().name,
                        Patterns::Selection(names),
                        "The friction law of the fault. Available laws:" +
                          descriptions);
      for (const auto &e : registry())
        e.declare(prm);
    }



    std::unique_ptr<Interface>
    create(ParameterHandler &prm)
    {
      const std::string name = prm.get("Friction law");
      for (const auto &e : registry())
        if (e.name == name)
          {
            auto law = e.create();
            law->parse_parameters(prm);
            return law;
          }
      AssertThrow(false,
                  ExcMessage("Unknown friction law <" + name +
                             "> in <Fault/Friction law>."));
      return nullptr;
    }
  } // namespace Friction
} // namespace rupture
