// The boundary-integral method's parameters.

#include <rupture/boundary_integral/simulation.h>

namespace rupture
{
  namespace BoundaryIntegral
  {
    void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Method",
        "finite elements",
        Patterns::Selection("finite elements|boundary integral"),
        "How the problem is discretized. 'finite elements': the body "
        "meshed in <Scene>, the fault as a contact interface (everything "
        "but <Boundary integral>). 'boundary integral': the review paper's "
        "dual method, the fault alone with the Green's function of the "
        "body (<Boundary integral>): quasi-dynamic earthquake cycles on the "
        "antiplane half-space (SCEC SEAS BP1).");
      prm.enter_subsection("Boundary integral");
      {
        prm.declare_entry(
          "Geometry",
          "antiplane half-space",
          Patterns::Selection("antiplane half-space"),
          "The body whose Green's function turns slip into traction: "
          "'antiplane half-space', a vertical strike-slip fault at x = 0 "
          "from the free surface y = 0 down, out-of-plane displacement only "
          "(the review paper's section 8, SEAS BP1).");
        prm.declare_entry("Fault depth",
                          "40e3",
                          Patterns::Double(),
                          "W (m, > 0): the depth down to which the fault is "
                          "solved; below it the fault slips at <Plate "
                          "rate>, which loads the part above.");
        prm.declare_entry("Element size",
                          "100",
                          Patterns::Double(),
                          "The length (m, > 0) of the fault's elements (W "
                          "is cut into equal elements of at most this "
                          "length; at most 20000 of them).");
        prm.declare_entry("Plate rate",
                          "1e-9",
                          Patterns::Double(),
                          "V_p (m/s, > 0): the slip rate of the fault below "
                          "<Fault depth>. The fault starts at the slip rate "
                          "at which the law in its initial state carries "
                          "<Initial shear stress> - eta V_p: with the law's "
                          "<Initial slip rate> = V_p and no <Initial "
                          "state>, V_p itself (the screen output gives the "
                          "range).");
        prm.declare_entry("Normal stress",
                          "50e6",
                          Patterns::Anything(),
                          "sigma_n (Pa, compressive > 0) as a function of "
                          "x, y, z (y up, the fault at x = 0: the depth is "
                          "-y; constants pi and year).");
        prm.declare_entry(
          "Initial shear stress",
          "",
          Patterns::Anything(),
          "tau_0 (Pa) as a function of x, y, z: the shear traction the "
          "fault carries at the start, before radiation damping (SEAS: "
          "tau_0 = sigma_n a_max asinh[V_p / (2 V_0) exp((f_0 + b ln(V_0 / "
          "V_p)) / a_max)] + eta V_p). The law's state at the start is the "
          "one for which it carries tau_0 - eta V_p at V_p.");
        prm.declare_entry("Relative tolerance",
                          "1e-7",
                          Patterns::Double(),
                          "The Dormand-Prince step's error, relative to the "
                          "slip and the state (> 0).");
        prm.declare_entry("Absolute tolerance",
                          "1e-8",
                          Patterns::Double(),
                          "The error (> 0) below which a change does not "
                          "matter: metres for the slip, and for the "
                          "logarithm of a state variable that spans "
                          "decades.");
        prm.declare_entry(
          "Sampling slip rate change",
          "0",
          Patterns::Double(0),
          "The station and statistics files get a row after a step when "
          "the log10 of the fault's largest slip rate has changed by at "
          "least this much since the last row, or when <Sampling interval> "
          "has passed; 0 writes every step.");
        prm.declare_entry("Sampling interval",
                          "3.15576e7",
                          Patterns::Double(0),
                          "The longest time (s) between two rows of the "
                          "station and statistics files (with <Sampling "
                          "slip rate change> > 0).");
        prm.declare_entry("Profile interval between events",
                          "1.57788e8",
                          Patterns::Double(0),
                          "Time (s) between two slip profiles "
                          "(slip_profiles.dat) outside events (SEAS: 5 "
                          "years); 0 writes none.");
        prm.declare_entry("Profile interval during events",
                          "1",
                          Patterns::Double(0),
                          "Time (s) between two slip profiles during an "
                          "event (SEAS: 1 s); 0 writes none.");
      }
      prm.leave_subsection();
    }



    bool
    chosen(ParameterHandler &prm)
    {
      return prm.get("Method") == "boundary integral";
    }
  } // namespace BoundaryIntegral
} // namespace rupture
