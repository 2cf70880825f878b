// The boundary-integral method's run: the time loop of the Dormand-Prince
// pair and the cycle outputs as they grow.

#include <rupture/base/binary_io.h>
#include <rupture/base/interruption.h>
#include <rupture/base/on_root.h>
#include <rupture/boundary_integral/antiplane_dynamics.h>
#include <rupture/boundary_integral/antiplane_finite_elements.h>
#include <rupture/boundary_integral/antiplane_half_space.h>
#include <rupture/boundary_integral/checkpoint.h>
#include <rupture/boundary_integral/cycle_output.h>
#include <rupture/boundary_integral/plane_strain_finite_elements.h>
#include <rupture/boundary_integral/quasi_dynamic_fault.h>
#include <rupture/boundary_integral/settings.h>
#include <rupture/boundary_integral/simulation.h>
#include <rupture/boundary_integral/text.h>
#include <rupture/fault/event_catalogue.h>
#include <rupture/output/directory.h>
#include <rupture/time_integration/dormand_prince.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>

namespace rupture
{
  namespace BoundaryIntegral
  {
    namespace
    {


      /// The fully dynamic phases so far and their steps.
      struct DynamicCount
      {
        std::uint64_t phases = 0, steps = 0;
      };

      /// What contrib/ reads of a run (as the finite-element runs'
      /// summary.json).
      std::string
      summary(const Settings                       &settings,
              const Clock                          &clock,
              const Stiffness                      &body,
              const TimeIntegration::DormandPrince &integrator,
              const double                          wall,
              const double                          body_wall,
              const unsigned int                    ranks,
              const DynamicCount                   *dynamic)
      {
        const bool         finished = clock.t >= settings.end_time;
        std::ostringstream json;
        json << std::setprecision(12) << "{\n"
             << "  \"status\": \"" << (finished ? "finished" : "ended early")
             << "\",\n"
             << "  \"end\": \"" << (finished ? "end time" : "number of events")
             << "\",\n"
             << "  \"method\": \"boundary integral\",\n"
             << "  \"ranks\": " << ranks << ",\n"
             << "  \"elements\": " << body.size() << ",\n"
             << "  \"steps\": " << clock.steps << ",\n"
             << "  \"rejected steps\": " << integrator.rejected_steps() << ",\n"
             << "  \"events\": " << clock.n_events << ",\n";
        if (dynamic)
          json << "  \"dynamic phases\": " << dynamic->phases << ",\n"
               << "  \"dynamic steps\": " << dynamic->steps << ",\n";
        json << "  \"time\": " << clock.t << ",\n"
             << "  \"smallest time step\": " << clock.dt_min << ",\n"
             << "  \"largest time step\": " << clock.dt_max << ",\n"
             << "  \"wall time\": " << (settings.test_mode ? 0. : wall) << ",\n"
             << "  \"stiffness wall time\": "
             << (settings.test_mode ? 0. : body_wall) << "\n"
             << "}\n";
        return json.str();
      }

      /// The body of <Boundary integral/Stiffness>.
      std::unique_ptr<Stiffness>
      make_body(const Settings &settings, const MPI_Comm communicator)
      {
        if (settings.geometry == "plane strain half-space")
          {
            PlaneStrainFiniteElements::Settings fe;
            fe.fault_extent  = settings.fault_depth;
            fe.node_spacing  = settings.element_size;
            fe.degree        = settings.fe_degree;
            fe.domain_size   = settings.domain_size;
            fe.growth        = settings.cell_growth;
            fe.dip           = settings.dip;
            fe.thrust        = settings.thrust;
            fe.shear_modulus = settings.shear_modulus;
            fe.lambda        = settings.lambda;
            for (const auto &station : settings.surface_stations)
              fe.surface_points.push_back(station.second[0]);
            return std::make_unique<PlaneStrainFiniteElements>(fe,
                                                               communicator);
          }
        if (settings.stiffness == "finite elements")
          {
            AntiplaneFiniteElements::Settings fe;
            fe.fault_depth            = settings.fault_depth;
            fe.node_spacing           = settings.element_size;
            fe.degree                 = settings.fe_degree;
            fe.domain_size            = settings.domain_size;
            fe.growth                 = settings.cell_growth;
            fe.shear_modulus          = settings.shear_modulus;
            fe.vertical_shear_modulus = settings.vertical_shear_modulus;
            fe.keep_body              = settings.fully_dynamic;
            return std::make_unique<AntiplaneFiniteElements>(fe, communicator);
          }
        // (An anisotropic body with C45 = 0 is the isotropic one of modulus
        // sqrt(C44 C55) with depths stretched by sqrt(C55 / C44): the
        // kernel, homogeneous of degree -1 in the depths, is the isotropic
        // one of that modulus; moments take C55.)
        return std::make_unique<AntiplaneHalfSpace>(
          settings.fault_depth,
          settings.element_size,
          std::sqrt(settings.shear_modulus * settings.vertical_shear_modulus),
          settings.shear_modulus);
      }
    } // namespace



