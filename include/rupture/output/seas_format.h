#ifndef rupture_output_seas_format_h
#define rupture_output_seas_format_h

#include <cmath>
#include <string>

namespace rupture
{
  namespace Output
  {
    /**
     * The header of a fault station file in the layout of the SCEC SEAS
     * (earthquake cycle) benchmarks: the comment lines (the location as
     * @p location, e.g. "on fault, 0 km along strike, 7.5 km down-dip";
     * no date in @p test_mode), the column names and the line that opens
     * the data; with @p normal_stress a column of the normal stress (MPa)
     * before the state's (SEAS BP3, where it changes with the slip).
     */
    std::string
    seas_station_header(const std::string &location,
                        const bool         test_mode,
                        const bool         normal_stress = false);

    /**
     * One data row of such a file: the time (s, 15 digits), the slip (m,
     * and the rest with 8), the log10
     * of the magnitude of the slip rate @p rate (m/s; -300 where it is 0),
     * the shear stress (MPa), the normal stress (MPa; only where
     * @p normal_stress is not NaN) and the log10 of the state (s).
     */
    std::string
    seas_station_row(const double time,
                     const double slip,
                     const double rate,
                     const double shear_stress,
                     const double log10_state,
                     const double normal_stress = std::nan(""));
  } // namespace Output
} // namespace rupture

#endif
