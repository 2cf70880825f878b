#include <rupture/base/utilities.h>
#include <rupture/friction/law_utilities.h>
#include <rupture/friction/linear_slip_weakening.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rupture
{
  namespace Friction
  {
    void
    LinearSlipWeakening::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear slip weakening");
      {
        prm.declare_entry("Static friction coefficient",
                          "0.6",
                          Patterns::Anything(),
                          "mu_0, the friction coefficient before slip, as a "
                          "function of the position x, y, z (m; in 2-D z = "
                          "0), e.g. '0.606' or "
                          "'(abs(x) < 15000) ? 0.677 : 10000'. >= mu_d.");
        prm.declare_entry("Dynamic friction coefficient",
                          "0.6",
                          Patterns::Anything(),
                          "mu_d, the friction coefficient after a slip path "
                          "of L_d, as a function of x, y, z. >= 0.");
        prm.declare_entry("Slip-weakening distance",
                          "1",
                          Patterns::Anything(),
                          "L_d (m), the slip path length over which mu falls "
                          "from mu_0 to mu_d, as a function of x, y, z. > 0.");
        prm.declare_entry("Cohesion",
                          "0",
                          Patterns::Anything(),
                          "Cohesion (Pa) added to the frictional strength, "
                          "as a function of x, y, z. >= 0.");
        prm.declare_entry(
          "Forced weakening region",
          "0",
          Patterns::Anything(),
          "Where mu is also forced down in time to nucleate a rupture (a "
          "function of x, y, z, nonzero inside), e.g. the paper's 20 km x 5 "
          "km weak patch. 0 for none.");
        prm.declare_entry("Forced weakening time",
                          "0.1",
                          Patterns::Double(0),
                          "Time (s) over which mu falls from mu_0 to mu_d "
                          "in the forced-weakening region, counted from the "
                          "start of the dynamic phase. > 0.");
      }
      prm.leave_subsection();
    }



    void
    LinearSlipWeakening::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear slip weakening");
      {
        const std::string s = "Fault/Linear slip weakening/";
        static_coefficient =
          Utilities::parse_function<3>(prm.get("Static friction coefficient"),
                                       1,
                                       s + "Static friction coefficient",
                                       "x,y,z");
        dynamic_coefficient =
          Utilities::parse_function<3>(prm.get("Dynamic friction coefficient"),
                                       1,
                                       s + "Dynamic friction coefficient",
                                       "x,y,z");
        weakening_distance =
          Utilities::parse_function<3>(prm.get("Slip-weakening distance"),
                                       1,
                                       s + "Slip-weakening distance",
                                       "x,y,z");
        forced_region =
          Utilities::parse_function<3>(prm.get("Forced weakening region"),
                                       1,
                                       s + "Forced weakening region",
                                       "x,y,z");
        forced_time = prm.get_double("Forced weakening time");
        AssertThrow(forced_time > 0,
                    ExcMessage("<Fault/Linear slip weakening/Forced weakening "
                               "time> must be > 0 (s)."));
        cohesion_function = Utilities::parse_function<3>(prm.get("Cohesion"),
                                                         1,
                                                         s + "Cohesion",
                                                         "x,y,z");
      }
      prm.leave_subsection();
    }



    std::array<double, 5>
    LinearSlipWeakening::point_parameters(const Point<3> &x,
                                          const State    &state) const
    {
      if (state.parameters.size() == 5)
        return {state.parameters[0],
                state.parameters[1],
                state.parameters[2],
                state.parameters[3],
                state.parameters[4]};
      return {static_coefficient->value(x),
              dynamic_coefficient->value(x),
              weakening_distance->value(x),
              cohesion_function->value(x),
              forced_region->value(x) != 0 ? 1. : 0.};
    }



    void
    LinearSlipWeakening::initialize_state(const Point<3> &x,
                                          const double,
                                          State &state) const
    {
      state                           = State();
      const auto [mu0, mud, ld, c, f] = point_parameters(x, state);
      const auto where                = [&]() {
        std::ostringstream s;
        s << " at the fault point (" << x << ")";
        return s.str();
      };
      AssertThrow(std::isfinite(mu0) && std::isfinite(mud) && mud >= 0 &&
                    mu0 >= mud,
                  ExcMessage("<Fault/Linear slip weakening/Static friction "
                             "coefficient> gives mu_0 = " +
                             std::to_string(mu0) +
                             " and <Fault/Linear slip weakening/Dynamic "
                             "friction coefficient> mu_d = " +
                             std::to_string(mud) + where() +
                             ", but 0 <= mu_d <= mu_0 is required."));
      AssertThrow(std::isfinite(ld) && ld > 0,
                  ExcMessage("<Fault/Linear slip weakening/Slip-weakening "
                             "distance> is " +
                             std::to_string(ld) + where() +
                             ", but it must be > 0 (m)."));
      AssertThrow(std::isfinite(c) && c >= 0,
                  ExcMessage("<Fault/Linear slip weakening/Cohesion> is " +
                             std::to_string(c) + where() +
                             ", but it must be >= 0 (Pa)."));
      // The law's functions of position are evaluated once per point: a
      // parsed expression costs far more than the rest of a node's step.
      state.parameters = {mu0, mud, ld, c, f};
    }



    double
    LinearSlipWeakening::coefficient(const Point<3> &x,
                                     const State    &old,
                                     const double    slip_increment,
                                     const double,
                                     double &derivative) const
    {
      const auto [mu0, mud, ld, c, forced_point] = point_parameters(x, old);
      (void)c;
      const double s  = old.slip_path + slip_increment;
      double       mu = mud;
      derivative      = 0;
      if (!weakening_enabled)
        return mu0;
      if (s < ld)
        {
          derivative = -(mu0 - mud) / ld;
          mu         = mu0 - (mu0 - mud) * s / ld;
        }
      if (forced_point != 0)
        {
          const double w =
            std::clamp((current_time - dynamic_start) / forced_time, 0., 1.);
          const double forced = mu0 - (mu0 - mud) * w;
          if (forced < mu)
            {
              derivative = 0;
              mu         = forced;
            }
        }
      return mu;
    }



    void
    LinearSlipWeakening::set_time(const double time)
    {
      current_time = time;
    }



    void
    LinearSlipWeakening::start_dynamic_phase(const double time)
    {
      dynamic_start = time;
    }



    void
    LinearSlipWeakening::enable_weakening(const bool enable)
    {
      weakening_enabled = enable;
    }



    bool
    LinearSlipWeakening::can_weaken(const Point<3> &x, const State &state) const
    {
      const auto p = point_parameters(x, state);
      return p[0] > p[1] && state.slip_path < p[2];
    }



    double
    LinearSlipWeakening::process_zone_width(const Point<3> &x,
                                            const State    &state,
                                            const double    pressure,
                                            const double    shear_modulus) const
    {
      const auto [mu0, mud, ld, c, f] = point_parameters(x, state);
      (void)c;
      (void)f;
      return LawUtilities::process_zone_at_rest(shear_modulus,
                                                ld,
                                                mu0 - mud,
                                                pressure);
    }



    double
    LinearSlipWeakening::cohesion(const Point<3> &x, const State &state) const
    {
      return point_parameters(x, state)[3];
    }

    RUPTURE_REGISTER_FRICTION_LAW(
      LinearSlipWeakening,
      "linear slip weakening",
      "mu falls linearly from mu_0 to mu_d over the slip path length L_d "
      "(the GeoFEM paper's eq. 2).")
  } // namespace Friction
} // namespace rupture
