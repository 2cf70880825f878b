#include <rupture/base/time_units.h>

#include <cmath>
#include <cstdio>

namespace rupture
{
  namespace Utilities
  {
    std::string
    readable_time(const double seconds, const double duration)
    {
      constexpr double day  = 86400;
      constexpr double year = 365.25 * day;
      if (!(std::isfinite(seconds) && std::isfinite(duration)) ||
          std::abs(duration) < day)
        return "";
      const bool   years = std::abs(duration) >= year;
      const double value = seconds / (years ? year : day);
      char         text[64];
      std::snprintf(
        text, sizeof(text), " (%.4g %s)", value, years ? "yr" : "d");
      return text;
    }
  } // namespace Utilities
} // namespace rupture
