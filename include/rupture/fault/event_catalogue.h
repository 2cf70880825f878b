#ifndef rupture_fault_event_catalogue_h
#define rupture_fault_event_catalogue_h

#include <rupture/fault/event_source.h>

#include <deal.II/base/parameter_handler.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace rupture
{
  namespace Output
  {
    class Directory;
  }

  namespace Fault
  {
    /**
     * The catalogue of a run's earthquakes, <output>/events.csv: an event
     * lasts while the fault's largest frictional slip rate is at least
     * <Fault/Output/Event slip rate> (1 mm/s, the SCEC SEAS definition).
     * One row per event, rewritten whole when an event ends and at the end
     * of the run (an event still going is marked incomplete): its number,
     * start and end time (s, and years), duration, hypocentre (the point of
     * the largest slip rate at the start), peak slip rate, seismic moment
     * (N m; N per metre of strike in 2-D), Mw (3-D), ruptured area (m^2; m
     * in 2-D: the pairs whose slip rate reached the threshold), and the
     * mean (over that area) and largest slip of the event.
     *
     * The per-point part (each point's slip at the event's start and its
     * peak slip rate) belongs to the fault (EventSource: the finite-element
     * Fault or the boundary-integral fault); this object keeps the rows and
     * the open event, and a checkpoint keeps both (the rows are few).
     */
    template <int dim>
    class EventCatalogue
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      /// Read <Fault/Output/Event catalogue> and <Event slip rate>; call
      /// inside <Fault/Output>.
      void
      parse_parameters(ParameterHandler &prm);

      bool
      enabled() const
      {
        return is_enabled;
      }

      /// The number of events that have ended.
      unsigned int
      n_events() const
      {
        return rows.size();
      }

      /**
       * After each accepted step at phase time @p time: start, follow or
       * end an event. Returns whether an event ended (the table is then
       * due). Collective.
       */
      bool
      record(EventSource<dim> &fault, const double time);

      /**
       * Write events.csv (rank 0), with the open event as incomplete.
       */
      void
      write(const EventSource<dim> &fault, Output::Directory &directory) const;

      void
      save(std::ostream &out) const;
      void
      load(std::istream &in);

    private:
      /// One row of the table.
      std::vector<double>
      row(const EventSummary<dim> &summary,
          const double             end,
          const bool               complete) const;

      bool   is_enabled = false;
      double threshold  = 1e-3;
      /// <Event end slip rate> (the threshold where it is 0).
      double end_threshold = 1e-3;
      /// The open event: its start time and hypocentre.
      bool                             open  = false;
      double                           start = 0;
      Point<dim>                       hypocentre;
      std::vector<std::vector<double>> rows;
      double                           last_time = 0;
    };
  } // namespace Fault
} // namespace rupture

#endif
