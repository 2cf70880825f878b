#ifndef rupture_material_anisotropy_h
#define rupture_material_anisotropy_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace rupture
{
  using namespace dealii;

  namespace Material
  {
    /**
     * A stiffness tensor a_ijkl in Voigt notation: sigma_I = C_IJ gamma_J
     * with I, J = 1..6 for the components 11, 22, 33, 23, 13, 12 (stored
     * from 0) and gamma the engineering strains (gamma_4 = 2 eps_23, ...).
     * Always three-dimensional: a 2-D plane-strain model takes its
     * in-plane part (plane_strain_tensor()).
     */
    using VoigtMatrix = std::array<std::array<double, 6>, 6>;

    /**
     * The symmetry classes a material may be given in, in its own frame.
     */
    enum class Symmetry
    {
      isotropic,
      transversely_isotropic,
      orthotropic,
      general
    };

    /// The names of <Material/Symmetry>, in the order of Symmetry.
    const std::vector<std::string> &
    symmetry_names();

    /**
     * The constants a class is given by in the material's frame, named
     * as the Voigt entries (C11, C13, ...). Transversely isotropic: C11,
     * C33, C13, C44, C66 with the symmetry axis along the material's
     * 3-axis (C12 = C11 - 2 C66). Orthotropic: the nine of the diagonal
     * blocks. General: all 21 with I <= J.
     */
    std::vector<std::string>
    constant_names(const Symmetry symmetry);

    /**
     * The Voigt matrix of a class from its named constants (which must be
     * exactly those of constant_names(); the caller checks that).
     */
    VoigtMatrix
    voigt_matrix(const Symmetry                       symmetry,
                 const std::map<std::string, double> &constants);

    /// The Voigt matrix of an isotropic material with Lame's constants.
    VoigtMatrix
    isotropic_voigt_matrix(const double lambda, const double mu);

    /**
     * The tensor in the model's frame when the material's axes 1, 2, 3
     * are the columns of @p axes (orthonormal, in model coordinates).
     */
    VoigtMatrix
    rotate(const VoigtMatrix &c, const Tensor<2, 3> &axes);

    /**
     * The eigenvalues (ascending) of the tensor as a map of symmetric
     * strains to stresses (its Kelvin form, whose shear rows carry a
     * factor sqrt 2): the energy density is positive for every strain if
     * and only if the smallest is positive.
     */
    std::array<double, 6>
    kelvin_eigenvalues(const VoigtMatrix &c);

    /// The Christoffel matrix Gamma_ik = a_ijkl n_j n_l for a unit @p n.
    SymmetricTensor<2, 3>
    christoffel_matrix(const VoigtMatrix &c, const Tensor<1, 3> &n);

    /**
     * The three phase speeds (descending: quasi-P, then the two shear
     * waves) of plane waves travelling along the unit vector @p n.
     */
    std::array<double, 3>
    phase_speeds(const VoigtMatrix  &c,
                 const double        density,
                 const Tensor<1, 3> &n);

    /**
     * The two phase speeds (descending) of the waves polarised in the
     * model plane x3 = 0 that travel along @p n (in that plane): those of
     * the plane's 2 x 2 block of the Christoffel matrix, which are the 2-D
     * model's waves.
     */
    std::array<double, 2>
    in_plane_phase_speeds(const VoigtMatrix  &c,
                          const double        density,
                          const Tensor<1, 3> &n);

    /**
     * Whether the plane x3 = 0 (the model plane of 2-D runs) is a plane
     * of mirror symmetry, in the sense that in-plane strains cause no
     * out-of-plane shear stress (C_I4 = C_I5 = 0 for I = 1, 2, 6, to
     * 1e-9 of the largest entry): only then do in-plane and out-of-plane
     * motions decouple and the 2-D plane-strain model is exact.
     */
    bool
    model_plane_is_mirror_plane(const VoigtMatrix &c);

    /**
     * The 4th-order stiffness tensor in @p dim dimensions: in 3-D the
     * whole tensor, in 2-D the plane-strain part for the components 1, 2
     * (which model_plane_is_mirror_plane() must allow).
     */
    template <int dim>
    SymmetricTensor<4, dim>
    stiffness_tensor(const VoigtMatrix &c);

    /**
     * The largest ratio, over all strains (in 2-D: in-plane strains), of
     * the energy density of a tensor to that of a fixed positive definite
     * reference: the largest eigenvalue of K_ref^-1/2 K K_ref^-1/2 of their
     * Kelvin forms. So eps : c : eps <= ratio(c) eps : reference : eps for
     * every strain, with equality for one: element matrices, and squared
     * wave speeds, of c are at most ratio(c) times those of the reference.
     */
    class EnergyRatio
    {
    public:
      EnergyRatio() = default;

      /// For @p reference (positive definite) in @p dim dimensions.
      EnergyRatio(const VoigtMatrix &reference, const unsigned int dim);

      double
      operator()(const VoigtMatrix &c) const;

      /**
       * Whether operator()(c) is certainly below @p t: t I - M positive
       * definite by a Cholesky factorization of the same M that
       * operator() computes (some 20 times cheaper than its eigenvalue).
       */
      bool
      certainly_below(const VoigtMatrix &c, const double t) const;

    private:
      /// M = L^-1 K L^-T for the Kelvin form K of @p c.
      VoigtMatrix
      transformed(const VoigtMatrix &c) const;

      /// The number of strain components and their Voigt indices.
      unsigned int                n    = 6;
      std::array<unsigned int, 6> rows = {{0, 1, 2, 3, 4, 5}};
      /// The inverse of the reference's Kelvin form's Cholesky factor.
      VoigtMatrix inverse_factor{};
    };

    /**
     * The largest of ratio(c_k) w_k over tensors c_k with weights w_k > 0,
     * taken one at a time: the eigenvalue problem is solved only for a
     * tensor that may raise the largest so far (EnergyRatio::
     * certainly_below() with a margin of 1e-10 passes over the others) or
     * that differs from the last one solved. The result is the maximum of
     * the exact values, the same number.
     */
    class LargestRatio
    {
    public:
      explicit LargestRatio(const EnergyRatio &ratio);

      /// Takes @p c with weight @p w: ratio(c) (not times w) where it was
      /// computed (or repeated from the last tensor), -1 where it was
      /// passed over because ratio(c) w is below the largest so far.
      double
      add(const VoigtMatrix &c, const double w);

      /// The largest ratio(c) w so far (0 before the first).
      double
      largest() const
      {
        return largest_value;
      }

      /// The number of eigenvalue problems solved so far.
      unsigned int
      solved() const
      {
        return solves;
      }

    private:
      const EnergyRatio *ratio;
      unsigned int       solves        = 0;
      double             largest_value = 0;
      bool               has_last      = false;
      VoigtMatrix        last{};
      double             last_ratio = 0;
    };

    /**
     * The extreme phase speeds over all directions of propagation, in
     * @p dim dimensions (in 2-D: directions and polarisations in the
     * model plane). Sampled over directions (every 2 degrees in 2-D,
     * about 3 degrees on the sphere in 3-D), then refined locally, so
     * accurate to about 1e-6 relative.
     */
    struct SpeedRange
    {
      double slowest = 0;
      double fastest = 0;
    };

    template <int dim>
    SpeedRange
    speed_range(const VoigtMatrix &c, const double density);
  } // namespace Material
} // namespace rupture

#endif
