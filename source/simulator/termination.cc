#include <rupture/base/binary_io.h>
#include <rupture/simulator/termination.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>
#include <utility>

namespace rupture
{
  namespace Termination
  {
    using namespace dealii;

    namespace
    {
      /// A number as the messages print it: 6 significant digits.
      std::string
      number(const double x)
      {
        std::ostringstream s;
        s.precision(6);
        s << x;
        return s.str();
      }
    } // namespace



    std::string
    name(const Reason reason)
    {
      switch (reason)
        {
          case Reason::end_time:
            return "end time";
          case Reason::rupture_died:
            return "rupture died";
          case Reason::steady_state:
            return "steady state";
          case Reason::runaway:
            return "runaway";
          case Reason::events:
            return "number of events";
          case Reason::wall_clock:
            return "wall-clock limit";
        }
      return "end time";
    }



    void
    Criteria::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Termination");
      {
        prm.declare_entry(
          "Slip rate threshold",
          "1e-3",
          Patterns::Double(0),
          "Slip rate (m/s) above which the fault counts as slipping "
          "seismically, for <Rupture died after>: the rupture has begun once "
          "the largest slip rate on the fault exceeded it (1 mm/s, the "
          "threshold of the rupture time, by default).");
        prm.declare_entry(
          "Rupture died after",
          "0",
          Patterns::Double(0),
          "End the run once the rupture has begun and then the largest slip "
          "rate on the fault has stayed below <Slip rate threshold> for "
          "this long (s of simulated time): the rupture has died, and what "
          "follows is waves leaving the model. 0 switches it off. It needs "
          "a fault and watches the dynamic phase (the only phase without a "
          "loading phase).");
        prm.declare_entry(
          "Steady state window",
          "0",
          Patterns::Double(0),
          "End the run once, over the last this many seconds of simulated "
          "time, the kinetic energy, and with a fault the largest slip rate "
          "and the mean shear traction on the fault, each varied by less "
          "than <Steady state tolerance> times its largest magnitude in "
          "the phase (so a quantity that has decayed to a small fraction of "
          "its peak counts as steady too). 0 switches it off.");
        prm.declare_entry("Steady state tolerance",
                          "1e-3",
                          Patterns::Double(0),
                          "Relative variation below which <Steady state "
                          "window> counts a quantity as steady.");
        prm.declare_entry(
          "Maximum seismic moment",
          "0",
          Patterns::Double(0),
          "End the run as a runaway rupture once the seismic moment exceeds "
          "this (N m; N per m of fault in 2-D). 0 switches it off.");
        prm.declare_entry("Maximum slip",
                          "0",
                          Patterns::Double(0),
                          "End the run as a runaway rupture once the largest "
                          "slip on the fault exceeds this (m). 0 switches it "
                          "off.");
        prm.declare_entry(
          "Maximum slipping area",
          "0",
          Patterns::Double(0),
          "End the run as a runaway rupture once the area slipping at once "
          "exceeds this (m^2; m in 2-D). 0 switches it off.");
        prm.declare_entry(
          "Number of events",
          "0",
          Patterns::Integer(0),
          "End the run once the event catalogue holds this many events "
          "(earthquakes that have ended, <Fault/Output/Event catalogue>, "
          "which it needs): earthquake cycles. 0 switches it off. With "
          "<Method> = boundary integral too.");
        prm.declare_entry(
          "Wall-clock limit",
          "0",
          Patterns::Double(0),
          "End the run, with all its output written, once it has run this "
          "many minutes of wall-clock time (checked after every step, so "
          "leave a step's time and the last output's to spare before a "
          "batch system's limit). 0 switches it off.");
      }
      prm.leave_subsection();
    }



