#include <rupture/time_integration/newmark.h>

#include <cmath>

namespace rupture
{
  namespace TimeIntegration
  {
    void
    Parameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time integration");
      {
        prm.declare_entry(
          "Scheme",
          "implicit Newmark",
          Patterns::Selection(
            "implicit Newmark|explicit central difference|quasi-static"),
          "How the equations of motion are stepped. 'implicit Newmark' "
          "solves a linear system per step with the Newmark beta and gamma "
          "below (unconditionally stable for 2 beta >= gamma >= 1/2). "
          "'explicit central difference' is Newmark with beta = 0, gamma = "
          "1/2 and a lumped mass; it needs no solve but a step below the "
          "stable limit, which the program computes. 'quasi-static' drops "
          "inertia and solves K u = f at each time (loading phases).");
        prm.declare_entry("Newmark beta",
                          "0.25",
                          Patterns::Double(0, 0.5),
                          "Newmark beta (the paper's beta_1), > 0 for the "
                          "implicit scheme. 0.25 with gamma = 0.5 is the "
                          "average-acceleration (trapezoidal) rule.");
        prm.declare_entry("Newmark gamma",
                          "0.5",
                          Patterns::Double(0.5, 1),
                          "Newmark gamma (the paper's beta_2), in [0.5, 1]. "
                          "Values above 0.5 add numerical damping.");
        prm.declare_entry("Time step",
                          "0.01",
                          Patterns::Double(0),
                          "Time step (s), > 0. For the explicit scheme 0 "
                          "selects the stable step times <Courant "
                          "fraction>.");
        prm.declare_entry("Courant fraction",
                          "0.5",
                          Patterns::Double(0, 1),
                          "Fraction of the stable step used by the explicit "
                          "scheme when <Time step> = 0.");
        prm.declare_entry("End time",
                          "1",
                          Patterns::Double(0),
                          "Time (s) at which the run ends, > 0.");
        prm.declare_entry(
          "Allow unstable time step",
          "false",
          Patterns::Bool(),
          "Let the explicit scheme run with a step above its stable limit. "
          "Only for stability studies: such a run blows up, and is stopped "
          "as soon as its energy balance error reaches half of the energy "
          "in play or a value is no longer finite.");
        StepControllerParameters::declare_parameters(prm);
        prm.enter_subsection("Loading phase");
        {
          prm.declare_entry(
            "Enabled",
            "false",
            Patterns::Bool(),
            "Step 1 of the paper's load sequence: a quasi-static loading "
            "phase (gravity, plate motion) before the run of <Scheme>. Its "
            "final state (stress, fault tractions, slip) is the initial "
            "state of the dynamic phase, and <End time> then counts from "
            "the start of the dynamic phase.");
          prm.declare_entry("Time step",
                            "3.15576e7",
                            Patterns::Double(0),
                            "Time step (s) of the loading phase, > 0 (one "
                            "year by default).");
          prm.declare_entry("End time",
                            "3.15576e9",
                            Patterns::Double(0),
                            "Time (s) at which the loading phase ends at "
                            "the latest, > 0 (100 years by default).");
          prm.declare_entry(
            "Stop when a bonded zone slips",
            "true",
            Patterns::Bool(),
            "End the loading phase at the first step in which a fault "
            "point slips while its friction weakens, i.e. a bonded zone "
            "reaches its strength; the dynamic phase starts from there.");
        }
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }



    void
    Parameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time integration");
      {
        const std::string s = prm.get("Scheme");
        scheme =
          (s == "implicit Newmark" ?
             Scheme::implicit_newmark :
             (s == "quasi-static" ? Scheme::quasi_static :
                                    Scheme::explicit_central_difference));
        beta                     = prm.get_double("Newmark beta");
        gamma                    = prm.get_double("Newmark gamma");
        time_step                = prm.get_double("Time step");
        courant_fraction         = prm.get_double("Courant fraction");
        end_time                 = prm.get_double("End time");
        allow_unstable_time_step = prm.get_bool("Allow unstable time step");
        step_controller.parse_parameters(prm);
        prm.enter_subsection("Loading phase");
        loading_phase     = prm.get_bool("Enabled");
        loading_time_step = prm.get_double("Time step");
        loading_end_time  = prm.get_double("End time");
        stop_loading_when_weakening =
          prm.get_bool("Stop when a bonded zone slips");
        prm.leave_subsection();
      }
      prm.leave_subsection();

