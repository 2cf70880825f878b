// The event catalogue of a run (events.csv).

#include <rupture/base/binary_io.h>
#include <rupture/fault/event_catalogue.h>
#include <rupture/output/directory.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace rupture
{
  namespace Fault
  {
    template <int dim>
    void
    EventCatalogue<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Event catalogue",
        "false",
        Patterns::Bool(),
        "Write <output>/events.csv: one row per earthquake, an event being "
        "an interval in which the fault's largest frictional slip rate is "
        "at least <Event slip rate>, with its start and end time (s and "
        "years), duration, hypocentre, peak slip rate, seismic moment (N "
        "per metre of strike in 2-D), Mw (3-D), ruptured area (length in "
        "2-D), mean and largest slip. Rewritten when an event ends and at "
        "the end of the run (an event still going is marked incomplete). "
        "For earthquake cycles; not with <Mesh refinement>.");
      prm.declare_entry("Event slip rate",
                        "1e-3",
                        Patterns::Double(0),
                        "The slip rate (m/s, > 0) above which the fault is "
                        "in an event, 1 mm/s as in the SCEC SEAS "
                        "benchmarks.");
      prm.declare_entry(
        "Event end slip rate",
        "0",
        Patterns::Double(0),
        "The slip rate (m/s) below which an event ends: 0 for <Event slip "
        "rate> itself (the SEAS definition); less than it, an event ends "
        "only when the largest slip rate has fallen below this, so that "
        "waves or afterslip that hover about <Event slip rate> after an "
        "event do not count as events of their own (fully dynamic cycles, "
        "<Boundary integral/Events>).");
    }



    template <int dim>
    void
    EventCatalogue<dim>::parse_parameters(ParameterHandler &prm)
    {
      is_enabled = prm.get_bool("Event catalogue");
      threshold  = prm.get_double("Event slip rate");
      AssertThrow(threshold > 0 && std::isfinite(threshold),
                  ExcMessage("<Fault/Output/Event slip rate> is " +
                             prm.get("Event slip rate") +
                             ", but it must be > 0 (m/s)."));
      end_threshold = prm.get_double("Event end slip rate");
      AssertThrow(std::isfinite(end_threshold) && end_threshold <= threshold,
                  ExcMessage("<Fault/Output/Event end slip rate> is " +
                             prm.get("Event end slip rate") +
                             ", but it must lie between 0 (the same as "
                             "<Event slip rate>) and <Event slip rate> = " +
                             prm.get("Event slip rate") + " m/s."));
      if (end_threshold == 0)
        end_threshold = threshold;
    }



    template <int dim>
    bool
    EventCatalogue<dim>::record(EventSource<dim> &fault, const double time)
    {
      if (!is_enabled)
        return false;
      last_time                   = time;
      const auto [rate, location] = fault.fastest_pair();
      if (!open)
        {
          if (rate >= threshold)
            {
              open       = true;
              start      = time;
              hypocentre = location;
              fault.start_event();
            }
          return false;
        }
      fault.track_event();
      if (rate >= end_threshold)
        return false;
      rows.push_back(row(fault.event_summary(threshold), time, true));
      open = false;
      return true;
    }



    template <int dim>
    std::vector<double>
    EventCatalogue<dim>::row(const EventSummary<dim> &s,
                             const double             end,
                             const bool               complete) const
    {
      std::vector<double> r = {
        double(rows.size() + 1), start, start / 3.15576e7, end, end - start};
      for (unsigned int d = 0; d < dim; ++d)
        r.push_back(hypocentre[d]);
      r.push_back(s.peak_rate);
      r.push_back(s.moment);
      if (dim == 3)
        r.push_back(s.moment > 0 ? 2. / 3. * (std::log10(s.moment) - 9.1) : 0.);
      r.push_back(s.area);
      r.push_back(s.area > 0 ? s.slip_area / s.area : 0.);
      r.push_back(s.largest_slip);
      r.push_back(complete ? 1 : 0);
      return r;
    }



    template <int dim>
    void
    EventCatalogue<dim>::write(const EventSource<dim> &fault,
                               Output::Directory      &directory) const
    {
      if (!is_enabled)
        return;
      // (Collective: the open event's summary.)
      std::vector<std::vector<double>> all = rows;
      if (open)
        all.push_back(row(fault.event_summary(threshold), last_time, false));
      if (dealii::Utilities::MPI::this_mpi_process(fault.mpi_communicator()) !=
          0)
        return;
      std::ostringstream out;
      out << "# Earthquakes of the run: intervals in which the largest "
             "frictional slip rate is at least "
          << threshold << " m/s";
      if (end_threshold != threshold)
        out << " (ending when it falls below " << end_threshold << " m/s)";
      out << ". Times since the start of the phase.\n";
      out << "event,start (s),start (years),end (s),duration (s),"
          << (dim == 2 ? "hypocentre x (m),hypocentre y (m)," :
                         "hypocentre x (m),hypocentre y (m),hypocentre z (m),")
          << "peak slip rate (m/s),"
          << (dim == 2 ? "moment (N/m)," : "moment (N m),Mw,")
          << (dim == 2 ? "ruptured length (m)," : "ruptured area (m^2),")
          << "mean slip (m),largest slip (m),complete\n";
      out << std::setprecision(10);
      for (const auto &r : all)
        for (unsigned int i = 0; i < r.size(); ++i)
          {
            if (i == 0 || i + 1 == r.size())
              out << static_cast<long long>(r[i]);
            else
              out << r[i];
            out << (i + 1 == r.size() ? "\n" : ",");
          }
      directory.write("events.csv", out.str());
    }



    template <int dim>
    void
    EventCatalogue<dim>::save(std::ostream &out) const
    {
      std::vector<double> scalars = {double(open), start, last_time};
      for (unsigned int d = 0; d < dim; ++d)
        scalars.push_back(hypocentre[d]);
      BinaryIO::write(out, scalars);
      BinaryIO::write(out, rows);
    }



    template <int dim>
    void
    EventCatalogue<dim>::load(std::istream &in)
    {
      std::vector<double> scalars;
      BinaryIO::read(in, scalars);
      AssertThrow(scalars.size() == 3 + dim,
                  ExcMessage("The checkpoint's event catalogue is damaged."));
      open      = scalars[0] != 0;
      start     = scalars[1];
      last_time = scalars[2];
      for (unsigned int d = 0; d < dim; ++d)
        hypocentre[d] = scalars[3 + d];
      BinaryIO::read(in, rows);
    }



    template class EventCatalogue<2>;
    template class EventCatalogue<3>;
  } // namespace Fault
} // namespace rupture
