#ifndef rupture_output_series_header_h
#define rupture_output_series_header_h

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace rupture
{
  namespace Output
  {
    /**
     * The "# time_step = ..." line of a SCEC-style time series (stations,
     * receivers) with @p time_step, the step of the run. When the rows'
     * times are not evenly spaced (a mesh that follows the rupture changes
     * the explicit step), a comment line follows that gives the smallest
     * and largest spacing, so that nobody takes row k for time k dt.
     */
    inline std::string
    time_step_lines(const std::vector<double> &times, const double time_step)
    {
      std::ostringstream out;
      out << "# time_step = " << time_step << "\n";
      double smallest = 0, largest = 0;
      for (unsigned int i = 1; i < times.size(); ++i)
        {
          const double spacing = times[i] - times[i - 1];
          smallest = (i == 1) ? spacing : std::min(smallest, spacing);
          largest  = std::max(largest, spacing);
        }
      if (largest > (1 + 1e-6) * smallest)
        out << "# The rows are not evenly spaced in time (the time step "
               "changed with the mesh): from "
            << smallest << " to " << largest
            << " s apart; column 1 holds each row's time.\n";
      return out.str();
    }
  } // namespace Output
} // namespace rupture

#endif