      if (loading_phase)
        AssertThrow(loading_time_step > 0 && loading_end_time > 0 &&
                      std::isfinite(loading_end_time),
                    ExcMessage("<Time integration/Loading phase/Time step> "
                               "and <End time> must be > 0 (s)."));
      AssertThrow(end_time > 0 && std::isfinite(end_time),
                  ExcMessage("<Time integration/End time> is " +
                             std::to_string(end_time) +
                             ", but it must be > 0 (s)."));
      // The adaptive controllers step quasi-static runs so far: a new step
      // of the implicit scheme costs a new matrix, and the explicit one has
      // its stable step.
      AssertThrow(step_controller.name == "fixed" ||
                    (scheme == Scheme::quasi_static && !loading_phase),
                  ExcMessage(
                    "<Time integration/Step controller/Controller> = " +
                    step_controller.name +
                    " works with <Time integration/"
                    "Scheme> = quasi-static (without a <Loading phase>) "
                    "only, but " +
                    (scheme == Scheme::quasi_static ?
                       std::string("the run has a loading phase") :
                       "<Scheme> is '" + scheme_name() + "'") +
                    ". Allowed: 'fixed' for this run, or a quasi-static run "
                    "(with <Fault/Radiation damping> for quasi-dynamic "
                    "cycles)."));
      if (scheme == Scheme::explicit_central_difference)
        {
          AssertThrow(time_step >= 0,
                      ExcMessage("<Time integration/Time step> is " +
                                 std::to_string(time_step) +
                                 ", but it must be > 0 (s), or 0 for the "
                                 "automatic stable step of the explicit "
                                 "scheme."));
          AssertThrow(courant_fraction > 0,
                      ExcMessage("<Time integration/Courant fraction> must "
                                 "be > 0."));
          // The explicit member of the Newmark family.
          beta  = 0;
          gamma = 0.5;
        }
      else
        {
          AssertThrow(time_step > 0 && std::isfinite(time_step),
                      ExcMessage("<Time integration/Time step> is " +
                                 std::to_string(time_step) +
                                 ", but it must be > 0 (s)."));
          if (scheme == Scheme::implicit_newmark)
            AssertThrow(beta > 0,
                        ExcMessage("<Time integration/Newmark beta> = 0 is "
                                   "the explicit member of the family; set "
                                   "<Scheme> = explicit central difference "
                                   "for it, or choose beta > 0 (0.25 is "
                                   "the usual value)."));
        }
    }



    std::string
    Parameters::scheme_name() const
    {
      switch (scheme)
        {
          case Scheme::implicit_newmark:
            return "implicit Newmark";
          case Scheme::explicit_central_difference:
            return "explicit central difference";
          default:
            return "quasi-static";
        }
    }



    NewmarkCoefficients::NewmarkCoefficients(const double beta,
                                             const double gamma,
                                             const double dt)
      : a0(1. / (beta * dt * dt))
      , a1(gamma / (beta * dt))
      , a2(1. / (beta * dt))
      , a3(1. / (2 * beta) - 1)
      , a4(gamma / beta - 1)
      , a5(dt / 2 * (gamma / beta - 2))
    {}



    double
    central_difference_stable_step(const double omega_max,
                                   const double alpha,
                                   const double beta,
                                   const double kelvin_voigt_fraction)
    {
      const double xi = alpha / (2 * omega_max) + beta * omega_max / 2;
      const double c  = 1 + 2 * kelvin_voigt_fraction;
      return 2. / omega_max * (std::sqrt(xi * xi + c) - xi) / c;
    }
  } // namespace TimeIntegration
} // namespace rupture
