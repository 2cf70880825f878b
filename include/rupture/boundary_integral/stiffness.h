#ifndef rupture_boundary_integral_stiffness_h
#define rupture_boundary_integral_stiffness_h

#include <string>
#include <vector>

namespace rupture
{
  namespace BoundaryIntegral
  {
    /**
     * What the boundary-integral fault needs of the body: the elements of
     * a fault that runs down from the surface (their depths and lengths)
     * and the dense stiffness K_ij, the shear traction at element i of a
     * unit slip of element j (Pa/m). The Green's function of the antiplane
     * half-space gives it in closed form (AntiplaneHalfSpace); a
     * finite-element model of the body gives it column by column, one
     * solve per element (AntiplaneFiniteElements).
     */
    class Stiffness
    {
    public:
      virtual ~Stiffness() = default;

      /// The number of elements N.
      virtual unsigned int
      size() const = 0;

      /// The depth (m, > 0, increasing with i) of element @p i, where its
      /// traction and slip rate are taken.
      virtual double
      depth(const unsigned int i) const = 0;

      /// The length (m) of fault that element @p i stands for.
      virtual double
      length(const unsigned int i) const = 0;

      /// The depth (m) of the lower end of the solved fault, below which it
      /// slips at the plate rate.
      virtual double
      extent() const = 0;

      /// The shear modulus (Pa) of the medium at the fault (for moments).
      virtual double
      shear_modulus() const = 0;

      /// Rows @p begin to @p end (excluded) of K, one after the other.
      virtual std::vector<double>
      rows(const unsigned int begin, const unsigned int end) const = 0;

      /// What the body and its elements are, for the screen.
      virtual std::string
      description() const = 0;
    };
  } // namespace BoundaryIntegral
} // namespace rupture

#endif
