#ifndef rupture_material_anisotropic_input_h
#define rupture_material_anisotropic_input_h

#include <rupture/material/anisotropy.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <map>
#include <string>
#include <vector>

namespace rupture
{
  namespace Material
  {
    /**
     * The entries of <Material> that describe anisotropic materials, one
     * field per material (a single field given for all is repeated).
     */
    struct AnisotropicEntries
    {
      std::vector<Symmetry>    symmetry;
      std::vector<std::string> stiffness;
      std::vector<std::string> axes;
    };

    /**
     * Read <Symmetry>, <Stiffness> and <Material axes> of the entered
     * subsection <Material> for the materials @p names. Throws a message
     * naming the entry if a list has neither one field nor one per
     * material, or if a class is unknown.
     */
    AnisotropicEntries
    read_anisotropic_entries(ParameterHandler               &prm,
                             const std::vector<std::string> &names);

    /**
     * The texts of the constants in material @p index's <Stiffness> field
     * of @p entries (anisotropic), by name (C11, ...): items 'Cij = value'
     * separated by commas outside parentheses, each value a number or a
     * function of x, y, z (not read here). Throws a message that names the
     * entry, the material (@p which, e.g. " of material 1 (slab)") and what
     * is allowed if an item is malformed, unknown, repeated or missing.
     */
    std::map<std::string, std::string>
    stiffness_texts(const AnisotropicEntries &entries,
                    const unsigned int        index,
                    const std::string        &which);

    /**
     * The material's axes in model coordinates (the columns of a rotation)
     * from its <Material axes> field. Throws a message naming the entry
     * and the material if they are not orthogonal or not as many as its
     * class allows.
     */
    Tensor<2, 3>
    material_axes(const AnisotropicEntries &entries,
                  const unsigned int        index,
                  const std::string        &which);

    /**
     * Whether the Kelvin form K of @p c is positive definite with its
     * smallest eigenvalue above @p fraction of its largest, by a cheap
     * sufficient test (the Cholesky factorization of K - fraction trace(K)
     * I) and, where that fails, the eigenvalues themselves.
     */
    bool
    positive_definite_enough(const VoigtMatrix &c, const double fraction);

    /// Whether a constant's value is allowed: finite, below 1e20 in
    /// magnitude (Pa).
    bool
    valid_constant(const double value);

    /**
     * The tensor in the model's frame of a material of class @p symmetry
     * with the named @p constants (allowed values) and @p axes. Throws a
     * message that names the entry and @p which (the material, and for
     * constants that vary in space the point) if it is not positive
     * definite.
     */
    VoigtMatrix
    checked_stiffness(const Symmetry                       symmetry,
                      const std::map<std::string, double> &constants,
                      const Tensor<2, 3>                  &axes,
                      const std::string                   &which);

    /**
     * The stiffness in the model's frame of material @p index of
     * @p entries (anisotropic), from its constants (numbers) and axes.
     * Throws a message that names the entry, the material (@p which) and
     * what is allowed if a constant is missing, unknown, not a finite
     * number (a function of position included: this is for the
     * boundary-integral method's homogeneous body), if the axes are not
     * orthogonal, or if the tensor is not positive definite.
     */
    VoigtMatrix
    anisotropic_stiffness(const AnisotropicEntries &entries,
                          const unsigned int        index,
                          const std::string        &which);
  } // namespace Material
} // namespace rupture

#endif
