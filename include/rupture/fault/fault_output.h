#ifndef rupture_fault_fault_output_h
#define rupture_fault_fault_output_h

#include <rupture/fault/event_catalogue.h>
#include <rupture/fault/fault.h>
#include <rupture/output/directory.h>
#include <rupture/output/series.h>

#include <deal.II/base/parameter_handler.h>

#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace rupture
{
  namespace Fault
  {
    /**
     * What the fault writes for the user, all from rank 0:
     * - <output>/fault.pvd with fault/fault_NNNNN.vtu: the fault surface
     *   with slip, slip rate, slip path, friction coefficient, normal and
     *   shear traction, state (0 stick, 1 slip, 2 open) and rupture time;
     * - station time series <output>/<name>.dat at named fault points in the
     *   SCEC format (values interpolated from the fault nodes);
     * - <output>/rupture_time.dat, the rupture-time contour file;
     * - <output>/events.csv, the earthquake catalogue (EventCatalogue), if
     *   asked for.
     *
     * Along-strike (h) and down-dip (v) components use the fault's strike
     * and dip directions; slip is the plus side's displacement minus the
     * minus side's.
     */
    template <int dim>
    class FaultOutput
    {
    public:
      /**
       * Write what a checkpoint keeps of this object to @p out, and read it
       * back (doc/manual.md, "Checkpoints and restart").
       */
      void
      save(std::ostream &out) const;
      void
      load(std::istream &in);
      static void
      declare_parameters(ParameterHandler &prm);

      /**
       * Read "Fault/Output". Throws a clear error for a malformed station.
       */
      void
      parse_parameters(ParameterHandler &prm);

      /**
       * Simulated time (s) between fault surface outputs: negative for
       * none, 0 for every step. <Fault/Output/Output interval> if given,
       * else @p volume_interval.
       */
      double
      surface_interval(const double volume_interval) const;

      /**
       * The stations' names (each writes <name>.dat, beside the fault's
       * rupture_time.dat).
       */
      std::vector<std::string>
      station_names() const
      {
        std::vector<std::string> result;
        for (const auto &s : stations)
          result.push_back(s.name);
        return result;
      }

      /**
       * Locate the stations on the fault (an error names a station that is
       * not on it) and set the strike and dip directions. @p surface is the
       * height of the model's top (its largest last coordinate), from which
       * down-dip distances are measured, positive down, as in SCEC's files,
       * unless <Fault/Output/Down-dip origin> gives another height.
       */
      void
      setup(const Fault<dim> &fault,
            const MPI_Comm    communicator,
            const double      surface);

      /**
       * Keep the stations' rows in scratch files of @p directory (on the
       * process that writes them) instead of in memory.
       */
      void
      keep_series_in(Output::Directory &directory);

      /**
       * Record the station values of the current step, and start, follow
       * or end an event of the catalogue. Collective.
       */
      void
      record(Fault<dim> &fault, const double time);

      /// Whether the run keeps an event catalogue.
      bool
      has_event_catalogue() const
      {
        return events.enabled();
      }

      /// The number of events that have ended (0 without a catalogue).
      unsigned int
      n_events() const
      {
        return events.n_events();
      }

      /**
       * A loading phase starts: its fault surfaces are written as
       * fault/loading_NNNNN.vtu and listed in fault-loading.pvd.
       */
      void
      start_loading_phase();

      /**
       * The dynamic phase starts (after a loading phase): the station time
       * series start anew, with its time as their time 0, and so does the
       * surface time series (fault/fault_NNNNN.vtu in fault.pvd).
       */
      void
      start_dynamic_phase();

      /**
       * Write the fault surface for ParaView.
       */
      void
      write_surface(const Fault<dim>  &fault,
                    Output::Directory &directory,
                    const double       time,
                    const unsigned int step);

      /**
       * Write the station files, the rupture-time contours and the event
       * catalogue. Collective.
       */
      void
      write_tables(const Fault<dim>  &fault,
                   Output::Directory &directory,
                   const double       time_step,
                   const bool         test_mode) const;

    private:
      struct Station
      {
        std::string                          name;
        Point<dim>                           location;
        std::vector<types::global_dof_index> nodes;
        std::vector<double>                  weights;
        Output::Series                       rows;
      };

      double
      strike_component(const Tensor<1, dim> &v) const;
      double
      dip_component(const Tensor<1, dim> &v) const;
      /// The direction of @p v in the fault plane in degrees from the
      /// along-strike direction, positive up-dip (the rake of Aki and
      /// Richards for a slip; 0 where @p v has no component in the plane).
      double
      rake_of(const Tensor<1, dim> &v) const;
      /// The down-dip distance of @p x from the down-dip origin (3-D; 0 in
      /// 2-D):
      /// its depth over the sine of the dip, or, on a horizontal fault,
      /// its distance down-dip from the plane point.
      double
      down_dip_distance(const Point<dim> &x) const;
      /// The text of station @p s in the SCEC SEAS layout; @p state_name
      /// is the law's first state output (empty for a law without state).
      std::string
      seas_station(const Station     &s,
                   const std::string &state_name,
                   const bool         test_mode) const;

      MPI_Comm    communicator;
      std::string station_text;
      std::string strike_text;
      std::string interval_text;
      /// <Station format> = SEAS.
      bool                                              seas_format = false;
      std::string                                       origin_text;
      std::vector<Station>                              stations;
      std::set<types::global_dof_index>                 station_keys;
      Tensor<1, dim>                                    strike;
      Tensor<1, dim>                                    dip;
      Point<dim>                                        origin;
      double                                            surface = 0;
      std::vector<std::vector<types::global_dof_index>> faces;
      std::vector<std::pair<double, std::string>>       records;
      std::string         file_prefix = "fault", pvd_name = "fault.pvd";
      EventCatalogue<dim> events;
    };
  } // namespace Fault
} // namespace rupture

#endif
