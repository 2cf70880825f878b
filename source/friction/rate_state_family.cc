#include <rupture/base/utilities.h>
#include <rupture/friction/law_utilities.h>
#include <rupture/friction/rate_state_family.h>

#include <cmath>

namespace rupture
{
  namespace Friction
  {
    template <std::size_t n>
    RateStateFamily<n>::RateStateFamily(
      const std::string                  &section,
      const std::array<ConstantEntry, n> &entries,
      const unsigned int                  slip_scale_constant,
      const unsigned int                  drop_constant)
      : section(section)
      , constant_entries(entries)
      , slip_scale_index(slip_scale_constant)
      , drop_index(drop_constant)
    {}



    template <std::size_t n>
    std::unique_ptr<FunctionParser<3>>
    RateStateFamily<n>::parse_function(ParameterHandler  &prm,
                                       const std::string &entry) const
    {
      return Utilities::parse_function<3>(prm.get(entry),
                                          1,
                                          "Fault/" + section + "/" + entry,
                                          "x,y,z");
    }



    template <std::size_t n>
    void
    RateStateFamily<n>::parse_constants(ParameterHandler &prm)
    {
      for (std::size_t i = 0; i < n; ++i)
        functions[i] = parse_function(prm, constant_entries[i].name);
    }



    template <std::size_t n>
    void
    RateStateFamily<n>::require(const bool         ok,
                                const std::string &entry,
                                const double       value,
                                const Point<3>    &x,
                                const std::string &allowed) const
    {
      LawUtilities::require(ok, section, entry, value, x, allowed);
    }



    template <std::size_t n>
    typename RateStateFamily<n>::Constants
    RateStateFamily<n>::start_state(const Point<3> &x, State &state) const
    {
      state             = State();
      const Constants c = constants(x, state);
      for (std::size_t i = 0; i < n; ++i)
        {
          const double v = c[i];
          const bool   ok =
            std::isfinite(v) &&
            (constant_entries[i].range == Range::finite ||
             (constant_entries[i].range == Range::non_negative && v >= 0) ||
             (constant_entries[i].range == Range::positive && v > 0));
          require(
            ok, constant_entries[i].name, v, x, constant_entries[i].allowed);
        }
      state.parameters.assign(c.begin(), c.end());
      return c;
    }



    template <std::size_t n>
    typename RateStateFamily<n>::Constants
    RateStateFamily<n>::constants(const Point<3> &x, const State &state) const
    {
      return LawUtilities::constants(functions, x, state);
    }



    template <std::size_t n>
    void
    RateStateFamily<n>::check_state(const Point<3> &x, const State &state) const
    {
      AssertThrow(state.variables.size() == n_state_variables(),
                  ExcMessage("The friction law in <Fault/" + section +
                             "> was used at a point whose state was not "
                             "initialised" +
                             LawUtilities::at_point(x) + "."));
    }



    template <std::size_t n>
    double
    RateStateFamily<n>::coefficient(const Point<3> &x,
                                    const State    &old,
                                    const double    slip_increment,
                                    const double    dt,
                                    double         &derivative) const
    {
      const Constants c = constants(x, old);
      check_state(x, old);
      return LawUtilities::step_coefficient(
        slip_increment,
        dt,
        [&](const double V, double &ds_dV) {
          return evolve(c, old.variables, V, dt, ds_dV);
        },
        [&](const double V, const double s, double &dmu_dV, double &dmu_ds) {
          return friction(c, old.variables, V, s, dmu_dV, dmu_ds);
        },
        derivative);
    }



    template <std::size_t n>
    double
    RateStateFamily<n>::coefficient_at_rate(const Point<3> &x,
                                            const State    &state,
                                            const double    V,
                                            double         &derivative) const
    {
      const Constants c      = constants(x, state);
      double          unused = 0;
      check_state(x, state);
      return friction(c,
                      state.variables,
                      V,
                      friction_state(state.variables),
                      derivative,
                      unused);
    }



    template <std::size_t n>
    double
    RateStateFamily<n>::cohesion(const Point<3> &, const State &) const
    {
      return 0;
    }



    template <std::size_t n>
    void
    RateStateFamily<n>::update_state(const Point<3> &x,
                                     const State    &old,
                                     const double    slip_increment,
                                     const double    dt,
                                     const double    shear_traction,
                                     State          &updated) const
    {
      check_state(x, old);
      Interface::update_state(
        x, old, slip_increment, dt, shear_traction, updated);
      const Constants c = constants(x, old);
      evolve_state(x,
                   c,
                   old.variables,
                   LawUtilities::slip_rate(slip_increment, dt),
                   dt,
                   shear_traction,
                   updated.variables);
    }



    template <std::size_t n>
    void
    RateStateFamily<n>::evolve_state(const Point<3> &,
                                     const Constants           &c,
                                     const std::vector<double> &old,
                                     const double               V,
                                     const double               dt,
                                     const double,
                                     std::vector<double> &updated) const
    {
      AssertThrow(n_state_variables() == 1,
                  ExcMessage("The friction law in <Fault/" + section +
                             "> has several state variables but no "
                             "evolve_state() of its own."));
      double unused = 0;
      updated       = {evolve(c, old, V, dt, unused)};
    }



    template <std::size_t n>
    void
    RateStateFamily<n>::state_rate(const Point<3>      &x,
                                   const State         &state,
                                   const double         V,
                                   std::vector<double> &rates) const
    {
      check_state(x, state);
      state_rates(constants(x, state), state.variables, V, rates);
    }



    template <std::size_t n>
    void
    RateStateFamily<n>::relax_state(const Point<3> &x,
                                    State          &state,
                                    const double    heating,
                                    const double    dt) const
    {
      check_state(x, state);
      relax(constants(x, state), state.variables, heating, dt);
    }



    template <std::size_t n>
    void
    RateStateFamily<n>::relaxation_rate(const Point<3>      &x,
                                        const State         &state,
                                        const double         heating,
                                        std::vector<double> &rates) const
    {
      check_state(x, state);
      relaxation_rates(constants(x, state), state.variables, heating, rates);
    }



    template <std::size_t n>
    void
    RateStateFamily<n>::state_rates(const Constants &,
                                    const std::vector<double> &,
                                    const double,
                                    std::vector<double> &) const
    {
      AssertThrow(false,
                  ExcMessage("The friction law in <Fault/" + section +
                             "> gives no rate of change of its state (which "
                             "a method that integrates the state in time, "
                             "the boundary-integral method, needs)."));
    }



    template <std::size_t n>
    double
    RateStateFamily<n>::slip_scale(const Point<3> &x, const State &state) const
    {
      return constants(x, state)[slip_scale_index];
    }



    template <std::size_t n>
    double
    RateStateFamily<n>::process_zone_width(const Point<3> &x,
                                           const State    &state,
                                           const double    pressure,
                                           const double    shear_modulus) const
    {
      const Constants c = constants(x, state);
      return LawUtilities::process_zone_at_rest(shear_modulus,
                                                c[slip_scale_index],
                                                c[drop_index],
                                                pressure);
    }



    // (The header declares these extern.)
    template class RateStateFamily<5>;
    template class RateStateFamily<7>;
    template class RateStateFamily<8>;
    template class RateStateFamily<11>;
  } // namespace Friction
} // namespace rupture
