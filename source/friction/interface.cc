#include <rupture/base/registry.h>
#include <rupture/friction/interface.h>

#include <algorithm>

namespace rupture
{
  namespace Friction
  {
    void
    Interface::initialize_state(const Point<3> &,
                                const double,
                                State &state) const
    {
      state = State();
    }



    double
    Interface::strength(const Point<3> &x,
                        const State    &old,
                        const double    slip_increment,
                        const double    dt,
                        const double    pressure,
                        double         &derivative_increment,
                        double         &derivative_pressure) const
    {
      double       dmu     = 0;
      const double mu      = coefficient(x, old, slip_increment, dt, dmu);
      derivative_increment = dmu * pressure;
      derivative_pressure  = mu;
      return mu * pressure + cohesion(x, old);
    }



    void
    Interface::check_uniqueness(const Point<3> &,
                                const State &,
                                const double,
                                const double) const
    {}



    double
    Interface::slip_scale(const Point<3> &, const State &) const
    {
      return std::numeric_limits<double>::quiet_NaN();
    }



    void
    Interface::state_rate(const Point<3> &,
                          const State &,
                          const double,
                          std::vector<double> &) const
    {
      AssertThrow(false,
                  ExcMessage("This friction law gives no rate of change of "
                             "its state (has_state_rate() is false)."));
    }



    double
    Interface::process_zone_width(const Point<3> &,
                                  const State &,
                                  const double,
                                  const double) const
    {
      return std::numeric_limits<double>::quiet_NaN();
    }



    void
    Interface::update_state(const Point<3> &,
                            const State &old,
                            const double slip_increment,
                            const double dt,
                            const double,
                            State &updated) const
    {
      updated           = old;
      updated.slip_path = old.slip_path + slip_increment;
      updated.slip_rate = (dt > 0) ? slip_increment / dt : 0.;
    }



    double
    Interface::coefficient_at_rate(const Point<3> &x,
                                   const State    &state,
                                   const double,
                                   double &derivative) const
    {
      double       unused = 0;
      const double mu     = coefficient(x, state, 0., 0., unused);
      derivative          = 0;
      return mu;
    }



    double
    Interface::strength_at_rate(const Point<3> &x,
                                const State    &state,
                                const double    V,
                                const double    pressure,
                                double         &derivative_rate,
                                double         &derivative_pressure) const
    {
      double       dmu    = 0;
      const double mu     = coefficient_at_rate(x, state, V, dmu);
      derivative_rate     = dmu * pressure;
      derivative_pressure = mu;
      return mu * pressure + cohesion(x, state);
    }



    void
    Interface::set_time(const double)
    {}



    void
    Interface::start_dynamic_phase(const double)
    {}



    void
    Interface::enable_weakening(const bool)
    {}



    bool
    Interface::can_weaken(const Point<3> &, const State &) const
    {
      return false;
    }



    namespace
    {
      using Factory = std::function<std::unique_ptr<Interface>()>;

      Utilities::Registry<Factory> &
      registry()
      {
        static Utilities::Registry<Factory> entries;
        return entries;
      }
    } // namespace



    bool
    register_law(const std::string                                 &name,
                 const std::string                                 &description,
                 const std::function<void(ParameterHandler &)>     &declare,
                 const std::function<std::unique_ptr<Interface>()> &create)
    {
      return registry().add({name, description, declare, create});
    }



    void
    declare_parameters(ParameterHandler &prm)
    {
      // Linear slip weakening, the GeoFEM paper's law, is the default
      // (the registry's first name would be the alphabetical first).
      prm.declare_entry("Friction law",
                        "linear slip weakening",
                        Patterns::Selection(registry().selection()),
                        "The friction law of the fault. Available laws:" +
                          registry().descriptions());
      registry().declare_all(prm);
    }



    std::string
    laws_with_state_rate()
    {
      std::vector<std::string> names = registry().names();
      std::sort(names.begin(), names.end());
      std::string result;
      for (const auto &name : names)
        if (registry()
              .find(name, "Fault/Friction law")
              .create()
              ->has_state_rate())
          result += (result.empty() ? "" : ", ") + name;
      return result;
    }



    std::unique_ptr<Interface>
    create(ParameterHandler &prm)
    {
      const std::string name = prm.get("Friction law");
      auto law = registry().find(name, "Fault/Friction law").create();
      law->parse_parameters(prm);
      return law;
    }
  } // namespace Friction
} // namespace rupture
