#ifndef rupture_boundary_integral_stiffness_h
#define rupture_boundary_integral_stiffness_h

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace rupture
{
  namespace BoundaryIntegral
  {
    /**
     * What the boundary-integral fault needs of the body: the elements of
     * a fault that runs down from the surface (their distances down the
     * fault and lengths) and the dense stiffness K_ij, the shear traction
     * at element i of a unit slip of element j (Pa/m). The Green's
     * function of the antiplane half-space gives it in closed form
     * (AntiplaneHalfSpace); a finite-element model of the body gives it
     * column by column, one solve per element (AntiplaneFiniteElements,
     * and PlaneStrainFiniteElements for a dipping fault, whose slip also
     * changes the normal stress: normal_rows()).
     */
    class Stiffness
    {
    public:
      virtual ~Stiffness() = default;

      /// The number of elements N.
      virtual unsigned int
      size() const = 0;

      /// The distance (m, >= 0, increasing with i) of element @p i from
      /// the surface, measured down the fault (the depth where the fault
      /// is vertical), where its traction and slip rate are taken.
      virtual double
      depth(const unsigned int i) const = 0;

      /// The length (m) of fault that element @p i stands for.
      virtual double
      length(const unsigned int i) const = 0;

      /// The distance down the fault (m) of the lower end of the solved
      /// fault, below which it slips at the plate rate.
      virtual double
      extent() const = 0;

      /// The shear modulus (Pa) of the medium at the fault (for moments).
      virtual double
      shear_modulus() const = 0;

      /// Rows @p begin to @p end (excluded) of K, one after the other.
      virtual std::vector<double>
      rows(const unsigned int begin, const unsigned int end) const = 0;

      /**
       * Rows @p begin to @p end of the normal stiffness: the change of the
       * normal stress (Pa, compression > 0) at element i per unit slip of
       * element j (Pa/m). Empty (the default) where slip does not change
       * the normal stress (the antiplane problem).
       */
      virtual std::vector<double>
      normal_rows(const unsigned int /*begin*/,
                  const unsigned int /*end*/) const
      {
        return {};
      }

      /// Whether normal_rows() gives anything.
      virtual bool
      changes_normal_stress() const
      {
        return false;
      }

      /// The number of points on the surface whose motion the body gives
      /// (surface_motion()).
      virtual unsigned int
      n_surface_points() const
      {
        return 0;
      }

      /**
       * The motion (x, y components) of surface point @p k when the fault
       * has the values @p fault_values relative to the plate's (slip
       * s_j - V_p t, or slip rate V_j - V_p) and the plate the value
       * @p plate_value (V_p t, or V_p): the blocks' rigid motion (the
       * hanging wall's +d/2, the footwall's -d/2 times @p plate_value, d
       * the slip direction) plus that of the slip relative to the plate.
       */
      virtual std::array<double, 2>
      surface_motion(const unsigned int /*k*/,
                     const std::vector<double> & /*fault_values*/,
                     const double /*plate_value*/) const
      {
        return {{0, 0}};
      }

      /// The fault's dip (degrees from the horizontal; 90: vertical). The
      /// fault runs from the surface point x = 0 down towards x > 0.
      virtual double
      dip() const
      {
        return 90;
      }

      /// The position (x, y; y up, the surface y = 0) of the point at the
      /// distance @p distance down the fault.
      void
      position(const double distance, double &x, double &y) const
      {
        const double angle = dip() * M_PI / 180;
        // (Exactly (0, -distance) for a vertical fault.)
        x = dip() == 90 ? 0. : distance * std::cos(angle);
        y = dip() == 90 ? -distance : -distance * std::sin(angle);
      }

      /// What the body and its elements are, for the screen.
      virtual std::string
      description() const = 0;
    };
  } // namespace BoundaryIntegral
} // namespace rupture

#endif
