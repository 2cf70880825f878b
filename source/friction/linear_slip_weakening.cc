#include <rupture/base/utilities.h>
#include <rupture/friction/linear_slip_weakening.h>

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
        cohesion_function = Utilities::parse_function<3>(prm.get("Cohesion"),
                                                         1,
                                                         s + "Cohesion",
                                                         "x,y,z");
      }
      prm.leave_subsection();
    }



    void
    LinearSlipWeakening::initialize_state(const Point<3> &x, State &state) const
    {
      state              = State();
      const double mu0   = static_coefficient->value(x);
      const double mud   = dynamic_coefficient->value(x);
      const double ld    = weakening_distance->value(x);
      const double c     = cohesion_function->value(x);
      const auto   where = [&]() {
        std::ostringstream s;
        s << " at the fault point (" << x << ")";
        return s.str();
      };
      AssertThrow(std::isfinite(mu0) && std::isfinite(mud) && mud >= 0 &&
                    mu0 >= mud,
                  ExcMessage("<Fault/Linear slip weakening>: mu_0 = " +
                             std::to_string(mu0) +
                             " and mu_d = " + std::to_string(mud) + where() +
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
    }



    double
    LinearSlipWeakening::coefficient(const Point<3> &x,
                                     const State    &old,
                                     const double    slip_increment,
                                     const double,
                                     double &derivative) const
    {
      const double mu0 = static_coefficient->value(x);
      const double mud = dynamic_coefficient->value(x);
      const double ld  = weakening_distance->value(x);
      const double s   = old.slip_path + slip_increment;
      if (s < ld)
        {
          derivative = -(mu0 - mud) / ld;
          return mu0 - (mu0 - mud) * s / ld;
        }
      derivative = 0;
      return mud;
    }



    double
    LinearSlipWeakening::cohesion(const Point<3> &x) const
    {
      return cohesion_function->value(x);
    }

    RUPTURE_REGISTER_FRICTION_LAW(
      LinearSlipWeakening,
      "linear slip weakening",
      "mu falls linearly from mu_0 to mu_d over the slip path length L_d "
      "(the GeoFEM paper's eq. 2).")
  } // namespace Friction
} // namespace rupture
