#include <rupture/friction/law_utilities.h>

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
    } // namespace LawUtilities
  }   // namespace Friction
} // namespace rupture