    void
    Criteria::parse_parameters(ParameterHandler &prm, const bool has_fault)
    {
      prm.enter_subsection("Termination");
      slip_rate_threshold = prm.get_double("Slip rate threshold");
      died_after          = prm.get_double("Rupture died after");
      steady_window       = prm.get_double("Steady state window");
      steady_tolerance    = prm.get_double("Steady state tolerance");
      max_moment          = prm.get_double("Maximum seismic moment");
      max_slip            = prm.get_double("Maximum slip");
      max_area            = prm.get_double("Maximum slipping area");
      wall_clock_minutes  = prm.get_double("Wall-clock limit");
      max_events          = prm.get_integer("Number of events");
      prm.leave_subsection();

      const std::pair<const char *, double> values[] = {
        {"Slip rate threshold", slip_rate_threshold},
        {"Rupture died after", died_after},
        {"Steady state window", steady_window},
        {"Steady state tolerance", steady_tolerance},
        {"Maximum seismic moment", max_moment},
        {"Maximum slip", max_slip},
        {"Maximum slipping area", max_area},
        {"Wall-clock limit", wall_clock_minutes}};
      for (const auto &[entry, value] : values)
        AssertThrow(std::isfinite(value),
                    ExcMessage(std::string("<Termination/") + entry +
                               "> must be a finite number >= 0 (0 switches "
                               "it off), not " +
                               number(value) + "."));
      AssertThrow(died_after == 0 || slip_rate_threshold > 0,
                  ExcMessage("<Termination/Rupture died after> needs a "
                             "<Termination/Slip rate threshold> above 0 "
                             "(m/s), e.g. 1e-3."));
      AssertThrow(steady_window == 0 ||
                    (steady_tolerance > 0 && steady_tolerance < 1),
                  ExcMessage("<Termination/Steady state tolerance> must be "
                             "between 0 and 1 (a relative variation), not " +
                             number(steady_tolerance) + "."));
      if (!has_fault)
        for (const auto &[entry, value] :
             {std::pair<const char *, double>{"Rupture died after", died_after},
              {"Maximum seismic moment", max_moment},
              {"Maximum slip", max_slip},
              {"Maximum slipping area", max_area},
              {"Number of events", double(max_events)}})
          AssertThrow(value == 0,
                      ExcMessage(std::string("<Termination/") + entry +
                                 "> watches the fault, but this run has "
                                 "none (<Fault/Model> is 'none'). Set it to "
                                 "0, or add a fault."));
    }



    bool
    Criteria::any() const
    {
      return died_after > 0 || steady_window > 0 || max_moment > 0 ||
             max_slip > 0 || max_area > 0 || wall_clock_minutes > 0 ||
             max_events > 0;
    }



    bool
    Criteria::uses_wall_clock() const
    {
      return wall_clock_minutes > 0;
    }



    std::string
    Criteria::description() const
    {
      std::ostringstream s;
      if (died_after > 0)
        s << "; the rupture has died (slip rate below "
          << number(slip_rate_threshold) << " m/s for " << number(died_after)
          << " s)";
      if (steady_window > 0)
        s << "; steady state (variation below " << number(steady_tolerance)
          << " over " << number(steady_window) << " s)";
      if (max_moment > 0)
        s << "; seismic moment above " << number(max_moment);
      if (max_slip > 0)
        s << "; slip above " << number(max_slip) << " m";
      if (max_area > 0)
        s << "; slipping area above " << number(max_area);
      if (max_events > 0)
        s << "; " << max_events << " events";
      if (wall_clock_minutes > 0)
        s << "; " << number(wall_clock_minutes) << " min of wall-clock time";
      const std::string text = s.str();
      return text.empty() ? text : "   Ends early when" + text.substr(1);
    }



    void
    Criteria::start_phase(const bool watched_phase)
    {
      watched       = watched_phase;
      rupture_began = false;
      largest[0] = largest[1] = largest[2] = 0;
      started                              = false;
      window.clear();
    }