    void
    run(ParameterHandler &prm, const MPI_Comm communicator, const bool resume)
    {
      const bool root =
        dealii::Utilities::MPI::this_mpi_process(communicator) == 0;
      const auto wall_start = std::chrono::steady_clock::now();

      Settings                         settings(prm);
      const std::unique_ptr<Stiffness> body = make_body(settings, communicator);
      // (What the body's stiffness cost: the finite elements' solves.)
      const double body_wall = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - wall_start)
                                 .count();
      const Stiffness    &geometry = *body;
      std::vector<double> sigma, tau0;
      settings.fault_stresses(geometry, sigma, tau0);
      const double eta    = settings.radiation_damping;
      auto        &events = settings.events;

      QuasiDynamicFault fault(geometry,
                              *settings.law,
                              sigma,
                              tau0,
                              eta,
                              settings.plate_rate,
                              communicator);
      CycleOutput       output(geometry,
                         settings.stations,
                         settings.sampling,
                         settings.test_mode,
                         communicator,
                         settings.surface_stations,
                         settings.plate_rate);
      output.state_name                                  = fault.state_name();
      TimeIntegration::DormandPrince::Settings tolerance = settings.integrator;
      tolerance.absolute_tolerance =
        fault.absolute_tolerances(settings.absolute_tolerance,
                                  settings.absolute_tolerance);
      TimeIntegration::DormandPrince integrator(
        [&](const double               t,
            const std::vector<double> &v,
            std::vector<double>       &r) { fault.rates(t, v, r); },
        tolerance);

      // The fully dynamic phases' body (<Events> = fully dynamic).
      std::unique_ptr<AntiplaneDynamics> dynamics;
      if (settings.fully_dynamic)
        {
          const auto *meshed =
            dynamic_cast<const AntiplaneFiniteElements *>(body.get());
          AssertThrow(meshed != nullptr, ExcInternalError());
          dynamics = std::make_unique<AntiplaneDynamics>(meshed->body(),
                                                         fault,
                                                         *settings.law,
                                                         settings.density,
                                                         settings.plate_rate,
                                                         settings.courant,
                                                         settings.kelvin_voigt);
        }

      // The state of the loop, all of it in a checkpoint.
      std::vector<double> y = fault.initial_values();
      DynamicCount        dynamic;
      Clock               clock;
      clock.dt = settings.first_step;
      Checkpoint checkpoint(settings.output_directory, communicator);
      if (resume)
        {
          std::istringstream in(checkpoint.read(clock, geometry.size()));
          BinaryIO::read(in, y);
          integrator.load(in);
          fault.load(in);
          events.load(in);
          output.load(in);
          BinaryIO::read(in, dynamic.phases);
          BinaryIO::read(in, dynamic.steps);
          AssertThrow(in.good() && y.size() == fault.initial_values().size(),
                      ExcMessage("--resume: the checkpoint <" +
                                 checkpoint.path() + "> is damaged."));
        }
      else
        fault.evaluate(0, y);

      // Every input is checked: the output directory.
      Output::Directory::check_name(settings.output_directory,
                                    "Output directory");
      Output::Directory directory(settings.output_directory, communicator);
      directory.open(resume);
      Utilities::on_root(communicator, [&]() {
        std::ostringstream parameters;
        prm.print_parameters(parameters, ParameterHandler::ShortPRM);
        directory.write("parameters.prm", parameters.str());
        output.open(directory, resume);
        // (A continued run's catalogue as the checkpoint has it.)
        events.write(fault, directory);
      });

