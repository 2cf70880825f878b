#ifndef rupture_time_integration_newmark_h
#define rupture_time_integration_newmark_h

#include <rupture/time_integration/step_controller.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace rupture
{
  using namespace dealii;

  namespace TimeIntegration
  {
    /**
     * The ways to step the equations of motion M a + C v + K u = f.
     */
    enum class Scheme
    {
      /// Newmark with beta > 0: one (non)linear solve per step.
      implicit_newmark,
      /// Newmark with beta = 0, gamma = 1/2 and a lumped mass: no solve.
      explicit_central_difference,
      /// No inertia: K u = f at each time.
      quasi_static
    };

    /**
     * Time-stepping parameters, from the section "Time integration".
     */
    struct Parameters
    {
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      Scheme scheme;
      /// Newmark beta and gamma (the paper's beta_1 and beta_2).
      double beta;
      double gamma;
      /// Time step (s). For the explicit scheme 0 means: the stable step
      /// times the Courant fraction.
      double time_step;
      double courant_fraction;
      double end_time;
      /// Whether the explicit scheme may run above its stable step (for
      /// stability studies only).
      bool allow_unstable_time_step;
      /// The quasi-static loading phase (step 1 of the paper's load
      /// sequence) that precedes the run of <Scheme>, if enabled.
      bool   loading_phase;
      double loading_time_step;
      double loading_end_time;
      bool   stop_loading_when_weakening;
      /// How the steps of a phase are chosen.
      StepControllerParameters step_controller;

      std::string
      scheme_name() const;
    };

    /**
     * The constants a_0 ... a_5 of the paper's eq. 15 that turn the Newmark
     * relations into the effective static problem of eq. 14.
     */
    struct NewmarkCoefficients
    {
      NewmarkCoefficients(const double beta,
                          const double gamma,
                          const double time_step);
      double a0, a1, a2, a3, a4, a5;
    };

    /**
     * Largest stable step of the central-difference scheme for a system
     * whose highest angular frequency is @p omega_max (rad/s), with
     * Rayleigh damping C = alpha M + beta K: dt = 2/omega (sqrt(1 + xi^2) -
     * xi) with the damping ratio xi = alpha/(2 omega) + beta omega/2 of
     * the highest mode.
     *
     * With a further stiffness-proportional damping whose coefficient is
     * the fraction @p kelvin_voigt_fraction c of the step itself (the
     * fault zone's), xi = xi_0 + c omega dt / 2, and the bound
     * omega dt / 2 = x solves (1 + 2 c) x^2 + 2 xi_0 x - 1 = 0.
     */
    double
    central_difference_stable_step(const double omega_max,
                                   const double alpha,
                                   const double beta,
                                   const double kelvin_voigt_fraction = 0);
  } // namespace TimeIntegration
} // namespace rupture

#endif
