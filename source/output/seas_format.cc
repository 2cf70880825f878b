// Station files in the layout of the SCEC SEAS benchmarks.

#include <rupture/output/seas_format.h>

#include <cmath>
#include <ctime>
#include <iomanip>
#include <sstream>

namespace rupture
{
  namespace Output
  {
    namespace
    {
      /// The first lines of a header: the problem @p problem, the code,
      /// the date (not in @p test_mode) and the location @p location.
      void
      header_start(std::ostream      &out,
                   const std::string &problem,
                   const std::string &location,
                   const bool         test_mode)
      {
        out << "# This is the file header:\n"
            << "# problem = " << problem << "\n"
            << "# code = rupture\n";
        if (!test_mode)
          {
            const std::time_t now = std::time(nullptr);
            out << "# date = " << std::put_time(std::gmtime(&now), "%Y/%m/%d")
                << "\n";
          }
        out << "# location = " << location << "\n";
      }
    } // namespace



    std::string
    seas_station_header(const std::string &location,
                        const bool         test_mode,
                        const bool         normal_stress,
                        const std::string &state_name)
    {
      const std::string  state = (state_name == "log10_theta") ?
                                   "State (log10 s)" :
                                   "State (" + state_name + ")";
      std::ostringstream out;
      header_start(out,
                   "rupture station output (SCEC SEAS format)",
                   location,
                   test_mode);
      out << "# Column #1 = Time (s)\n"
          << "# Column #2 = Slip (m)\n"
          << "# Column #3 = Slip rate (log10 m/s)\n"
          << "# Column #4 = Shear stress (MPa)\n";
      if (normal_stress)
        out << "# Column #5 = Normal stress (MPa)\n"
            << "# Column #6 = " << state << "\n"
            << "# The line below lists the names of the data fields\n"
            << "t slip slip_rate shear_stress normal_stress state\n";
      else
        out << "# Column #5 = " << state << "\n"
            << "# The line below lists the names of the data fields\n"
            << "t slip slip_rate shear_stress state\n";
      out << "# Here is the time-series data.\n";
      return out.str();
    }



    std::string
    seas_station_row(const double time,
                     const double slip,
                     const double rate,
                     const double shear_stress,
                     const double state,
                     const double normal_stress)
    {
      std::ostringstream out;
      // (The time with 15 digits: an event of steps of milliseconds late
      // in a cycle run of 10^10 s must not share one time stamp.)
      out << std::scientific << std::setprecision(15) << time
          << std::setprecision(7);
      const double magnitude = std::abs(rate);
      out << " " << slip << " "
          << (magnitude > 0 ? std::log10(magnitude) : -300.) << " "
          << shear_stress << " ";
      if (!std::isnan(normal_stress))
        out << normal_stress << " ";
      out << state << "\n";
      return out.str();
    }


    std::string
    seas_surface_header(const std::string &location, const bool test_mode)
    {
      std::ostringstream out;
      header_start(out,
                   "rupture surface station output (SCEC SEAS format)",
                   location,
                   test_mode);
      out << "# Column #1 = Time (s)\n"
          << "# Column #2 = Displacement along x, horizontal (m)\n"
          << "# Column #3 = Displacement along y, up (m)\n"
          << "# Column #4 = Velocity along x (m/s)\n"
          << "# Column #5 = Velocity along y (m/s)\n"
          << "# The line below lists the names of the data fields\n"
          << "t disp_1 disp_2 vel_1 vel_2\n"
          << "# Here is the time-series data.\n";
      return out.str();
    }



    std::string
    seas_surface_row(const double                 time,
                     const std::array<double, 2> &displacement,
                     const std::array<double, 2> &velocity)
    {
      std::ostringstream out;
      out << std::scientific << std::setprecision(15) << time
          << std::setprecision(7) << " " << displacement[0] << " "
          << displacement[1] << " " << velocity[0] << " " << velocity[1]
          << "\n";
      return out.str();
    }
  } // namespace Output
} // namespace rupture