      std::cout << std::flush;
      if (root)
        {
          std::cout << std::setprecision(6)
                    << (settings.stiffness == "finite elements" ?
                          "Boundary-integral method (the fault alone), the "
                          "body's stiffness from " :
                          "Boundary-integral method (the review paper's dual "
                          "method): ")
                    << geometry.description()
                    << ", mu = " << settings.shear_modulus
                    << (settings.vertical_shear_modulus !=
                            settings.shear_modulus ?
                          " Pa (C55; C44 = " +
                            dealii::Utilities::to_string(
                              settings.vertical_shear_modulus) +
                            " Pa, sqrt(C44 C55) = " +
                            dealii::Utilities::to_string(
                              std::sqrt(settings.shear_modulus *
                                        settings.vertical_shear_modulus)) +
                            ")" :
                          std::string())
                    << " Pa, eta = " << eta
                    << " Pa s/m, V_p = " << settings.plate_rate << " m/s; "
                    << dealii::Utilities::MPI::n_mpi_processes(communicator)
                    << " rank(s)\n";
          if (resume)
            std::cout << "  continued from the checkpoint at t = " << clock.t
                      << " s (step " << clock.steps << ")\n";
          else
            {
              double slowest = 1e300, fastest = 0;
              for (unsigned int i = 0; i < geometry.size(); ++i)
                {
                  slowest = std::min(slowest, fault.slip_rate(i));
                  fastest = std::max(fastest, fault.slip_rate(i));
                }
              std::cout << "  initial slip rates from " << slowest << " to "
                        << fastest << " m/s\n";
            }
          std::cout << std::flush;
        }
      if (!resume)
        output.record(0, 0, 0, 0, fault, true);

      auto last_checkpoint = std::chrono::steady_clock::now();
      // (The step whose checkpoint is written: none yet, or the one the
      // run continues from.)
      unsigned long checkpoint_step =
        resume ? clock.steps : std::numeric_limits<unsigned long>::max();
      // (The bytes of a checkpoint of the loop's state now; the output's
      // part on rank 0 only.)
      const auto checkpoint_bytes = [&]() {
        std::ostringstream out;
        Checkpoint::write_clock(out, clock, geometry.size());
        BinaryIO::write(out, y);
        integrator.save(out);
        fault.save(out);
        events.save(out);
        Utilities::on_root(communicator, [&]() {
          output.save(out);
          // (Written by every run, so that a quasi-dynamic run's checkpoint
          // can continue with fully dynamic events, and back.)
          BinaryIO::write(out, dynamic.phases);
          BinaryIO::write(out, dynamic.steps);
        });
        return out.str();
      };
      const auto write_checkpoint = [&]() {
        if (checkpoint_step == clock.steps)
          return; // (This step's is written.)
        const std::string bytes = checkpoint_bytes();
        Utilities::on_root(communicator,
                           [&]() { Checkpoint::store(directory, bytes); });
        checkpoint_step = clock.steps;
        last_checkpoint = std::chrono::steady_clock::now();
      };

      const double end_time = settings.end_time;

      // An event that ended at @p time: counted, the catalogue rewritten.
      const auto count_event = [&](const double time) {
        ++clock.n_events;
        Utilities::on_root(communicator,
                           [&]() { events.write(fault, directory); });
        if (root)
          std::cout << "  event " << clock.n_events
                    << " ended at t = " << std::setprecision(6) << time / year
                    << " years\n"
                    << std::flush;
      };

