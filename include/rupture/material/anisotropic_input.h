#ifndef rupture_material_anisotropic_input_h
#define rupture_material_anisotropic_input_h

#include <rupture/material/anisotropy.h>

#include <deal.II/base/parameter_handler.h>

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
     * The stiffness in the model's frame of material @p index of
     * @p entries (anisotropic), from its constants and axes. Throws a
     * message that names the entry, the material (@p which, e.g. " of
     * material 1 (slab)") and what is allowed if a constant is missing,
     * unknown or not finite, if the axes are not orthogonal, or if the
     * tensor is not positive definite.
     */
    VoigtMatrix
    anisotropic_stiffness(const AnisotropicEntries &entries,
                          const unsigned int        index,
                          const std::string        &which);
  } // namespace Material
} // namespace rupture

#endif
