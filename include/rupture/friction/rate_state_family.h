#ifndef rupture_friction_rate_state_family_h
#define rupture_friction_rate_state_family_h

#include <rupture/friction/interface.h>

#include <deal.II/base/function_parser.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace rupture
{
  namespace Friction
  {
    /**
     * The base of the rate-and-state family (rate and state, the slowness
     * law, flash heating, two state variables, Chester): what those laws
     * share is written here once, in the slip rate V, and a law provides
     * only its own physics at a point:
     *
     * - friction_state(): the number s through which its state enters the
     *   friction coefficient (theta, psi, the sum of two states);
     * - evolve(): s after a step dt at the constant slip rate V, and
     *   ds/dV;
     * - friction(): mu(V, s) and its partial derivatives;
     * - evolve_state(): all state variables after the step (by default the
     *   one variable evolve() gives);
     * - state_rates(): the rates of change of its state variables at V, for
     *   the methods that integrate the state as an ordinary differential
     *   equation (laws that give them say so in has_state_rate());
     * - initialize_state(): its initial state, after start_state() has
     *   checked and cached the constants.
     *
     * From these the base makes the Interface: the coefficient of a step,
     * mu(V, s_new(V)) with V = slip increment / dt, and its derivative with
     * respect to the slip increment (the consistent tangent), the
     * coefficient at a rate with the state held (the split nodes), the
     * state after a step, the slip scale and the process-zone estimate from
     * two of the constants, no cohesion.
     *
     * The law's constants (@p n of them) are functions of position in the
     * law's subsection, parsed by parse_constants(), checked against their
     * ranges and cached in State::parameters by start_state().
     */
    template <std::size_t n>
    class RateStateFamily : public Interface
    {
    public:
      using Constants = std::array<double, n>;

      /**
       * What a constant may be: a finite number, >= 0 or > 0.
       */
      enum class Range
      {
        finite,
        non_negative,
        positive
      };

      /**
       * A constant of the law: its entry in the law's subsection, its range
       * and how a message names the allowed values ("> 0 (m)").
       */
      struct ConstantEntry
      {
        const char *name;
        Range       range;
        const char *allowed;
      };

      /**
       * The law with the subsection @p section ("Rate and state") and the
       * constants @p entries; constant @p slip_scale_constant is the slip
       * over which the state evolves and @p drop_constant the strength drop
       * per unit pressure over it (for the process-zone width).
       */
      RateStateFamily(const std::string                  &section,
                      const std::array<ConstantEntry, n> &entries,
                      const unsigned int                  slip_scale_constant,
                      const unsigned int                  drop_constant);

      double
      coefficient(const Point<3> &x,
                  const State    &old,
                  const double    slip_increment,
                  const double    dt,
                  double         &derivative) const final;

      double
      coefficient_at_rate(const Point<3> &x,
                          const State    &state,
                          const double    V,
                          double         &derivative) const final;

      double
      cohesion(const Point<3> &x, const State &state) const final;

      void
      update_state(const Point<3> &x,
                   const State    &old,
                   const double    slip_increment,
                   const double    dt,
                   const double    shear_traction,
                   State          &updated) const final;

      void
      state_rate(const Point<3>      &x,
                 const State         &state,
                 const double         V,
                 std::vector<double> &rates) const final;

      void
      relax_state(const Point<3> &x,
                  State          &state,
                  const double    heating,
                  const double    dt) const final;

      void
      relaxation_rate(const Point<3>      &x,
                      const State         &state,
                      const double         heating,
                      std::vector<double> &rates) const final;

      double
      slip_scale(const Point<3> &x, const State &state) const override;

      double
      process_zone_width(const Point<3> &x,
                         const State    &state,
                         const double    pressure,
                         const double    shear_modulus) const override;

      bool
      has_process_zone_width() const final
      {
        return true;
      }

      bool
      depends_on_slip_rate() const final
      {
        return true;
      }

      // The law's physics at a point of constants c, in the slip rate V.

      /**
       * The number through which the state variables enter the friction.
       */
      virtual double
      friction_state(const std::vector<double> &variables) const = 0;

      /**
       * friction_state() after a step of length @p dt at the constant slip
       * rate @p V from the state @p variables, and its derivative with
       * respect to V in @p ds_dV.
       */
      virtual double
      evolve(const Constants           &c,
             const std::vector<double> &variables,
             const double               V,
             const double               dt,
             double                    &ds_dV) const = 0;

      /**
       * The friction coefficient mu(V, s) (the other state variables, such
       * as a temperature, from @p variables) and its partial derivatives.
       */
      virtual double
      friction(const Constants           &c,
               const std::vector<double> &variables,
               const double               V,
               const double               s,
               double                    &dmu_dV,
               double                    &dmu_ds) const = 0;

      /**
       * All state variables after a step of length @p dt at the slip rate
       * @p V from @p old, in which the fault carried @p shear_traction (Pa).
       * The default is the one variable evolve() gives.
       */
      virtual void
      evolve_state(const Point<3>            &x,
                   const Constants           &c,
                   const std::vector<double> &old,
                   const double               V,
                   const double               dt,
                   const double               shear_traction,
                   std::vector<double>       &updated) const;

      /**
       * The rates of change of the state variables @p variables at the slip
       * rate @p V (laws with has_state_rate() override it; the default
       * throws).
       */
      virtual void
      state_rates(const Constants           &c,
                  const std::vector<double> &variables,
                  const double               V,
                  std::vector<double>       &rates) const;

      /**
       * Advance the variables of @p variables that relax (state_relaxes())
       * over @p dt under the heating @p heating (W/m^2), exactly (laws
       * with such variables override it; the default has none).
       */
      virtual void
      relax(const Constants     &c,
            std::vector<double> &variables,
            const double         heating,
            const double         dt) const
      {
        (void)c;
        (void)variables;
        (void)heating;
        (void)dt;
      }

      /**
       * The rates of change of the variables that relax under the heating
       * @p heating (0 for the others; the default has none).
       */
      virtual void
      relaxation_rates(const Constants           &c,
                       const std::vector<double> &variables,
                       const double               heating,
                       std::vector<double>       &rates) const
      {
        (void)c;
        (void)heating;
        rates.assign(variables.size(), 0.);
      }

      /**
       * The number of state variables (1 unless a law says otherwise).
       */
      virtual unsigned int
      n_state_variables() const
      {
        return 1;
      }

    protected:
      /**
       * Read the constants' functions of position (the caller is inside the
       * law's subsection).
       */
      void
      parse_constants(ParameterHandler &prm);

      /**
       * The function of position in entry @p entry of the law's subsection.
       */
      std::unique_ptr<FunctionParser<3>>
      parse_function(ParameterHandler &prm, const std::string &entry) const;

      /**
       * Start initialize_state(): reset @p state, check the constants at
       * @p x against their ranges (a message naming the entry and the point
       * otherwise), cache them in @p state.parameters and return them.
       */
      Constants
      start_state(const Point<3> &x, State &state) const;

      /**
       * The constants at @p x (cached in the state, else evaluated).
       */
      Constants
      constants(const Point<3> &x, const State &state) const;

      /**
       * Throw unless @p state holds the law's state variables (it was
       * initialised).
       */
      void
      check_state(const Point<3> &x, const State &state) const;

      /**
       * LawUtilities::require() in the law's subsection.
       */
      void
      require(const bool         ok,
              const std::string &entry,
              const double       value,
              const Point<3>    &x,
              const std::string &allowed) const;

      /// The law's subsection.
      const std::string section;

    private:
      const std::array<ConstantEntry, n>                constant_entries;
      const unsigned int                                slip_scale_index;
      const unsigned int                                drop_index;
      std::array<std::unique_ptr<FunctionParser<3>>, n> functions;
    };

    // The laws' numbers of constants (instantiated in
    // rate_state_family.cc): a law with another number adds its own.
    extern template class RateStateFamily<5>;
    extern template class RateStateFamily<7>;
    extern template class RateStateFamily<8>;
    extern template class RateStateFamily<11>;
  } // namespace Friction
} // namespace rupture

#endif
