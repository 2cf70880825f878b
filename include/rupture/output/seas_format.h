#ifndef rupture_output_seas_format_h
#define rupture_output_seas_format_h

#include <array>
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
     * before the state's (SEAS BP3, where it changes with the slip). The
     * state column is the friction law's first state output @p state_name
     * ("log10_theta", SEAS's "State (log10 s)"; else named as the law
     * names it, e.g. "psi").
     */
    std::string
    seas_station_header(const std::string &location,
                        const bool         test_mode,
                        const bool         normal_stress = false,
                        const std::string &state_name    = "log10_theta");

    /**
     * One data row of such a file: the time (s, 15 digits), the slip (m,
     * and the rest with 8), the log10
     * of the magnitude of the slip rate @p rate (m/s; -300 where it is 0),
     * the shear stress (MPa), the normal stress (MPa; only where
     * @p normal_stress is not NaN) and the state (the law's first state
     * output: the log10 of theta (s) for the laws of theta).
     */
    std::string
    seas_station_row(const double time,
                     const double slip,
                     const double rate,
                     const double shear_stress,
                     const double state,
                     const double normal_stress = std::nan(""));

    /**
     * The header of a surface station file of the SEAS BP3 layout: the
     * location @p location and the columns t, disp_1, disp_2, vel_1,
     * vel_2 (the displacement and velocity along x, horizontal, and y,
     * up; m and m/s).
     */
    std::string
    seas_surface_header(const std::string &location, const bool test_mode);

    /// One data row of such a file.
    std::string
    seas_surface_row(const double                 time,
                     const std::array<double, 2> &displacement,
                     const std::array<double, 2> &velocity);
  } // namespace Output
} // namespace rupture

#endif
