#include <rupture/friction/law_utilities.h>

#include <deal.II/base/numbers.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace rupture
{
  namespace Friction
  {
    namespace LawUtilities
    {
      std::string
      at_point(const Point<3> &x)
      {
        std::ostringstream s;
        s << " at the fault point (" << x << ")";
        return s.str();
      }



      void
      require(const bool         ok,
              const std::string &section,
              const std::string &entry,
              const double       value,
              const Point<3>    &x,
              const std::string &allowed)
      {
        AssertThrow(ok,
                    ExcMessage("<Fault/" + section + "/" + entry + "> is " +
                               std::to_string(value) + at_point(x) +
                               ", but it must be " + allowed + "."));
      }



      double
      process_zone_at_rest(const double shear_modulus,
                           const double slip_scale,
                           const double drop,
                           const double pressure)
      {
        const double denominator = drop * pressure;
        if (!(denominator > 0) || !std::isfinite(denominator))
          return std::numeric_limits<double>::infinity();
        return 9. * numbers::PI / 32. * shear_modulus * slip_scale /
               denominator;
      }
    } // namespace LawUtilities
  }   // namespace Friction
} // namespace rupture
