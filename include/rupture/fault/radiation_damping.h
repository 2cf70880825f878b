#ifndef rupture_fault_radiation_damping_h
#define rupture_fault_radiation_damping_h

#include <string>

namespace rupture
{
  namespace Fault
  {
    /**
     * The value of <Fault/Radiation damping>: a number >= 0 (Pa s/m), or
     * -1 for 'auto' (half the shear impedance across the fault, which the
     * caller takes from the material). Anything else is refused with a
     * message naming the entry.
     */
    double
    read_radiation_damping(const std::string &text);
  } // namespace Fault
} // namespace rupture

#endif
