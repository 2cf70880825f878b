// The boundary-integral method's run: the time loop of the Dormand-Prince
// pair and the cycle outputs as they grow.

#include <rupture/base/interruption.h>
#include <rupture/base/utilities.h>
#include <rupture/boundary_integral/quasi_dynamic_fault.h>
#include <rupture/boundary_integral/simulation.h>
#include <rupture/fault/event_catalogue.h>
#include <rupture/friction/interface.h>
#include <rupture/output/directory.h>
#include <rupture/output/seas_format.h>
#include <rupture/time_integration/dormand_prince.h>

#include <deal.II/base/function_parser.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
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

      /// A station: the element above its depth and the weight of the one
      /// below (linear interpolation between centres).
      struct Station
      {
        std::string   name;
        double        depth   = 0;
        unsigned int  element = 0;
        double        weight  = 0;
        std::ofstream file;
      };

      std::string
      number(const double x)
      {
        std::ostringstream s;
        s << std::setprecision(10) << x;
        return s.str();
      }
    } // namespace



    void
    run(ParameterHandler &prm, const MPI_Comm communicator)
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
      const unsigned int max_events =
        prm.get_integer("Maximum number of events");
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

      QuasiDynamicFault   fault(geometry,
                              *law,
                              sigma,
                              tau0,
                              std::vector<double>(geometry.size(), plate_rate),
                              eta,
                              plate_rate,
                              communicator);
      std::vector<double> y = fault.initial_values();
      fault.evaluate(0, y);
      double initial_slowest = 1e300, initial_fastest = 0;
      for (unsigned int i = 0; i < geometry.size(); ++i)
        {
          initial_slowest = std::min(initial_slowest, fault.slip_rate(i));
          initial_fastest = std::max(initial_fastest, fault.slip_rate(i));
        }
      std::vector<Station> stations;
      for (const auto &[name, point] : station_points)
        {
          AssertThrow(std::abs(point[0]) < 1e-6 && point[1] <= 0 &&
                        -point[1] <=
                          geometry.size() * geometry.element_length(),
                      ExcMessage("The station <" + name +
                                 "> of <Fault/Output/Stations> is not on "
                                 "the fault: with <Method> = boundary "
                                 "integral the fault is x = 0 between the "
                                 "depths 0 and <Fault depth> (y from 0 down "
                                 "to -W), e.g. 'bp1_st050: 0, -5000'."));
          Station s;
          s.name               = name;
          s.depth              = -point[1];
          const unsigned int n = geometry.size();
          const double       position =
            std::clamp(s.depth / geometry.element_length() - 0.5, 0., n - 1.);
          s.element = n > 1 ? std::min<unsigned int>(position, n - 2) : 0;
          s.weight  = n > 1 ? position - s.element : 0.;
          stations.push_back(std::move(s));
        }

      // Every input is checked: the output directory.
      const std::string directory_name = prm.get("Output directory");
      Output::Directory::check_name(directory_name, "Output directory");
      Output::Directory directory(directory_name, communicator);
      directory.open();
      std::ofstream statistics, profiles;
      if (root)
        {
          std::ostringstream parameters;
          prm.print_parameters(parameters, ParameterHandler::ShortPRM);
          directory.write("parameters.prm", parameters.str());
          statistics.open(directory.record("statistics.dat"));
          statistics << "# rupture, boundary-integral method: one row per "
                        "sampled step\n"
                     << "# 1: Step\n# 2: Time (s)\n# 3: Time step (s)\n"
                     << "# 4: Maximum slip rate (m/s)\n"
                     << "# 5: Rejected steps (so far)\n"
                     << std::scientific << std::setprecision(10);
          for (auto &s : stations)
            {
              s.file.open(directory.record(s.name + ".dat"));
              s.file << Output::seas_station_header("on fault, " +
                                                      number(s.depth / 1e3) +
                                                      " km depth",
                                                    test_mode)
                     << std::scientific << std::setprecision(7);
            }
          if (profile_slow > 0 || profile_fast > 0)
            {
              profiles.open(directory.record("slip_profiles.dat"));
              profiles << "# Slip profiles: the first row holds 0, 0 and "
                          "the depths (m) of the element centres; each "
                          "further row t (s), the log10 of the largest slip "
                          "rate (m/s), and the slip (m) at those depths.\n"
                       << std::scientific << std::setprecision(7) << "0 0";
              for (unsigned int i = 0; i < geometry.size(); ++i)
                profiles << " " << geometry.centre(i);
              profiles << "\n";
            }
        }

      std::cout << std::flush;
      if (root)
        std::cout << "Boundary-integral method (the review paper's dual "
                     "method): antiplane half-space, "
                  << geometry.size() << " elements of "
                  << geometry.element_length() << " m down to "
                  << geometry.size() * geometry.element_length() / 1e3
                  << " km, mu = " << mu << " Pa, eta = " << eta
                  << " Pa s/m, V_p = " << plate_rate << " m/s; "
                  << dealii::Utilities::MPI::n_mpi_processes(communicator)
                  << " rank(s)\n"
                  << "  initial slip rates from " << initial_slowest << " to "
                  << initial_fastest << " m/s\n"
                  << std::flush;

      TimeIntegration::DormandPrince::Settings tolerance = settings;
      tolerance.absolute_tolerance =
        fault.absolute_tolerances(absolute, absolute);
      TimeIntegration::DormandPrince integrator(
        [&](const double               t,
            const std::vector<double> &v,
            std::vector<double>       &r) { fault.rates(t, v, r); },
        tolerance);

      // Outputs at an accepted state.
      double last_row_rate = -1, last_row_time = 0;
      double last_profile = -1e300;
      // The step of the last row and of the last profile (a forced row
      // is not written twice).
      long          rows_step = -1, profile_step = -1;
      unsigned long steps  = 0;
      double        dt_min = 1e300, dt_max = 0, last_dt = 0;
      const auto    write_rows = [&](const double t, const bool force) {
        const double vmax = fault.max_slip_rate();
        const double change =
          std::abs(std::log10(std::max(vmax, 1e-300)) -
                   std::log10(std::max(last_row_rate, 1e-300)));
        if ((force || sampling_change == 0 || change >= sampling_change ||
             t - last_row_time >= sampling_interval) &&
            rows_step != long(steps))
          {
            rows_step     = steps;
            last_row_rate = vmax;
            last_row_time = t;
            if (root)
              {
                statistics << steps << " " << t << " " << last_dt << " " << vmax
                           << " " << integrator.rejected_steps() << "\n";
                for (auto &s : stations)
                  {
                    const unsigned int i = s.element;
                    const unsigned int j =
                      std::min<unsigned int>(i + 1, fault.size() - 1);
                    const auto mix = [&](const double a, const double b) {
                      return (1 - s.weight) * a + s.weight * b;
                    };
                    const double state = mix(std::log10(fault.state(i)),
                                             std::log10(fault.state(j)));
                    s.file << Output::seas_station_row(
                      t,
                      mix(fault.slip(i), fault.slip(j)),
                      mix(fault.slip_rate(i), fault.slip_rate(j)),
                      mix(fault.shear_stress(i), fault.shear_stress(j)) / 1e6,
                      state);
                  }
              }
          }
        const double interval =
          vmax >= event_rate ? profile_fast : profile_slow;
        if (root && profiles.is_open() &&
            (force || (interval > 0 && t - last_profile >= interval)) &&
            profile_step != long(steps))
          {
            profile_step = steps;
            last_profile = t;
            profiles << t << " " << std::log10(std::max(vmax, 1e-300));
            for (unsigned int i = 0; i < fault.size(); ++i)
              profiles << " " << fault.slip(i);
            profiles << "\n";
          }
      };
      write_rows(0, true);


      double       t = 0, dt = first_step;
      unsigned int n_events    = 0;
      double       next_report = 0.1 * end_time;
      while (t < end_time)
        {
          last_dt = integrator.advance(t, y, dt, end_time);
          ++steps;
          dt_min = std::min(dt_min, last_dt);
          dt_max = std::max(dt_max, last_dt);
          fault.evaluate(t, y);
          const bool ended = events.record(fault, t);
          write_rows(t, t >= end_time);
          if (ended)
            {
              ++n_events;
              events.write(fault, directory);
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
          if (Interruption::requested() != 0)
            {
              events.write(fault, directory);
              throw Interruption::Stopped(Interruption::requested(),
                                          "Stopped by " +
                                            Interruption::signal_name(
                                              Interruption::requested()) +
                                            " at t = " + number(t) +
                                            " s; the files written so far "
                                            "hold the run up to there.");
            }
          if (max_events > 0 && n_events >= max_events)
            {
              write_rows(t, true);
              break;
            }
        }
      events.write(fault, directory);
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
