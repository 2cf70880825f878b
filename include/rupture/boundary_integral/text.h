#ifndef rupture_boundary_integral_text_h
#define rupture_boundary_integral_text_h

#include <iomanip>
#include <sstream>
#include <string>

namespace rupture
{
  namespace BoundaryIntegral
  {
    /// A Julian year (s): the years of the screen, the catalogue and the
    /// functions of position (the constant <year>).
    constexpr double year = 3.15576e7;

    /// @p x for messages and the screen, with up to 10 significant digits.
    inline std::string
    number(const double x)
    {
      std::ostringstream s;
      s << std::setprecision(10) << x;
      return s.str();
    }
  } // namespace BoundaryIntegral
} // namespace rupture

#endif
