#ifndef rupture_boundary_integral_antiplane_half_space_h
#define rupture_boundary_integral_antiplane_half_space_h

#include <rupture/boundary_integral/stiffness.h>

#include <vector>

namespace rupture
{
  /**
   * The review paper's dual method (sections 7-9): the fault is solved on
   * its own, through the Green's function of the body, which turns the
   * slip of the fault into the traction on it. Nothing of the volume is
   * discretized.
   */
  namespace BoundaryIntegral
  {
    /**
     * The antiplane problem of the review paper's section 8 (and of the
     * SCEC SEAS benchmark BP1): a vertical strike-slip fault at x = 0 in an
     * elastic half-space y < 0 with a free surface y = 0; the only
     * displacement is u(x, y) out of the plane, so that mu Delta u = 0
     * (8.5), with the Green's function G = ln r / (2 pi mu) (8.6).
     *
     * The fault from the surface down to the depth W is cut into N elements
     * of equal length h = W / N, each with a uniform slip s_j (the jump of
     * u across the fault, (8.8)); below W the fault slips at the plate rate
     * (the loading), so only s_j - V_p t, the slip relative to a fault
     * slipping uniformly all the way down, makes stress. The traction at
     * the centre of element i is
     *   tau_i = tau0_i + sum_j K_ij (s_j - V_p t),
     * with the stiffness K_ij the shear stress at the centre depth z_i of a
     * unit uniform slip on element j, from its top d1 to its bottom d2:
     *   K_ij = mu / (2 pi) [1 / (z_i - d2) - 1 / (z_i - d1)
     *                       + 1 / (z_i + d1) - 1 / (z_i + d2)].
     * The first two terms are Betti's formula (8.7) differentiated (the
     * stress mu du/dx on the fault of a dislocation from d1 to d2: the
     * hypersingular kernel mu / (2 pi (z - xi)^2) of dG / dxi integrated
     * over the element); the last two are the image of the element in the
     * free surface (mirror slip from -d2 to -d1), which makes the surface
     * traction-free. A slip uniform over the whole fault (d1 = 0, d2 to
     * infinity) makes no stress, as it must. The self term is
     * K_ii = -2 mu / (pi h) plus the image: slip relieves the stress.
     */
    class AntiplaneHalfSpace : public Stiffness
    {
    public:
      /**
       * @p depth W (m) of the part of the fault that is solved (below it
       * the fault creeps at the plate rate), cut into elements of length
       * about @p element_size (m); @p shear_modulus mu (Pa) of the kernel,
       * @p moment_modulus that of the moments (0: mu; they differ for an
       * anisotropic body, whose kernel takes sqrt(C44 C55) and whose
       * moment C55).
       */
      AntiplaneHalfSpace(const double depth,
                         const double element_size,
                         const double shear_modulus,
                         const double moment_modulus = 0);

      /// The number of elements N.
      unsigned int
      size() const override
      {
        return n;
      }

      /// The length of each element (m).
      double
      element_length() const
      {
        return h;
      }

      /// The depth (m, > 0) of the centre of element @p i.
      double
      centre(const unsigned int i) const
      {
        return (i + 0.5) * h;
      }

      /// The centre of element @p i.
      double
      depth(const unsigned int i) const override
      {
        return centre(i);
      }

      double
      length(const unsigned int) const override
      {
        return h;
      }

      double
      extent() const override
      {
        return n * h;
      }

      /// The shear modulus (Pa) of the moments.
      double
      shear_modulus() const override
      {
        return moment_mu;
      }

      /// The stress at the centre of element @p i of a unit slip on element
      /// @p j (Pa/m).
      double
      stiffness(const unsigned int i, const unsigned int j) const;

      /// Rows @p begin to @p end (excluded) of K, one after the other.
      std::vector<double>
      rows(const unsigned int begin, const unsigned int end) const override;

      std::string
      description() const override;

    private:
      unsigned int n;
      double       h;
      double       mu, moment_mu;
    };
  } // namespace BoundaryIntegral
} // namespace rupture

#endif