      // A fully dynamic phase from the state of the step just taken until
      // the largest slip rate falls below <Quasi-dynamic below>; then the
      // quasi-dynamic fault goes on from its slip and state. A checkpoint
      // falls due only between the phases: a run stopped by a signal
      // during one keeps the checkpoint of the phase's start, from which
      // --resume takes the same steps again.
      const auto run_dynamic_phase = [&]() {
        const std::string at_start =
          settings.checkpoints() ? checkpoint_bytes() : std::string();
        const unsigned long steps_at_start = clock.steps;
        ++dynamic.phases;
        if (root)
          std::cout << "  fully dynamic from t = " << std::setprecision(8)
                    << clock.t / year << " years (max slip rate "
                    << std::setprecision(4) << fault.max_slip_rate()
                    << " m/s), steps of " << dynamics->time_step() << " s\n"
                    << std::flush;
        dynamics->start(clock.t, y);
        // (The first step balances friction at the phase's start, which
        // the quasi-dynamic step recorded: counted, not written.)
        dynamics->step();
        ++clock.steps;
        ++dynamic.steps;
        while (true)
          {
            dynamics->step();
            ++clock.steps;
            ++dynamic.steps;
            const double tk = dynamics->time();
            fault.impose(dynamics->unknowns(),
                         dynamics->slip_rates(),
                         dynamics->tractions());
            AssertThrow(std::isfinite(fault.max_slip_rate()),
                        ExcMessage(
                          "The fully dynamic phase's slip rate is not a "
                          "number at t = " +
                          number(tk) +
                          " s: its steps are unstable. Give a smaller "
                          "<Boundary integral/Courant number>."));
            // (Every rank takes the same steps; rank 0's end decides for
            // all, so that the ranks' collectives stay matched.)
            const bool last =
              dealii::Utilities::MPI::max(int(root &&
                                              (fault.max_slip_rate() <
                                                 settings.quasi_dynamic_below ||
                                               tk >= end_time)),
                                          communicator);
            const bool ended = events.record(fault, tk);
            output.record(tk,
                          clock.steps,
                          dynamics->time_step(),
                          integrator.rejected_steps(),
                          fault,
                          tk >= end_time);
            if (ended)
              count_event(tk);
            const int signal =
              dealii::Utilities::MPI::max(Interruption::requested(),
                                          communicator);
            if (signal != 0)
              {
                Utilities::on_root(communicator,
                                   [&]() { events.write(fault, directory); });
                if (!at_start.empty())
                  Utilities::on_root(communicator, [&]() {
                    Checkpoint::store(directory, at_start);
                  });
                throw Interruption::Stopped(
                  signal,
                  "Stopped by " + Interruption::signal_name(signal) +
                    " at t = " + number(tk) +
                    " s, in the fully dynamic phase that started at step " +
                    std::to_string(steps_at_start) +
                    "; the files written so far hold the run up to there" +
                    (settings.checkpoints() ?
                       ", and --resume continues it from that phase's "
                       "start." :
                       "."));
              }
            if (last)
              break;
          }
        // Back to the quasi-dynamic fault: its slip rates from its balance
        // at the dynamic phase's slip and state.
        clock.t = dynamics->time();
        y       = dynamics->unknowns();
        // (Rank 0's, on every rank.)
        {
          const int ierr =
            MPI_Bcast(y.data(), int(y.size()), MPI_DOUBLE, 0, communicator);
          AssertThrowMPI(ierr);
          const int error = MPI_Bcast(&clock.t, 1, MPI_DOUBLE, 0, communicator);
          AssertThrowMPI(error);
        }
        fault.evaluate(clock.t, y);
        std::vector<double> rate;
        fault.rates(clock.t, y, rate);
        integrator.restart(rate);
        clock.dt      = 10 * dynamics->time_step();
        clock.last_dt = dynamics->time_step();
        clock.dt_min  = std::min(clock.dt_min, clock.last_dt);
        if (root)
          std::cout << "  quasi-dynamic from t = " << std::setprecision(8)
                    << clock.t / year << " years after "
                    << clock.steps - steps_at_start << " dynamic steps\n"
                    << std::flush;
      };
      double next_report =
        (std::floor(10 * clock.t / end_time) + 1) * 0.1 * end_time;
      double &t = clock.t;
      // (A checkpoint whose largest slip rate is above the switch's is the
      // start of a dynamic phase that a signal interrupted: it comes
      // first.)
      // (<Termination/Number of events> reached, and the last row that
      // then ends the files.)
      const auto enough_events = [&]() {
        return settings.max_events > 0 && clock.n_events >= settings.max_events;
      };
      const auto record_last = [&]() {
        output.record(t,
                      clock.steps,
                      clock.last_dt,
                      integrator.rejected_steps(),
                      fault,
                      true);
      };
      bool ended_early = false;
      if (resume && dynamics && t < end_time &&
          fault.max_slip_rate() >= settings.dynamic_above)
        {
          run_dynamic_phase();
          // (As the step that started it would have ended the run.)
          ended_early = enough_events();
          if (ended_early)
            record_last();
          // (The checkpoint that fell due in the phase.)
          else if (settings.checkpoints())
            write_checkpoint();
        }
      while (!ended_early && t < end_time)
        {
          // (A checkpoint falls due where the step count passes a
          // multiple of <Checkpoint/Interval>, also in the many steps of
          // a fully dynamic phase.)
          const unsigned long steps_before = clock.steps;
          try
            {
              clock.last_dt = integrator.advance(t, y, clock.dt, end_time);
            }
          catch (const ExceptionBase &)
            {
              // (Every rank fails the same step; if the fault would have
              // opened in the steps tried, that is what to say.)
              const std::string report = fault.opening_report();
              AssertThrow(report.empty(), ExcMessage(report));
              throw;
            }
          ++clock.steps;
          clock.dt_min = std::min(clock.dt_min, clock.last_dt);
          clock.dt_max = std::max(clock.dt_max, clock.last_dt);
          fault.accept(y, integrator.last_rate());
          if (fault.relaxing())
            integrator.restart(fault.relax(t, y, clock.last_dt));
          const bool ended = events.record(fault, t);
          output.record(t,
                        clock.steps,
                        clock.last_dt,
                        integrator.rejected_steps(),
                        fault,
                        t >= end_time);
          if (ended)
            count_event(t);
          if (dynamics && t < end_time &&
              fault.max_slip_rate() >= settings.dynamic_above)
            run_dynamic_phase();
          if (root && t >= next_report && t < end_time)
            {
              std::cout << "  t = " << std::setprecision(6) << t / year
                        << " years, " << clock.steps << " steps, max slip rate "
                        << fault.max_slip_rate() << " m/s\n"
                        << std::flush;
              next_report += 0.1 * end_time;
            }
          const bool done = enough_events();
          if (done)
            record_last();
          // (Rank 0's clock decides for all.)
          const bool minutes_passed = dealii::Utilities::MPI::max(
            int(settings.checkpoint_minutes > 0 &&
                std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                              last_checkpoint)
                    .count() >= 60 * settings.checkpoint_minutes &&
                root),
            communicator);
          // (SIGUSR1: a checkpoint now, and the run goes on.)
          const bool requested = dealii::Utilities::MPI::max(
            int(Interruption::take_checkpoint_request()), communicator);
          if (requested || (settings.checkpoints() &&
                            ((settings.checkpoint_steps > 0 &&
                              clock.steps / settings.checkpoint_steps !=
                                steps_before / settings.checkpoint_steps) ||
                             minutes_passed)))
            write_checkpoint();
          // (Together: a signal that reached one rank stops all.)
          const int signal =
            dealii::Utilities::MPI::max(Interruption::requested(),
                                        communicator);
          if (signal != 0)
            {
              Utilities::on_root(communicator,
                                 [&]() { events.write(fault, directory); });
              if (settings.checkpoints())
                write_checkpoint();
              throw Interruption::Stopped(
                signal,
                "Stopped by " + Interruption::signal_name(signal) + " at t = " +
                  number(t) + " s (step " + std::to_string(clock.steps) +
                  "); the files written so far hold the run up to there" +
                  (settings.checkpoints() ? ", and --resume continues it." :
                                            "."));
            }
          if (done)
            break;
        }
      Utilities::on_root(communicator,
                         [&]() { events.write(fault, directory); });
      if (settings.checkpoints())
        write_checkpoint();
      if (root)
        {
          const double wall = std::chrono::duration<double>(
                                std::chrono::steady_clock::now() - wall_start)
                                .count();
          std::cout << "Ended at t = " << std::setprecision(8) << t << " s ("
                    << t / year << " years) after " << clock.n_events
                    << " event(s)";
          if (!settings.test_mode)
            std::cout << ", " << clock.steps << " steps ("
                      << integrator.rejected_steps()
                      << " rejected), time steps from " << clock.dt_min
                      << " to " << clock.dt_max << " s, "
                      << std::setprecision(3) << wall << " s wall time";
          std::cout << ".\n" << std::flush;
          directory.write("summary.json",
                          summary(settings,
                                  clock,
                                  geometry,
                                  integrator,
                                  wall,
                                  body_wall,
                                  dealii::Utilities::MPI::n_mpi_processes(
                                    communicator),
                                  dynamics ? &dynamic : nullptr));
        }
    }
  } // namespace BoundaryIntegral
} // namespace rupture
