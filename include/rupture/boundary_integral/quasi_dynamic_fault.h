#ifndef rupture_boundary_integral_quasi_dynamic_fault_h
#define rupture_boundary_integral_quasi_dynamic_fault_h

#include <rupture/boundary_integral/stiffness.h>
#include <rupture/fault/event_source.h>
#include <rupture/friction/interface.h>

#include <deal.II/base/mpi.h>

#include <iosfwd>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace rupture
{
  namespace BoundaryIntegral
  {
    /**
     * The fault of the boundary-integral method as a system of ordinary
     * differential equations: the slip s_i and the friction law's state of
     * every element evolve with
     *   ds_i/dt = V_i,   d(state_i)/dt = the law's state rate at V_i,
     * where the slip rate V_i >= 0 solves, point by point, the balance of
     * the elastic traction and the strength with radiation damping eta
     * (the quasi-dynamic approximation of inertia),
     *   tau_i - eta V_i = S_i(V_i, state_i),
     *   tau_i = tau0_i + sum_j K_ij (s_j - V_p t)
     * (a Stiffness: AntiplaneHalfSpace), S the law's strength at the rate with
     * the state held (Friction::Interface::strength_at_rate) under the
     * normal stress sigma_i = sigma0_i + sum_j N_ij (s_j - V_p t), N the
     * body's normal stiffness (Stiffness::normal_rows(); none in the
     * antiplane problem: sigma_i = sigma0_i). The law sees the element as
     * its position (x, y, 0) (Stiffness::position(): (0, -depth, 0) on a
     * vertical fault): its functions of position are written in x and y.
     *
     * The unknowns are one vector y: the N slips, then the N values of
     * each state variable (in its logarithm where the law says the
     * variable spans decades, Friction::Interface::
     * state_interpolates_in_logarithm()). Each rank computes the rows of K
     * it owns and the ranks exchange their rates, so every rank holds all
     * of y and takes the same steps.
     *
     * It is also the event catalogue's source (the slip at an event's
     * start, the peak slip rates, the moment per unit length).
     */
    class QuasiDynamicFault : public Fault::EventSource<2>
    {
    public:
      /**
       * The fault of @p geometry with the friction law @p law at the
       * normal stress @p normal_stress (Pa, compressive > 0) and the initial
       * shear traction @p initial_shear (Pa) per element; radiation damping
       * @p damping (Pa s/m) and the plate rate @p plate_rate (m/s), at
       * which the law's initial state is found from tau0 - eta V_p (laws
       * whose initial state follows from the traction).
       */
      QuasiDynamicFault(const Stiffness           &geometry,
                        const Friction::Interface &law,
                        const std::vector<double> &normal_stress,
                        const std::vector<double> &initial_shear,
                        const double               damping,
                        const double               plate_rate,
                        const MPI_Comm             communicator);

      /// The initial unknowns (zero slip, the law's initial state).
      std::vector<double>
      initial_values() const;

      /// The tolerances below which a change of each unknown does not
      /// matter: @p slip (m) for the slips, @p state (of the variable, or
      /// of its logarithm) for the states.
      std::vector<double>
      absolute_tolerances(const double slip, const double state) const;

      /// dy/dt at time @p t (s since the start) and @p y. Collective.
      void
      rates(const double               t,
            const std::vector<double> &y,
            std::vector<double>       &rate);

      /**
       * Evaluate slip rate, traction and state at (@p t, @p y) for
       * output and events (what slip_rate(), shear_stress() and state()
       * then give). Collective.
       */
      void
      evaluate(const double t, const std::vector<double> &y);

      /**
       * The same for the unknowns @p y whose rates @p rate the last call
       * of rates() computed (the integrator's last stage): no new solve.
       * Collective.
       */
      void
      accept(const std::vector<double> &y, const std::vector<double> &rate);

      /// Whether the law has state variables that relax by themselves
      /// (Friction::Interface::state_relaxes(): Chester's temperature),
      /// which the integrator leaves alone and relax() advances.
      bool
      relaxing() const
      {
        return !relaxing_variables.empty();
      }

      /**
       * After an accepted step of length @p dt to (@p t, @p y), accept()ed:
       * advance the relaxing state variables in @p y exactly over the step
       * (Friction::Interface::relax_state()), under the mean of the
       * frictional heating (|traction| times the slip rate) at the step's
       * start and end, and evaluate the fault anew. Returns the rates at
       * the new @p y: the first stage of the integrator's next step.
       * (Splitting the step so is first order in the coupling's step
       * error; the explicit pair alone would need steps shorter than the
       * relaxation time over years of loading.) Collective.
       */
      std::vector<double>
      relax(const double t, std::vector<double> &y, const double dt);

      /**
       * Take the fault's state from elsewhere (a fully dynamic phase,
       * AntiplaneDynamics): the slips and states @p y (as the integrator's
       * unknowns), the slip rates with their signs @p signed_rates and the
       * shear tractions @p tractions (Pa) per element: what the outputs
       * and the event catalogue then read, and the first guesses of the
       * next slip-rate solves.
       */
      void
      impose(const std::vector<double> &y,
             const std::vector<double> &signed_rates,
             const std::vector<double> &tractions);

      /// The law's position of element @p i, its initial shear traction
      /// tau0_i (Pa) and its normal stress before any slip (Pa).
      const Point<3> &
      point(const unsigned int i) const
      {
        return points[i];
      }
      double
      initial_shear(const unsigned int i) const
      {
        return tau0[i];
      }
      double
      initial_normal_stress(const unsigned int i) const
      {
        return sigma[i];
      }
      /// The law's state of element @p i in @p y (the integrator's
      /// unknowns), and back.
      void
      unpack_state(const unsigned int         i,
                   const std::vector<double> &y,
                   Friction::State           &state) const;
      void
      pack_state(const unsigned int     i,
                 const Friction::State &state,
                 std::vector<double>   &y) const;

      unsigned int
      size() const
      {
        return n;
      }
      double
      slip(const unsigned int i) const
      {
        return current[i];
      }
      double
      slip_rate(const unsigned int i) const
      {
        return velocity[i];
      }
      /// The shear traction tau_i - eta V_i (Pa) carried by the fault.
      double
      shear_stress(const unsigned int i) const
      {
        return traction[i];
      }
      /// The normal stress (Pa, compression > 0) on element i.
      double
      normal_stress(const unsigned int i) const
      {
        return normal_now[i];
      }
      /// Whether the slip changes the normal stress (a plane-strain body).
      bool
      normal_stress_changes() const
      {
        return coupled;
      }
      /// The slip rate of element i with its sign (negative: against the
      /// plates' sense).
      double
      signed_slip_rate(const unsigned int i) const
      {
        return signed_velocity[i];
      }

      /**
       * Where the normal stress fell to zero or below in the steps tried
       * since the last accepted one (their rates are not numbers, which
       * makes the integrator reject them): a message for the user, or
       * empty if it did not. Collective.
       */
      std::string
      opening_report() const;
      /// The law's first state output at element @p i (log10 theta, psi,
      /// th1: Friction::Interface::state_output()), and its name.
      double
      state(const unsigned int i) const;
      std::string
      state_name() const;
      double
      max_slip_rate() const;

      /// Write what evaluate() computed, the first guesses of the slip-rate
      /// solves and the open event (a checkpoint), and read it back.
      void
      save(std::ostream &out) const;
      void
      load(std::istream &in);

      // The event catalogue's questions (Fault::EventSource).
      std::pair<double, Point<2>>
      fastest_pair() const override;
      void
      start_event() override;
      void
      track_event() override;
      Fault::EventSummary<2>
      event_summary(const double threshold) const override;
      MPI_Comm
      mpi_communicator() const override
      {
        return communicator;
      }

    private:
      /// The slip rate at element @p i for the elastic traction
      /// @p tau and the normal stress @p normal_stress with the state
      /// @p state.
      double
      solve_rate(const unsigned int     i,
                 const double           tau,
                 const double           normal_stress,
                 const Friction::State &state) const;

      const Stiffness           &geometry;
      const Friction::Interface &law;
      const MPI_Comm             communicator;
      const unsigned int         n;
      unsigned int               n_variables = 0;
      std::vector<bool>          logarithmic;
      std::vector<Point<3>>      points;
      std::vector<double>        sigma, tau0;
      const double               eta, plate_rate;
      /// The law's state of every element at the start (its parameters).
      std::vector<Friction::State> states;
      /// The friction balance of this rank's rows under the loads that
      /// rates() computed last (shear_load, normal_load): the slip rates and
      /// state rates of (@p t, @p y) in @p rate. Collective.
      void
      balance(const double               t,
              const std::vector<double> &y,
              std::vector<double>       &rate);
      /// This rank's rows' shear traction and normal stress from the slip
      /// (without the damping), as rates() computed them last.
      std::vector<double> shear_load, normal_load;
      /// Scratch of rates(): the slips relative to the plate's, and this
      /// rank's rates.
      std::vector<double> relative, local;
      /// This rank's rows of K, and their range.
      unsigned int        row_begin = 0, row_end = 0;
      std::vector<double> stiffness;
      /// This rank's rows of the normal stiffness (empty: none).
      std::vector<double> normal_stiffness;
      /// Rows per rank, for the exchange of the rates.
      std::vector<int> counts, offsets;
      // The last evaluate().
      std::vector<double> current, velocity, traction, normal_now;
      /// Whether the body couples the normal stress to the slip (the same
      /// on every rank).
      const bool coupled;
      /// The last accepted slip rates with their signs.
      std::vector<double> signed_velocity;
      /// The lowest normal stress (<= 0) of the stages tried since the last
      /// accepted step and its time, and where (this rank's rows).
      std::pair<double, double> opening =
        {std::numeric_limits<double>::infinity(), 0.};
      unsigned int                     opening_at = 0;
      std::vector<std::vector<double>> variables;
      /// The state variables that relax (relaxing()), and the frictional
      /// heating (W/m^2) of every element at the start of the step.
      std::vector<unsigned int> relaxing_variables;
      std::vector<double>       heating;
      /// The relaxing variables at the start of the step and their rates
      /// there (by variable, then element), which rates() holds through
      /// the step; relax() advances them from the start anew.
      std::vector<std::vector<double>> held_start, held_rates;
      /// heating and held_rates from the last accepted traction, slip rate
      /// and state.
      void
      set_heating();
      // The open event.
      std::vector<double> event_start, event_peak;
    };
  } // namespace BoundaryIntegral
} // namespace rupture

#endif
