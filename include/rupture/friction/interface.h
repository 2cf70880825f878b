#ifndef rupture_friction_interface_h
#define rupture_friction_interface_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace rupture
{
  using namespace dealii;

  /**
   * Friction laws. A law is pointwise physics: it sees the position, the
   * state of a fault point at the start of a step and the slip it makes in
   * the step, never a mesh, a vector or MPI, so a small test can exercise
   * it fully. The contact algorithm asks it for the friction coefficient
   * as a function of the slip increment of the step, which covers slip
   * weakening (mu of the slip path) and rate-and-state laws (mu of the slip
   * rate increment / dt and of the state variables evolved over the step).
   */
  namespace Friction
  {
    /**
     * What a fault point remembers between steps.
     */
    struct State
    {
      /// Accumulated length of the slip path (m): the paper's |u_t^p|.
      double slip_path = 0;
      /// Magnitude of the slip rate over the last step (m/s).
      double slip_rate = 0;
      /// State variables of rate-and-state laws (theta, ...), in the units
      /// the law documents.
      std::vector<double> variables;
      /// Constants of the law at this point, evaluated once from its
      /// functions of position by initialize_state(), so that a step does
      /// not evaluate them again (the law documents which).
      std::vector<double> parameters;
    };

    class Interface
    {
    public:
      virtual ~Interface() = default;

      virtual void
      parse_parameters(ParameterHandler &prm) = 0;

      /**
       * Set up the state variables of a point at the start of a run.
       * @p initial_friction is the ratio |tau_0| / |sigma_0| of the fault's
       * initial shear and normal traction there (NaN where the fault is not
       * in compression), for laws whose initial state is defined by it.
       */
      virtual void
      initialize_state(const Point<3> &x,
                       const double    initial_friction,
                       State          &state) const;

      /**
       * The same without an initial traction (laws that need one throw).
       */
      void
      initialize_state(const Point<3> &x, State &state) const
      {
        initialize_state(x, std::numeric_limits<double>::quiet_NaN(), state);
      }

      /**
       * The friction coefficient after a slip increment @p slip_increment
       * (>= 0, m) in a step of length @p dt from the state @p old, and its
       * derivative with respect to the slip increment (1/m).
       */
      virtual double
      coefficient(const Point<3> &x,
                  const State    &old,
                  const double    slip_increment,
                  const double    dt,
                  double         &derivative) const = 0;

      /**
       * The cohesion (Pa) at @p x: strength = mu |sigma_n| + cohesion.
       */
      virtual double
      cohesion(const Point<3> &x, const State &state) const = 0;

      /**
       * The shear strength (Pa) of a point pressed by the compressive normal
       * traction @p pressure (>= 0, Pa) after a slip increment
       * @p slip_increment in a step @p dt from the state @p old, and its
       * derivatives with respect to the slip increment (Pa/m) and to the
       * pressure. The default is the law's friction coefficient times the
       * pressure plus the cohesion; a law whose strength is not of that
       * form (Cochard-Madariaga rate weakening, which does not depend on
       * the normal traction) overrides it.
       */
      virtual double
      strength(const Point<3> &x,
               const State    &old,
               const double    slip_increment,
               const double    dt,
               const double    pressure,
               double         &derivative_increment,
               double         &derivative_pressure) const;

      /**
       * The friction coefficient at the slip rate @p V (>= 0, m/s) with the
       * state variables of @p state as they are (not evolved over a step),
       * and its derivative with respect to V (s/m). The split-node method
       * of the explicit scheme evaluates friction this way at the time of
       * the traction, with the state evolved up to that time by
       * update_state() (second order in time). Laws of the slip rate
       * override it; the default, for laws of the slip path, is their
       * coefficient without further slip.
       */
      virtual double
      coefficient_at_rate(const Point<3> &x,
                          const State    &state,
                          const double    V,
                          double         &derivative) const;

      /**
       * The shear strength (Pa) at the slip rate @p V with the state held
       * as it is, pressed by @p pressure (>= 0, Pa), and its derivatives
       * with respect to V (Pa s/m) and to the pressure: the
       * coefficient_at_rate() times the pressure plus the cohesion, unless
       * a law overrides it (as strength()).
       */
      virtual double
      strength_at_rate(const Point<3> &x,
                       const State    &state,
                       const double    V,
                       const double    pressure,
                       double         &derivative_rate,
                       double         &derivative_pressure) const;

      /**
       * Whether update_state() uses the shear traction (laws with
       * frictional heating): the time-centred split-node update then
       * corrects the state with the mean traction over the step.
       */
      virtual bool
      state_depends_on_traction() const
      {
        return false;
      }

      /**
       * A step's slip rate V solves
       *   |T_stick| - Z V = strength(V dt),
       * with Z (Pa s/m) the impedance of the node. It has one solution only
       * while Z exceeds the law's fastest weakening, max(-d strength/dV).
       * Laws that know that bound check it here and throw, naming the point,
       * the parameters and what to change; the default checks nothing (the
       * fault still diagnoses a root at which the strength falls faster
       * than Z).
       */
      virtual void
      check_uniqueness(const Point<3> &x,
                       const State    &old,
                       const double    pressure,
                       const double    impedance) const;

      /**
       * The state after the step, in which the fault carried the shear
       * traction @p shear_traction (Pa, magnitude) over the slip increment:
       * laws whose state follows the frictional heating use it.
       */
      virtual void
      update_state(const Point<3> &x,
                   const State    &old,
                   const double    slip_increment,
                   const double    dt,
                   const double    shear_traction,
                   State          &updated) const;

      /**
       * The load sequence's clock and phase, for the laws that depend on
       * them (linear slip weakening's forced nucleation and its bonded
       * zones); the others ignore them. set_time(): the time (s) at the end
       * of the step being solved; start_dynamic_phase(): the time at which
       * the dynamic phase starts (0 without a loading phase);
       * enable_weakening(): switch weakening off (during a quasi-static
       * loading phase, when bonded zones hold up to their static strength)
       * or on.
       */
      virtual void
      set_time(const double time);

      virtual void
      start_dynamic_phase(const double time);

      virtual void
      enable_weakening(const bool enable);

      /**
       * Names of the state variables the fault surface output shows (one
       * field each, e.g. "log10_theta"); none for laws without state.
       */
      virtual std::vector<std::string>
      state_names() const
      {
        return {};
      }

      /**
       * The values of those fields for @p state.
       */
      virtual std::vector<double>
      state_output(const State &) const
      {
        return {};
      }

      /**
       * Whether state variable @p i interpolates in its logarithm when the
       * fault's state moves to new nodes of a changed mesh
       * (Fault::interpolate_new_pairs()): true for positive variables that
       * span decades (the theta of the aging and slip laws), false for
       * those that interpolate as they are (psi, temperatures, additive
       * states).
       */
      virtual bool
      state_interpolates_in_logarithm(const unsigned int i) const
      {
        (void)i;
        return false;
      }

      /**
       * Whether the friction coefficient depends on the slip rate (the slip
       * increment over dt) and not only on the slip path: rate-and-state
       * laws.
       */
      virtual bool
      depends_on_slip_rate() const
      {
        return false;
      }

      /**
       * The width (m) of the process zone (the cohesive zone behind a
       * rupture front, where the strength falls from its peak to its
       * residual value) at @p x, for a front that has not yet accelerated,
       * on a fault pressed by @p pressure (>= 0, Pa) in a medium of shear
       * modulus @p shear_modulus (Pa): (9 pi / 32) mu d / Delta, with the
       * law's slip scale d (slip-weakening distance, state evolution
       * distance) and its strength drop over it per unit pressure Delta
       * (mu_s - mu_d, the state coefficient b). A moving front shrinks it.
       * Infinite where the law does not weaken (or there is no pressure);
       * NaN for laws that give no estimate (has_process_zone_width()).
       */
      virtual double
      process_zone_width(const Point<3> &x,
                         const State    &state,
                         const double    pressure,
                         const double    shear_modulus) const;

      /**
       * The slip (m) over which the law's state evolves at @p x (the
       * characteristic slip distance L of rate and state, the shorter of
       * two), NaN for laws without an evolving state. L / V is the time over
       * which a fault slipping at V forgets its state: the rate-and-state
       * step controller takes a fraction of it.
       */
      virtual double
      slip_scale(const Point<3> &x, const State &state) const;

      /**
       * Whether the law gives the rates of change of its state variables
       * (state_rate()): what a method that integrates the fault's state as
       * an ordinary differential equation needs (the boundary-integral
       * method).
       */
      virtual bool
      has_state_rate() const
      {
        return false;
      }

      /**
       * The rates of change d(state variable)/dt of the state variables of
       * @p state at the slip rate @p V (>= 0, m/s), one per variable, in
       * @p rates. Laws without has_state_rate() throw.
       */
      virtual void
      state_rate(const Point<3>      &x,
                 const State         &state,
                 const double         V,
                 std::vector<double> &rates) const;

      /**
       * Whether state variable @p v relaxes by itself over a time of its
       * own towards a value set by the frictional heating (Chester's
       * temperature): stiff for an explicit integrator over years of
       * loading, so state_rate() gives 0 for it and relax_state() advances
       * it exactly over a step, with the heating held.
       */
      virtual bool
      state_relaxes(const unsigned int v) const
      {
        (void)v;
        return false;
      }

      /**
       * Advance the variables of @p state that relax (state_relaxes())
       * over @p dt under the frictional heating @p heating (the shear
       * traction times the slip rate, W/m^2, held over the step), exactly;
       * the others stay. Nothing for laws without such variables.
       */
      virtual void
      relax_state(const Point<3> &x,
                  State          &state,
                  const double    heating,
                  const double    dt) const
      {
        (void)x;
        (void)state;
        (void)heating;
        (void)dt;
      }

      /**
       * The rates of change of the variables of @p state that relax
       * (state_relaxes()) under the heating @p heating (W/m^2), one per
       * state variable in @p rates (0 for the others): an integrator holds
       * them over a step, so that the other variables see the relaxing
       * ones change linearly through it.
       */
      virtual void
      relaxation_rate(const Point<3>      &x,
                      const State         &state,
                      const double         heating,
                      std::vector<double> &rates) const
      {
        (void)x;
        (void)heating;
        rates.assign(state.variables.size(), 0.);
      }

      /**
       * Whether process_zone_width() gives an estimate: a mesh that
       * refines to the process zone needs it.
       */
      virtual bool
      has_process_zone_width() const
      {
        return false;
      }

      /**
       * Whether the friction at @p x can still weaken from @p state (a
       * bonded zone): slipping there ends a loading phase.
       */
      virtual bool
      can_weaken(const Point<3> &x, const State &state) const;
    };

    /**
     * Register a law. Use RUPTURE_REGISTER_FRICTION_LAW.
     */
    bool
    register_law(const std::string                                 &name,
                 const std::string                                 &description,
                 const std::function<void(ParameterHandler &)>     &declare,
                 const std::function<std::unique_ptr<Interface>()> &create);

    /**
     * Declare "Fault/Friction law" and the subsections of all laws.
     */
    void
    declare_parameters(ParameterHandler &prm);

    /**
     * The names of the laws that give the rates of change of their state
     * (Interface::has_state_rate()), in alphabetical order and separated by
     * commas: what a method that integrates the state allows.
     */
    std::string
    laws_with_state_rate();

    /**
     * Create and parse the law named in "Fault/Friction law" (the caller
     * is inside the "Fault" subsection).
     */
    std::unique_ptr<Interface>
    create(ParameterHandler &prm);
  } // namespace Friction
} // namespace rupture

#define RUPTURE_REGISTER_FRICTION_LAW(classname, name, description)            \
  namespace                                                                    \
  {                                                                            \
    const bool dummy_friction_##classname = ::rupture::Friction::register_law( \
      name,                                                                    \
      description,                                                             \
      &classname::declare_parameters,                                          \
      []() {                                                                   \
        return std::unique_ptr<::rupture::Friction::Interface>(                \
          new classname());                                                    \
      });                                                                      \
  }

#endif
