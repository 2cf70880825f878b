#ifndef rupture_output_statistics_columns_h
#define rupture_output_statistics_columns_h

namespace rupture
{
  namespace Output
  {
    /**
     * The names of the columns of <output>/statistics that the program
     * itself reads back (the final summary, the early-end criteria): they
     * are written and read through these, never by position.
     */
    namespace Columns
    {
      inline constexpr const char *kinetic_energy = "Kinetic energy (J)";
      inline constexpr const char *strain_energy  = "Strain energy (J)";
      inline constexpr const char *external_work =
        "Work of loads and boundary reactions (J)";
      inline constexpr const char *dissipated_energy =
        "Energy dissipated by damping and absorbing boundaries (J)";
      inline constexpr const char *balance_error =
        "Energy balance error (J): kinetic + strain + dissipated + fault "
        "work - work - initial energy";
      inline constexpr const char *l2_error =
        "L2 error of the displacement (m m^(dim/2))";
      inline constexpr const char *slipping_area =
        "Slipping area (m^2, m in 2-D)";
      inline constexpr const char *max_slip      = "Maximum slip (m)";
      inline constexpr const char *max_slip_rate = "Maximum slip rate (m/s)";
      inline constexpr const char *seismic_moment =
        "Seismic moment (N m, N in 2-D)";
      inline constexpr const char *mean_shear_traction =
        "Mean shear traction on the fault (Pa)";
    } // namespace Columns
  }   // namespace Output
} // namespace rupture

#endif
