#ifndef rupture_boundary_integral_settings_h
#define rupture_boundary_integral_settings_h

#include <rupture/boundary_integral/cycle_output.h>
#include <rupture/fault/event_catalogue.h>
#include <rupture/friction/interface.h>
#include <rupture/time_integration/dormand_prince.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rupture
{
  namespace BoundaryIntegral
  {
    using namespace dealii;

    class Stiffness;

    /**
     * Everything a boundary-integral cycle run reads from the parameters,
     * checked (each message names its entry): the medium of <Material>,
     * the friction law, the radiation damping, the stations and the event
     * catalogue of <Fault>, the clock of <Time integration>, <Boundary
     * integral>, <Termination/Number of events> and <Checkpoint>.
     */
    struct Settings
    {
      /// Read and check them. Collective only in that every rank reads.
      explicit Settings(ParameterHandler &prm);

      /// The fault's normal stress and initial shear stress at the depths
      /// of @p body's elements (checked: compression, above eta V_p).
      void
      fault_stresses(const Stiffness     &body,
                     std::vector<double> &normal_stress,
                     std::vector<double> &initial_shear_stress) const;

      /// Within <Material>: an anisotropic first material's antiplane
      /// moduli (shear_modulus = C55, vertical_shear_modulus = C44), and
      /// the check that the body is homogeneous.
      void
      read_anisotropic_moduli(ParameterHandler &prm);

      bool        test_mode = false;
      std::string output_directory;

      // The medium and the fault.
      /// The antiplane shear moduli (Pa): C55 (sigma_xz per u,x: the
      /// modulus across the fault, of the moment) and C44 (sigma_yz per
      /// u,y); equal for an isotropic body.
      double shear_modulus          = 0;
      double vertical_shear_modulus = 0;
      /// Lame's first constant (Pa), for the plane-strain body.
      double lambda = 0;
      /// The density (kg/m^3), for the fully dynamic phases.
      double density = 0;
      /// Whether the first material is anisotropic.
      bool                                          anisotropic       = false;
      double                                        radiation_damping = 0;
      double                                        plate_rate        = 0;
      std::unique_ptr<Friction::Interface>          law;
      std::string                                   law_name;
      Fault::EventCatalogue<2>                      events;
      std::vector<std::pair<std::string, Point<2>>> stations;
      /// <Boundary integral/Surface stations> (points (x, 0)).
      std::vector<std::pair<std::string, Point<2>>> surface_stations;

      // <Boundary integral>.
      std::string           geometry;
      double                dip    = 90;
      bool                  thrust = true;
      std::string           stiffness;
      int                   fe_degree   = 1;
      double                domain_size = 0, cell_growth = 1;
      double                fault_depth = 0, element_size = 0;
      std::string           normal_stress, initial_shear_stress;
      double                absolute_tolerance = 0;
      CycleOutput::Sampling sampling;
      /// <Events> = fully dynamic, its thresholds (m/s), Courant number and
      /// Kelvin-Voigt damping (time steps).
      bool   fully_dynamic       = false;
      double dynamic_above       = 1e-3;
      double quasi_dynamic_below = 5e-4;
      double courant             = 0.5;
      double kelvin_voigt        = 0.1;

      // The clock and the end.
      double                                   end_time   = 0;
      double                                   first_step = 0;
      TimeIntegration::DormandPrince::Settings integrator;
      unsigned int                             max_events = 0;

      // Checkpoints.
      unsigned int checkpoint_steps   = 0;
      double       checkpoint_minutes = 0;

      bool
      checkpoints() const
      {
        return checkpoint_steps > 0 || checkpoint_minutes > 0;
      }
    };
  } // namespace BoundaryIntegral
} // namespace rupture

#endif
