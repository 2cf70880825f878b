#ifndef rupture_output_output_schedule_h
#define rupture_output_output_schedule_h

#include <rupture/base/binary_io.h>

namespace rupture
{
  namespace Output
  {
    /**
     * When a run writes what: volume snapshots and fault surfaces every
     * so many seconds of the phase's clock, a line on the screen every so
     * many steps, and the tables (statistics, stations, receivers) at
     * least once a minute of wall time.
     */
    struct OutputSchedule
    {
      /// <Output/Output interval> (s; negative: no volume snapshots).
      double interval = 0;
      /// <Fault/Output/Output interval> (s; negative: no fault surfaces).
      double fault_interval = -1;
      /// <Output/Screen output interval> (steps).
      unsigned int screen_interval = 1;
      /// The phase time of the next volume snapshot and fault surface.
      double next_output_time       = 0;
      double next_fault_output_time = 0;
      /// Wall time (MPI_Wtime) of the last write of the tables.
      double last_table_write = 0;

      /// The times of the next outputs as named checkpoint records.
      void
      save(BinaryIO::Records &records) const
      {
        records["output/next output time"]       = next_output_time;
        records["output/next fault output time"] = next_fault_output_time;
      }
      void
      load(const BinaryIO::Records &records)
      {
        next_output_time = BinaryIO::record(records, "output/next output time");
        next_fault_output_time =
          BinaryIO::record(records, "output/next fault output time");
      }
    };
  } // namespace Output
} // namespace rupture

#endif
