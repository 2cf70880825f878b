#ifndef rupture_boundary_integral_cycle_output_h
#define rupture_boundary_integral_cycle_output_h

#include <rupture/boundary_integral/quasi_dynamic_fault.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <fstream>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace rupture
{
  namespace Output
  {
    class Directory;
  }

  namespace BoundaryIntegral
  {
    /**
     * The distance down the fault of the station @p name at @p point on
     * the fault that dips at @p dip degrees from (0, 0) down to the
     * distance @p extent (on a vertical fault: the depth -y); throws with
     * a message naming <Fault/Output/Stations> where the point is not on
     * it (within a metre on a dipping fault).
     */
    double
    station_distance(const std::string &name,
                     const Point<2>    &point,
                     const double       dip,
                     const double       extent);

    /**
     * The series of a boundary-integral cycle run, appended to their files
     * as the run goes (never held in memory; rank 0 writes):
     * - statistics.dat: step, time, time step, largest slip rate, rejected
     *   steps so far;
     * - <station>.dat: the SEAS station files (t, slip, log10 slip rate,
     *   shear stress in MPa, the normal stress in MPa where the slip
     *   changes it, log10 state), interpolated linearly between the
     *   element centres;
     * - slip_profiles.dat: the slip at every element (a first row of their
     *   depths);
     * - <surface station>.dat: the displacement and velocity (x and y) of
     *   the body's surface points (Stiffness::surface_motion(), named and
     *   placed by @p surface_points), with the fault stations' rows.
     * The statistics and stations get a row after a step when the log10 of
     * the largest slip rate has changed by the sampling tolerance since the
     * last row or the sampling interval has passed (every step with a
     * tolerance of 0); the profiles every <between> seconds outside events
     * and every <during> seconds in them. A checkpoint records where each
     * file ends (save()); a continued run cuts the files back to it.
     */
    class CycleOutput
    {
    public:
      struct Sampling
      {
        double rate_change     = 0;
        double interval        = 0;
        double profile_between = 0;
        double profile_during  = 0;
        double event_rate      = 1e-3;
      };

      /**
       * Check the stations (named points (x, y) on the fault of
       * @p geometry: (0, -depth) on a vertical fault; the message names
       * <Fault/Output/Stations>).
       */
      CycleOutput(const Stiffness                                     &geometry,
                  const std::vector<std::pair<std::string, Point<2>>> &stations,
                  const Sampling                                      &sampling,
                  const bool     test_mode,
                  const MPI_Comm communicator,
                  const std::vector<std::pair<std::string, Point<2>>>
                              &surface_points = {},
                  const double plate_rate     = 0);

      /// The name of the stations' state column: the friction law's first
      /// state output (QuasiDynamicFault::state_name()), set before open().
      std::string state_name = "log10_theta";

      /**
       * Open the files in @p directory: with their headers, or
       * (@p continuing) cut back to the lengths that load() read.
       */
      void
      open(Output::Directory &directory, const bool continuing);

      /**
       * After the accepted step @p step (of length @p dt, @p rejected steps
       * rejected so far) to time @p t: the rows that are due (@p force: the
       * statistics and station rows and a profile now, unless this step has
       * them already).
       */
      void
      record(const double             t,
             const unsigned long      step,
             const double             dt,
             const unsigned long      rejected,
             const QuasiDynamicFault &fault,
             const bool               force);

      /// Flush the files and write their lengths and the sampling state.
      void
      save(std::ostream &out);
      void
      load(std::istream &in);

    private:
      struct Station
      {
        std::string   name;
        double        depth   = 0;
        unsigned int  element = 0;
        double        weight  = 0;
        std::ofstream file;
        std::string   path;
      };

      /// Open @p file at @p path: a new file, or the old one cut back to
      /// @p length bytes. Returns the stream, positioned at its end.
      void
      open_file(std::ofstream      &file,
                const std::string  &path,
                const bool          continuing,
                const std::uint64_t length);

      const Stiffness &geometry;
      /// Whether the stations get a normal-stress column (the body
      /// couples it to the slip).
      const bool           normal_stress;
      const Sampling       sampling;
      const bool           test_mode;
      const bool           root;
      std::vector<Station> stations;
      /// The surface stations (their element is the body's surface point).
      std::vector<Station> surface_stations;
      const double         plate_rate;
      /// Scratch: the fault's values relative to the plate's.
      std::vector<double> relative;
      std::ofstream       statistics, profiles;
      std::string         statistics_path, profiles_path;
      // The sampling state.
      double last_row_rate = -1, last_row_time = 0, last_profile = -1e300;
      long   rows_step = -1, profile_step = -1;
      /// The lengths of the files (statistics, profiles, stations) that
      /// load() read.
      std::vector<std::uint64_t> lengths;
    };
  } // namespace BoundaryIntegral
} // namespace rupture

#endif
