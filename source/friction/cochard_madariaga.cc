#include <rupture/base/utilities.h>
#include <rupture/friction/cochard_madariaga.h>
#include <rupture/friction/law_utilities.h>

#include <cmath>
#include <sstream>

namespace rupture
{
  namespace Friction
  {
    namespace
    {
      const std::array<const char *, 3> names = {"Maximum traction drop",
                                                 "Reference slip rate",
                                                 "Residual strength"};
    } // namespace



    void
    CochardMadariaga::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Cochard Madariaga");
      {
        prm.declare_entry(names[0],
                          "1e7",
                          Patterns::Anything(),
                          "sigma_0 (Pa), the strength lost between rest and "
                          "very fast slip, as a function of x, y, z (m; in "
                          "2-D z = 0). > 0.");
        prm.declare_entry(names[1],
                          "1",
                          Patterns::Anything(),
                          "V0 (m/s): at the slip rate V0 half of sigma_0 is "
                          "lost. A function of x, y, z. > 0.");
        prm.declare_entry(names[2],
                          "0",
                          Patterns::Anything(),
                          "tau_r (Pa), the strength at very fast slip, as a "
                          "function of x, y, z. >= 0.");
      }
      prm.leave_subsection();
    }



    void
    CochardMadariaga::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Cochard Madariaga");
      for (unsigned int i = 0; i < 3; ++i)
        functions[i] =
          Utilities::parse_function<3>(prm.get(names[i]),
                                       1,
                                       std::string("Fault/Cochard Madariaga/") +
                                         names[i],
                                       "x,y,z");
      prm.leave_subsection();
    }



    void
    CochardMadariaga::initialize_state(const Point<3> &x,
                                       const double,
                                       State &state) const
    {
      state             = State();
      const Constants c = LawUtilities::constants(functions, x, state);
      const auto      require =
        [&](const bool ok, const unsigned int i, const std::string &allowed) {
          LawUtilities::require(
            ok, "Cochard Madariaga", names[i], c[i], x, allowed);
        };
      require(std::isfinite(c[0]) && c[0] > 0, 0, "> 0 (Pa)");
      require(std::isfinite(c[1]) && c[1] > 0, 1, "> 0 (m/s)");
      require(std::isfinite(c[2]) && c[2] >= 0, 2, ">= 0 (Pa)");
      state.parameters.assign(c.begin(), c.end());
    }



    double
    CochardMadariaga::strength_of_rate(const Constants &c,
                                       const double     V,
                                       double          &derivative)
    {
      const auto [sigma, V0, tau_r] = c;
      const double v                = std::max(V, 0.);
      const double w                = V0 / (V0 + v);
      derivative                    = -sigma * w * w / V0;
      return tau_r + sigma * w;
    }



    double
    CochardMadariaga::coefficient(const Point<3> &,
                                  const State &,
                                  const double,
                                  const double,
                                  double &derivative) const
    {
      derivative = 0;
      return 0;
    }



    double
    CochardMadariaga::cohesion(const Point<3> &x, const State &state) const
    {
      double unused = 0;
      return strength_of_rate(LawUtilities::constants(functions, x, state),
                              state.slip_rate,
                              unused);
    }



    double
    CochardMadariaga::strength(const Point<3> &x,
                               const State    &old,
                               const double    slip_increment,
                               const double    dt,
                               const double,
                               double &derivative_increment,
                               double &derivative_pressure) const
    {
      const Constants c  = LawUtilities::constants(functions, x, old);
      double          dS = 0;
      const double    S =
        strength_of_rate(c, LawUtilities::slip_rate(slip_increment, dt), dS);
      derivative_increment = (dt > 0) ? dS / dt : 0.;
      derivative_pressure  = 0;
      return S;
    }



    double
    CochardMadariaga::strength_at_rate(const Point<3> &x,
                                       const State    &state,
                                       const double    V,
                                       const double,
                                       double &derivative_rate,
                                       double &derivative_pressure) const
    {
      const Constants c   = LawUtilities::constants(functions, x, state);
      derivative_pressure = 0;
      return strength_of_rate(c, std::max(V, 0.), derivative_rate);
    }



    void
    CochardMadariaga::check_uniqueness(const Point<3> &x,
                                       const State    &old,
                                       const double,
                                       const double impedance) const
    {
      const Constants c = LawUtilities::constants(functions, x, old);
      if (c[0] / c[1] < impedance)
        return;
      std::ostringstream message;
      message << "Cochard-Madariaga friction" << LawUtilities::at_point(x)
              << " has no unique slip rate: its strength falls with the slip "
                 "rate at up to sigma_0 / V0 = "
              << c[0] / c[1] << " Pa s/m (<Fault/Cochard Madariaga/" << names[0]
              << "> = " << c[0] << " Pa, <" << names[1] << "> = " << c[1]
              << " m/s), but the node's impedance, the traction change per "
                 "unit slip rate, is only Z = "
              << impedance
              << " Pa s/m. It must be sigma_0 / V0 < Z: raise V0 or lower "
                 "sigma_0, or raise Z by refining the mesh or shortening the "
                 "time step (Z grows as 1/dt; with penalty contact Z = "
                 "penalty * dt, so there a larger time step or penalty).";
      AssertThrow(false, ExcMessage(message.str()));
    }

    RUPTURE_REGISTER_FRICTION_LAW(
      CochardMadariaga,
      "cochard madariaga",
      "Cochard and Madariaga's rate weakening (the review's eq. 5.9): a "
      "strength tau_r + sigma_0 V0 / (V0 + V) that does not depend on the "
      "normal traction.")
  } // namespace Friction
} // namespace rupture
