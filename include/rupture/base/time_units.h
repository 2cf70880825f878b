#ifndef rupture_base_time_units_h
#define rupture_base_time_units_h

#include <string>

namespace rupture
{
  namespace Utilities
  {
    /**
     * A time of a phase that lasts @p duration seconds, as a person reads
     * it, to print beside its value in seconds: " (12.3 yr)" in phases of
     * a year or longer, " (4.5 d)" in phases of a day or longer, and
     * nothing in shorter ones, whose times read well in seconds. For the
     * screen and the log; files keep seconds.
     */
    std::string
    readable_time(const double seconds, const double duration);
  } // namespace Utilities
} // namespace rupture

#endif