    Reason
    Criteria::check(const Sample &sample, std::string &message)
    {
      if (wall_clock_minutes > 0 &&
          sample.wall_seconds >= 60 * wall_clock_minutes)
        {
          message = "the wall-clock limit of " + number(wall_clock_minutes) +
                    " min (<Termination/Wall-clock limit>) was reached.";
          return Reason::wall_clock;
        }
      if (!watched)
        return Reason::end_time;
      if (!started)
        {
          started     = true;
          phase_start = sample.time;
        }

      if (max_events > 0 && sample.events >= max_events)
        {
          message = std::to_string(max_events) +
                    " events have ended (<Termination/Number of events>).";
          return Reason::events;
        }

      const std::tuple<double, double, const char *, const char *> limits[] = {
        {sample.seismic_moment,
         max_moment,
         "the seismic moment",
         "Maximum seismic moment"},
        {sample.max_slip, max_slip, "the largest slip", "Maximum slip"},
        {sample.slipping_area,
         max_area,
         "the slipping area",
         "Maximum slipping area"}};
      for (const auto &[value, limit, what, entry] : limits)
        if (limit > 0 && value > limit)
          {
            message = "the rupture ran away: " + std::string(what) + " " +
                      number(value) + " exceeds <Termination/" + entry +
                      "> = " + number(limit) + ".";
            return Reason::runaway;
          }

      if (died_after > 0)
        {
          if (sample.max_slip_rate > slip_rate_threshold)
            {
              rupture_began = true;
              quiet_since   = sample.time;
            }
          else if (rupture_began && sample.time - quiet_since >= died_after)
            {
              message = "the rupture died: the largest slip rate has stayed "
                        "below " +
                        number(slip_rate_threshold) +
                        " m/s since t = " + number(quiet_since) +
                        " s (<Termination/Rupture died "
                        "after> = " +
                        number(died_after) + " s).";
              return Reason::rupture_died;
            }
        }

      if (steady_window > 0)
        {
          for (unsigned int k = 0; k < 3; ++k)
            largest[k] = std::max(largest[k], std::abs(sample.*quantities[k]));
          window.push_back(sample);
          while (window.size() > 1 &&
                 sample.time - window[1].time >= steady_window)
            window.pop_front();
          if (sample.time - phase_start >= steady_window &&
              sample.time - window.front().time >= steady_window)
            {
              bool steady = true;
              for (unsigned int k = 0; k < 3; ++k)
                {
                  const auto q   = quantities[k];
                  double     low = window.front().*q, high = low;
                  for (const Sample &s : window)
                    {
                      low  = std::min(low, s.*q);
                      high = std::max(high, s.*q);
                    }
                  steady =
                    steady && (high - low <= steady_tolerance * largest[k]);
                }
              if (steady)
                {
                  message = "steady state: over the last " +
                            number(steady_window) +
                            " s the kinetic energy, the largest slip rate "
                            "and the mean shear traction varied by less "
                            "than " +
                            number(steady_tolerance) +
                            " of their largest size (<Termination/Steady "
                            "state window>).";
                  return Reason::steady_state;
                }
            }
        }
      return Reason::end_time;
    }
    void
    Criteria::save(std::ostream &out) const
    {
      std::vector<double> flags = {double(watched),
                                   double(rupture_began),
                                   quiet_since,
                                   phase_start,
                                   double(started),
                                   largest[0],
                                   largest[1],
                                   largest[2]};
      BinaryIO::write(out, flags);
      std::vector<std::vector<double>> samples;
      for (const Sample &s : window)
        samples.push_back({s.time,
                           s.wall_seconds,
                           s.kinetic_energy,
                           s.max_slip_rate,
                           s.mean_shear_traction,
                           s.seismic_moment,
                           s.max_slip,
                           s.slipping_area});
      BinaryIO::write(out, samples);
    }



    void
    Criteria::load(std::istream &in)
    {
      std::vector<double> flags;
      BinaryIO::read(in, flags);
      AssertThrow(flags.size() == 8,
                  ExcMessage("The checkpoint's termination state is "
                             "damaged."));
      watched       = flags[0] != 0;
      rupture_began = flags[1] != 0;
      quiet_since   = flags[2];
      phase_start   = flags[3];
      started       = flags[4] != 0;
      for (unsigned int k = 0; k < 3; ++k)
        largest[k] = flags[5 + k];
      std::vector<std::vector<double>> samples;
      BinaryIO::read(in, samples);
      window.clear();
      for (const auto &v : samples)
        {
          AssertThrow(v.size() == 8,
                      ExcMessage("The checkpoint's termination state is "
                                 "damaged."));
          window.push_back(
            Sample{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]});
        }
    }

  } // namespace Termination
} // namespace rupture
