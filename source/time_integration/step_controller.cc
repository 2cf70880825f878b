// The step controllers of a phase: "fixed" and the rate-and-state rule of
// Lapusta et al. (2000).

#include <rupture/time_integration/step_controller.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rupture
{
  namespace TimeIntegration
  {
    void
    StepControllerParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using dealii::Patterns::Double;
      prm.enter_subsection("Step controller");
      {
        prm.declare_entry(
          "Controller",
          "fixed",
          dealii::Patterns::Selection("fixed|rate and state"),
          "How the time steps of a run are chosen. 'fixed': the phase's "
          "<Time step> throughout (the implicit scheme still cuts a step "
          "whose Newton iteration fails). 'rate and state': the rule of "
          "Lapusta et al. (2000) for whole earthquake cycles, dt = xi min "
          "(L / V) over the fault (L the friction law's characteristic "
          "slip distance, V the slip rate of the last step, xi <State "
          "evolution fraction>), between <Minimum time step> and <Maximum "
          "time step> and at most <Maximum growth factor> times the step "
          "before; the first step is <Time step>. Works with the "
          "quasi-static scheme (with <Fault/Radiation damping>: "
          "quasi-dynamic) and a friction law with a state.");
        prm.declare_entry(
          "State evolution fraction",
          "0.1",
          Double(),
          "xi: the fraction of the shortest state evolution time L / V "
          "that a step of the 'rate and state' controller spans, in (0, "
          "1]. Lapusta et al. (2000) show stability up to about 1/2 for "
          "the aging law on stiff enough grids; accuracy asks for less.");
        prm.declare_entry("Minimum time step",
                          "1e-3",
                          Double(),
                          "The shortest step (s) the 'rate and state' "
                          "controller takes, > 0.");
        prm.declare_entry("Maximum time step",
                          "3.15576e7",
                          Double(),
                          "The longest step (s) the 'rate and state' "
                          "controller takes, >= <Minimum time step> (one "
                          "year by default).");
        prm.declare_entry("Maximum growth factor",
                          "2",
                          Double(),
                          "A step of the 'rate and state' controller is at "
                          "most this factor longer than the step before, "
                          ">= 1.");
      }
      prm.leave_subsection();
    }



    void
    StepControllerParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Step controller");
      {
        name           = prm.get("Controller");
        state_fraction = prm.get_double("State evolution fraction");
        minimum_step   = prm.get_double("Minimum time step");
        maximum_step   = prm.get_double("Maximum time step");
        growth_factor  = prm.get_double("Maximum growth factor");
      }
      prm.leave_subsection();
      const auto require = [](const bool         ok,
                              const std::string &entry,
                              const double       value,
                              const std::string &allowed) {
        std::ostringstream message;
        message << "<Time integration/Step controller/" << entry << "> is "
                << value << ", but it must be " << allowed << ".";
        AssertThrow(ok, dealii::ExcMessage(message.str()));
      };
      require(state_fraction > 0 && state_fraction <= 1,
              "State evolution fraction",
              state_fraction,
              "in (0, 1]");
      require(minimum_step > 0 && std::isfinite(minimum_step),
              "Minimum time step",
              minimum_step,
              "> 0 (s)");
      require(
        maximum_step >= minimum_step && std::isfinite(maximum_step),
        "Maximum time step",
        maximum_step,
        ">= <Minimum time step> = " +
          [&]() {
            std::ostringstream s;
            s << minimum_step;
            return s.str();
          }() +
          " (s)");
      require(growth_factor >= 1 && std::isfinite(growth_factor),
              "Maximum growth factor",
              growth_factor,
              ">= 1");
    }



    namespace
    {
      /**
       * The phase's step, every step.
       */
      class Fixed : public StepController
      {
      public:
        explicit Fixed(const double step)
          : step(step)
        {}

        std::string
        name() const override
        {
          return "fixed";
        }

        bool
        adaptive() const override
        {
          return false;
        }

        double
        next(const StepInputs &) const override
        {
          return step;
        }

        void
        accept(const double) override
        {}

        void
        reject(const double) override
        {}

        void
        save(BinaryIO::Records &) const override
        {}

        void
        load(const BinaryIO::Records &) override
        {}

      private:
        const double step;
      };



      /**
       * dt = xi min(L / V), bounded and growing by at most a factor.
       */
      class RateAndState : public StepController
      {
      public:
        RateAndState(const StepControllerParameters &parameters,
                     const double                    initial_step)
          : parameters(parameters)
          , last(initial_step)
        {}

        std::string
        name() const override
        {
          return "rate and state";
        }

        bool
        adaptive() const override
        {
          return true;
        }

        double
        next(const StepInputs &inputs) const override
        {
          // The first step is the phase's <Time step>; then growth is
          // limited by the step before (after a rejection: by the failed
          // step's half).
          double dt = taken ? parameters.growth_factor * last : last;
          if (std::isfinite(inputs.state_evolution_time))
            dt =
              std::min(dt,
                       parameters.state_fraction * inputs.state_evolution_time);
          return std::clamp(dt,
                            parameters.minimum_step,
                            parameters.maximum_step);
        }

        void
        accept(const double dt) override
        {
          last  = dt;
          taken = true;
        }

        void
        reject(const double dt) override
        {
          last  = dt / 2;
          taken = false;
        }

        void
        save(BinaryIO::Records &records) const override
        {
          records["integrator/step controller/last step"] = last;
          records["integrator/step controller/taken"]     = taken ? 1 : 0;
        }

        void
        load(const BinaryIO::Records &records) override
        {
          const auto l = records.find("integrator/step controller/last step");
          const auto t = records.find("integrator/step controller/taken");
          if (l != records.end() && t != records.end())
            {
              last  = l->second;
              taken = (t->second != 0);
            }
        }

      private:
        const StepControllerParameters parameters;
        double                         last;
        bool                           taken = false;
      };
    } // namespace



    std::unique_ptr<StepController>
    create_step_controller(const StepControllerParameters &parameters,
                           const double                    initial_step)
    {
      if (parameters.name == "rate and state")
        return std::make_unique<RateAndState>(parameters, initial_step);
      return std::make_unique<Fixed>(initial_step);
    }
  } // namespace TimeIntegration
} // namespace rupture
