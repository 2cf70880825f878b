#ifndef rupture_boundary_integral_antiplane_dynamics_h
#define rupture_boundary_integral_antiplane_dynamics_h

#include <rupture/friction/interface.h>

#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace rupture
{
  namespace BoundaryIntegral
  {
    struct AntiplaneBody;
    class QuasiDynamicFault;

    /**
     * A fully dynamic phase of an antiplane cycle run: the waves of the
     * meshed body beside the fault (AntiplaneBody), rho u_tt = div(C grad
     * u), with friction on the fault's nodes, from the state of a
     * quasi-dynamic phase back to one.
     *
     * The unknown is the displacement relative to the plates' motion,
     * u - V_p t / 2, so that the fault's slip is s = V_p t + 2 u there (the
     * antisymmetry of the problem: the side x < 0 moves by -u). Central
     * differences with the mass lumped on the elements' Gauss-Lobatto
     * nodes: displacements at the times t_k, velocities at the half steps.
     * At a fault node i of tributary length w_i and lumped mass M_i the
     * elastic traction tau_i = tau0_i - (A u)_i / w_i drives the slip rate
     * against the strength S, M_i dV/dt = 2 w_i (tau_i - S); with the rate
     * W of the next half step this is S = T - Z W, T = tau_i + Z V_-,
     * Z = M_i / (2 w_i dt), and friction holds at t_k at the mean slip
     * rate V_k = (V_- + W) / 2 with the state evolved up to t_k (the
     * volume method's split nodes do the same: second order; for a law
     * whose state depends on the traction, Chester's, the state's step
     * takes the traction at t_k, first order in that coupling). Written
     * in V_k, S(|V_k|) = |T + Z V_-| - 2 Z |V_k| with V_k of the sense of
     * T + Z V_-: W = 2 V_k - V_- may have either sense (a node that stops
     * or turns back). The state then moves over the step to t_k+1 at the
     * rate W (Friction::Interface::update_state()).
     *
     * The fault below W stays held at the plates' motion. The far side and
     * the bottom, held in the quasi-dynamic phases, absorb the waves
     * (Lysmer's dashpots, rho c v per area, c the S-wave speed across the
     * boundary) and keep the force that held them at the phase's start,
     * so the body starts in balance. The phase starts from the static field
     * of the slip and the static field of the slip rates (no jump in
     * stress or slip rate) and ends with the slip and state at t_k.
     *
     * Every rank takes the same steps on the whole body.
     */
    class AntiplaneDynamics
    {
    public:
      /**
       * The body @p body of the fault @p fault (its elements are the
       * body's fault nodes) with the friction law @p law, the density
       * @p density (kg/m^3), the plate rate @p plate_rate (m/s) and the
       * Courant number @p courant (the step is that times the stable step
       * 2 / sqrt(largest eigenvalue of M^-1 A), found by power iteration)
       * and Kelvin-Voigt damping of @p damping time steps (the stress of
       * u + damping dt v: it damps the mesh's highest frequencies, which a
       * sudden slip excites and which would ring on at the fault; Day et
       * al. 2005 take 0.1).
       */
      AntiplaneDynamics(std::shared_ptr<const AntiplaneBody> body,
                        const QuasiDynamicFault             &fault,
                        const Friction::Interface           &law,
                        const double                         density,
                        const double                         plate_rate,
                        const double                         courant,
                        const double                         damping);

      double
      time_step() const
      {
        return dt;
      }

      /**
       * Start at time @p t from the slips and states @p y and the slip
       * rates of the quasi-dynamic fault (its last evaluation).
       */
      void
      start(const double t, const std::vector<double> &y);

      /**
       * One step from t_k to t_k+1. Afterwards time(), unknowns(),
       * slip_rates() and tractions() are those of t_k (where friction was
       * balanced), the state of the next step is t_k+1's.
       */
      void
      step();

      /// The time of the values of the last step.
      double
      time() const
      {
        return recorded_time;
      }

      /// The slips and states at time() as the quasi-dynamic fault's
      /// unknowns.
      const std::vector<double> &
      unknowns() const
      {
        return recorded;
      }
      const std::vector<double> &
      slip_rates() const
      {
        return rate;
      }
      const std::vector<double> &
      tractions() const
      {
        return traction;
      }
      double
      max_slip_rate() const;

    private:
      /// The size m >= 0 of the mean slip rate at node @p i that solves
      /// @p target - 2 Z m = S(m) with the state @p state (0 where S(0)
      /// holds the target), from the first guess @p guess.
      double
      solve_rate(const unsigned int     i,
                 const double           target,
                 const double           guess,
                 const Friction::State &state) const;

      std::shared_ptr<const AntiplaneBody> body;
      const QuasiDynamicFault             &fault;
      const Friction::Interface           &law;
      const double                         plate_rate;
      /// The time step and the Kelvin-Voigt damping time (s).
      double                 dt = 0, viscosity = 0;
      dealii::Vector<double> scratch;
      /// Lumped masses, the dashpots of the absorbing sides, whether an
      /// unknown is held (the fault below W), the fault's node of each
      /// unknown (or invalid).
      dealii::Vector<double>    mass, dashpot;
      std::vector<bool>         fixed;
      std::vector<unsigned int> fault_index;
      // The state: u at t_k, v at t_k - dt / 2, the force that holds the
      // absorbing sides, and the friction state at t_k per element.
      double                       t = 0;
      dealii::Vector<double>       u, v, hold, force;
      std::vector<Friction::State> states;
      // The values of the last step (at recorded_time).
      double              recorded_time = 0;
      std::vector<double> recorded, rate, traction;
    };
  } // namespace BoundaryIntegral
} // namespace rupture

#endif
