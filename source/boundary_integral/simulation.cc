// The boundary-integral method's run: the time loop of the Dormand-Prince
// pair and the cycle outputs as they grow.

#include <rupture/base/binary_io.h>
#include <rupture/base/interruption.h>
#include <rupture/base/utilities.h>
#include <rupture/boundary_integral/antiplane_half_space.h>
#include <rupture/boundary_integral/cycle_output.h>
#include <rupture/boundary_integral/quasi_dynamic_fault.h>
#include <rupture/boundary_integral/simulation.h>
#include <rupture/fault/event_catalogue.h>
#include <rupture/friction/interface.h>
#include <rupture/output/directory.h>
#include <rupture/time_integration/dormand_prince.h>

#include <deal.II/base/function_parser.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
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
      constexpr double year = 3.15576e7;

      /// The values at the element centres of the function of x, y, z in
      /// <Boundary integral/@p entry>.
      std::vector<double>
      values_along(const AntiplaneHalfSpace &geometry,
                   ParameterHandler         &prm,
                   const std::string        &entry)
      {
        const std::string expression = prm.get(entry);
        AssertThrow(!dealii::Utilities::trim(expression).empty(),
                    ExcMessage("<Boundary integral/" + entry +
                               "> is empty. Give a function of x, y, z (y "
                               "up, the fault at x = 0, the depth -y), e.g. "
                               "a number."));
        FunctionParser<3> f(1);
        try
          {
            f.initialize("x,y,z",
                         expression,
                         {{"pi", M_PI}, {"year", year}},
                         false);
          }
        catch (const ExceptionBase &e)
          {
            AssertThrow(false,
                        ExcMessage("<Boundary integral/" + entry + "> = <" +
                                   expression +
                                   "> is not a function of x, y, z: " +
                                   Utilities::message_of(e)));
          }
        std::vector<double> v;
        for (unsigned int i = 0; i < geometry.size(); ++i)
          {
            const double value = f.value(Point<3>(0., -geometry.centre(i), 0.));
            AssertThrow(std::isfinite(value),
                        ExcMessage("<Boundary integral/" + entry +
                                   "> is not finite at the depth " +
                                   std::to_string(geometry.centre(i)) + " m."));
            v.push_back(value);
          }
        return v;
      }

      /// The first number of the list in <Material/@p entry>.
      double
      first_material_value(ParameterHandler &prm, const std::string &entry)
      {
        const auto values =
          Utilities::parse_doubles(prm.get(entry), "Material/" + entry);
        AssertThrow(!values.empty(),
                    ExcMessage("<Material/" + entry + "> is empty."));
        return values[0];
      }

      /**
       * Run @p action on rank 0 and throw its error on every rank (a
       * failure to write a file must not leave the others waiting in the
       * next collective call).
       */
      template <typename Action>
      void
      on_root(const MPI_Comm communicator, const Action &action)
      {
        std::string error;
        if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
          try
            {
              action();
            }
          catch (const ExceptionBase &e)
            {
              error = Utilities::message_of(e);
            }
          catch (const std::exception &e)
            {
              error = e.what();
            }
        error = dealii::Utilities::MPI::broadcast(communicator, error, 0);
        AssertThrow(error.empty(), ExcMessage(error));
      }

      std::string
      number(const double x)
      {
        std::ostringstream s;
        s << std::setprecision(10) << x;
        return s.str();
      }
    } // namespace



    void
    run(ParameterHandler &prm, const MPI_Comm communicator, const bool resume)
    {
      const bool root =
        dealii::Utilities::MPI::this_mpi_process(communicator) == 0;
      const auto wall_start = std::chrono::steady_clock::now();
      const bool test_mode  = prm.get_bool("Test mode");

      // The medium.
      prm.enter_subsection("Material");
      double mu = 0;
      if (prm.get("Parametrization") == "wave speeds")
        mu = first_material_value(prm, "Density") *
             std::pow(first_material_value(prm, "S-wave speed"), 2);
      else
        mu = first_material_value(prm, "Young's modulus") /
             (2 * (1 + first_material_value(prm, "Poisson's ratio")));
      prm.leave_subsection();

      // The friction law, the damping and the fault's outputs.
      prm.enter_subsection("Fault");
      std::unique_ptr<Friction::Interface> law = Friction::create(prm);
      const double eta = prm.get_double("Radiation damping");
      AssertThrow(law->has_state_rate(),
                  ExcMessage(
                    "<Fault/Friction law> = " + prm.get("Friction law") +
                    " gives no rate of change of its state, which "
                    "the boundary-integral method integrates. "
                    "Allowed with <Method> = boundary integral: "
                    "rate and state."));
      prm.enter_subsection("Output");
      Fault::EventCatalogue<2> events;
      events.parse_parameters(prm);
      const double event_rate = prm.get_double("Event slip rate");
      const auto   station_points =
        Utilities::parse_named_points<2>(prm.get("Stations"),
                                         "Fault/Output/Stations");
      prm.leave_subsection();
      prm.leave_subsection();

      // The clock.
      prm.enter_subsection("Time integration");
      const double end_time   = prm.get_double("End time");
      double       first_step = prm.get_double("Time step");
      AssertThrow(end_time > 0 && std::isfinite(end_time),
                  ExcMessage("<Time integration/End time> must be > 0 (s)."));
      AssertThrow(first_step > 0 && std::isfinite(first_step),
                  ExcMessage("<Time integration/Time step> (the first step "
                             "the boundary-integral method tries) must be "
                             "> 0 (s)."));
      TimeIntegration::DormandPrince::Settings settings;
      prm.enter_subsection("Step controller");
      settings.minimum_step   = prm.get_double("Minimum time step");
      settings.maximum_step   = prm.get_double("Maximum time step");
      settings.maximum_growth = prm.get_double("Maximum growth factor");
      prm.leave_subsection();
      prm.leave_subsection();

      // The fault.
      prm.enter_subsection("Boundary integral");
      const AntiplaneHalfSpace geometry(prm.get_double("Fault depth"),
                                        prm.get_double("Element size"),
                                        mu);
      const double             plate_rate = prm.get_double("Plate rate");
      AssertThrow(std::isfinite(plate_rate) && plate_rate > 0,
                  ExcMessage("<Boundary integral/Plate rate> must be > 0 "
                             "(m/s)."));
      const std::vector<double> sigma =
        values_along(geometry, prm, "Normal stress");
      const std::vector<double> tau0 =
        values_along(geometry, prm, "Initial shear stress");
      for (unsigned int i = 0; i < geometry.size(); ++i)
        {
          AssertThrow(sigma[i] > 0,
                      ExcMessage("<Boundary integral/Normal stress> is " +
                                 number(sigma[i]) + " Pa at the depth " +
                                 number(geometry.centre(i)) +
                                 " m, but it must be > 0 (compression)."));
          AssertThrow(tau0[i] - eta * plate_rate > 0,
                      ExcMessage("<Boundary integral/Initial shear stress> "
                                 "is " +
                                 number(tau0[i]) + " Pa at the depth " +
                                 number(geometry.centre(i)) +
                                 " m, but it must exceed eta V_p = " +
                                 number(eta * plate_rate) +
                                 " Pa, so that the fault slips at V_p."));
        }
      settings.relative_tolerance = prm.get_double("Relative tolerance");
      const double absolute       = prm.get_double("Absolute tolerance");
      AssertThrow(settings.relative_tolerance > 0 &&
                    settings.relative_tolerance < 1 && absolute > 0,
                  ExcMessage("<Boundary integral/Relative tolerance> must lie "
                             "in (0, 1) and <Absolute tolerance> be > 0."));

      const double sampling_change =
        prm.get_double("Sampling slip rate change");
      const double sampling_interval = prm.get_double("Sampling interval");
      const double profile_slow =
        prm.get_double("Profile interval between events");
      const double profile_fast =
        prm.get_double("Profile interval during events");
      prm.leave_subsection();
      AssertThrow(settings.minimum_step > 0 &&
                    settings.maximum_step >= settings.minimum_step &&
                    settings.maximum_growth > 1,
                  ExcMessage("<Time integration/Step controller>: the "
                             "minimum time step must be > 0, the maximum at "
                             "least the minimum, the growth factor > 1."));

      // The end: <Termination/Number of events> (the one criterion of
      // <Termination> that a cycle run of this method uses).
      prm.enter_subsection("Termination");
      const unsigned int max_events = prm.get_integer("Number of events");
      prm.leave_subsection();
      AssertThrow(max_events == 0 || events.enabled(),
                  ExcMessage("<Termination/Number of events> counts the "
                             "events of the event catalogue: set "
                             "<Fault/Output/Event catalogue> = true."));

      // Checkpoints.
      prm.enter_subsection("Checkpoint");
      const unsigned int checkpoint_steps = prm.get_integer("Interval");
      const double checkpoint_minutes = prm.get_double("Wall-clock interval");
      prm.leave_subsection();
      const bool checkpoints = checkpoint_steps > 0 || checkpoint_minutes > 0;

      QuasiDynamicFault fault(
        geometry, *law, sigma, tau0, eta, plate_rate, communicator);
      CycleOutput                              output(geometry,
                         station_points,
                         {sampling_change,
                                                       sampling_interval,
                                                       profile_slow,
                                                       profile_fast,
                                                       event_rate},
                         test_mode,
                         communicator);
      TimeIntegration::DormandPrince::Settings tolerance = settings;
      tolerance.absolute_tolerance =
        fault.absolute_tolerances(absolute, absolute);
      TimeIntegration::DormandPrince integrator(
        [&](const double               t,
            const std::vector<double> &v,
            std::vector<double>       &r) { fault.rates(t, v, r); },
        tolerance);

      // The state of the loop, all of it in a checkpoint.
      std::vector<double> y = fault.initial_values();
      double              t = 0, dt = first_step, last_dt = 0;
      double              dt_min = 1e300, dt_max = 0;
      unsigned long       steps = 0, n_events = 0;
      const std::string   directory_name  = prm.get("Output directory");
      const std::string   checkpoint_name = "checkpoint/boundary_integral.bin";
      const std::string   previous_name =
        "checkpoint/boundary_integral.previous.bin";
      const char *const tag = "rupture boundary-integral checkpoint 1";
      if (resume)
        {
          // Rank 0 reads the newest checkpoint (or, if a run was killed
          // between writing one and renaming it, the one before) and
          // sends it to the others.
          std::string path, bytes;
          on_root(communicator, [&]() {
            for (const std::string &name : {checkpoint_name, previous_name})
              {
                path = directory_name + "/" + name;
                std::ifstream file(path, std::ios::binary);
                if (file)
                  {
                    std::ostringstream content;
                    content << file.rdbuf();
                    bytes = content.str();
                    return;
                  }
              }
            AssertThrow(false,
                        ExcMessage("--resume: there is no checkpoint <" +
                                   directory_name + "/" + checkpoint_name +
                                   "> to continue from. A run writes one "
                                   "with <Checkpoint/Interval> or "
                                   "<Wall-clock interval>."));
          });
          path  = dealii::Utilities::MPI::broadcast(communicator, path, 0);
          bytes = dealii::Utilities::MPI::broadcast(communicator, bytes, 0);
          std::istringstream  in(bytes);
          std::string         read_tag;
          std::vector<double> scalars;
          BinaryIO::read(in, read_tag);
          AssertThrow(read_tag == tag,
                      ExcMessage("--resume: <" + path +
                                 "> is not a checkpoint of the "
                                 "boundary-integral method."));
          BinaryIO::read(in, scalars);
          AssertThrow(scalars.size() == 8 && scalars[7] == geometry.size(),
                      ExcMessage("--resume: the checkpoint <" + path +
                                 "> has another number of elements than "
                                 "<Boundary integral/Fault depth> and "
                                 "<Element size> give."));
          t        = scalars[0];
          dt       = scalars[1];
          last_dt  = scalars[2];
          dt_min   = scalars[3];
          dt_max   = scalars[4];
          steps    = static_cast<unsigned long>(scalars[5]);
          n_events = static_cast<unsigned long>(scalars[6]);
          BinaryIO::read(in, y);
          integrator.load(in);
          fault.load(in);
          events.load(in);
          output.load(in);
          AssertThrow(in.good() && y.size() == fault.initial_values().size(),
                      ExcMessage("--resume: the checkpoint <" + path +
                                 "> is damaged."));
        }
      else
        fault.evaluate(0, y);

      // Every input is checked: the output directory.
      Output::Directory::check_name(directory_name, "Output directory");
      Output::Directory directory(directory_name, communicator);
      directory.open(resume);
      on_root(communicator, [&]() {
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
                    << "Boundary-integral method (the review paper's dual "
                       "method): antiplane half-space, "
                    << geometry.size() << " elements of "
                    << geometry.element_length() << " m down to "
                    << geometry.size() * geometry.element_length() / 1e3
                    << " km, mu = " << mu << " Pa, eta = " << eta
                    << " Pa s/m, V_p = " << plate_rate << " m/s; "
                    << dealii::Utilities::MPI::n_mpi_processes(communicator)
                    << " rank(s)\n";
          if (resume)
            std::cout << "  continued from the checkpoint at t = " << t
                      << " s (step " << steps << ")\n";
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
        resume ? steps : std::numeric_limits<unsigned long>::max();
      const auto write_checkpoint = [&]() {
        if (checkpoint_step == steps)
          return; // (This step's is written.)
        std::ostringstream out;
        BinaryIO::write(out, std::string(tag));
        BinaryIO::write(out,
                        std::vector<double>{t,
                                            dt,
                                            last_dt,
                                            dt_min,
                                            dt_max,
                                            double(steps),
                                            double(n_events),
                                            double(geometry.size())});
        BinaryIO::write(out, y);
        integrator.save(out);
        fault.save(out);
        events.save(out);
        on_root(communicator, [&]() {
          output.save(out);
          // The newest and the one before are kept: the new one is
          // written whole under a name of its own, then the newest
          // becomes the one before and the new one the newest (a run
          // killed between the two renames leaves the one before, which
          // --resume takes).
          const std::string writing =
            directory.record("checkpoint/boundary_integral.writing.bin");
          const std::string newest = directory.record(checkpoint_name);
          const std::string before = directory.record(previous_name);
          directory.write("checkpoint/boundary_integral.writing.bin",
                          out.str());
          if (std::filesystem::exists(newest))
            std::filesystem::rename(newest, before);
          std::filesystem::rename(writing, newest);
        });
        checkpoint_step = steps;
        last_checkpoint = std::chrono::steady_clock::now();
      };

      double next_report = (std::floor(10 * t / end_time) + 1) * 0.1 * end_time;
      while (t < end_time)
        {
          last_dt = integrator.advance(t, y, dt, end_time);
          ++steps;
          dt_min = std::min(dt_min, last_dt);
          dt_max = std::max(dt_max, last_dt);
          fault.accept(y, integrator.last_rate());
          const bool ended = events.record(fault, t);
          output.record(t,
                        steps,
                        last_dt,
                        integrator.rejected_steps(),
                        fault,
                        t >= end_time);
          if (ended)
            {
              ++n_events;
              on_root(communicator, [&]() { events.write(fault, directory); });
              if (root)
                std::cout << "  event " << n_events
                          << " ended at t = " << std::setprecision(6)
                          << t / year << " years\n"
                          << std::flush;
            }
          if (root && t >= next_report && t < end_time)
            {
              std::cout << "  t = " << std::setprecision(6) << t / year
                        << " years, " << steps << " steps, max slip rate "
                        << fault.max_slip_rate() << " m/s\n"
                        << std::flush;
              next_report += 0.1 * end_time;
            }
          const bool done = max_events > 0 && n_events >= max_events;
          if (done)
            output.record(
              t, steps, last_dt, integrator.rejected_steps(), fault, true);
          // (Rank 0's clock decides for all.)
          const bool minutes_passed = dealii::Utilities::MPI::max(
            int(checkpoint_minutes > 0 &&
                std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                              last_checkpoint)
                    .count() >= 60 * checkpoint_minutes &&
                root),
            communicator);
          // (SIGUSR1: a checkpoint now, and the run goes on.)
          const bool requested = dealii::Utilities::MPI::max(
            int(Interruption::take_checkpoint_request()), communicator);
          if (requested || (checkpoints && ((checkpoint_steps > 0 &&
                                             steps % checkpoint_steps == 0) ||
                                            minutes_passed)))
            write_checkpoint();
          // (Together: a signal that reached one rank stops all.)
          const int signal =
            dealii::Utilities::MPI::max(Interruption::requested(),
                                        communicator);
          if (signal != 0)
            {
              on_root(communicator, [&]() { events.write(fault, directory); });
              if (checkpoints)
                write_checkpoint();
              throw Interruption::Stopped(
                signal,
                "Stopped by " + Interruption::signal_name(signal) +
                  " at t = " + number(t) + " s (step " + std::to_string(steps) +
                  "); the files written so far hold the run up to there" +
                  (checkpoints ? ", and --resume continues it." : "."));
            }
          if (done)
            break;
        }
      on_root(communicator, [&]() { events.write(fault, directory); });
      if (checkpoints)
        write_checkpoint();
      if (root)
        {
          const double wall = std::chrono::duration<double>(
                                std::chrono::steady_clock::now() - wall_start)
                                .count();
          std::cout << "Ended at t = " << std::setprecision(8) << t << " s ("
                    << t / year << " years) after " << n_events << " event(s)";
          if (!test_mode)
            std::cout << ", " << steps << " steps ("
                      << integrator.rejected_steps()
                      << " rejected), time steps from " << dt_min << " to "
                      << dt_max << " s, " << std::setprecision(3) << wall
                      << " s wall time";
          std::cout << ".\n" << std::flush;
          // What contrib/ reads of a run (as the finite-element runs'
          // summary.json).
          std::ostringstream json;
          json << std::setprecision(12) << "{\n"
               << "  \"status\": \""
               << (t >= end_time ? "finished" : "ended early") << "\",\n"
               << "  \"end\": \""
               << (t >= end_time ? "end time" : "number of events") << "\",\n"
               << "  \"method\": \"boundary integral\",\n"
               << "  \"ranks\": "
               << dealii::Utilities::MPI::n_mpi_processes(communicator) << ",\n"
               << "  \"elements\": " << geometry.size() << ",\n"
               << "  \"steps\": " << steps << ",\n"
               << "  \"rejected steps\": " << integrator.rejected_steps()
               << ",\n"
               << "  \"events\": " << n_events << ",\n"
               << "  \"time\": " << t << ",\n"
               << "  \"smallest time step\": " << dt_min << ",\n"
               << "  \"largest time step\": " << dt_max << ",\n"
               << "  \"wall time\": " << (test_mode ? 0. : wall) << "\n"
               << "}\n";
          directory.write("summary.json", json.str());
        }
    }
  } // namespace BoundaryIntegral
} // namespace rupture
