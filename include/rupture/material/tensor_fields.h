#ifndef rupture_material_tensor_fields_h
#define rupture_material_tensor_fields_h

#include <rupture/material/anisotropy.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rupture
{
  using namespace dealii;

  namespace Material
  {
    struct AnisotropicEntries;

    /**
     * Anisotropic materials whose constants in <Material/Stiffness> are
     * functions of position (x, y, z; z = 0 in 2-D), each one on its own,
     * so that the tensor's shape (its anisotropy), not only its size,
     * varies in space: "C11 = 6e10 - 2e5*z, C33 = 4e10, ...". Constants
     * given as numbers stay numbers; the class and the material axes are
     * fixed per material.
     */
    class TensorFields
    {
    public:
      /**
       * Read the constants of the anisotropic materials of @p entries
       * (@p names for messages) for a model of dimension @p dim. Throws a
       * message that names the entry, the material and the constant if a
       * value is neither a number nor a function of x, y, z, or a number
       * that is not allowed; the constants of a material that has no
       * function are left to anisotropic_stiffness().
       */
      void
      parse(const AnisotropicEntries       &entries,
            const std::vector<std::string> &names,
            const unsigned int              dim);

      /// Whether some constant of material @p i (of any material) is a
      /// function.
      bool
      varies(const unsigned int i) const;
      bool
      varies() const;

      /// The tensor of material @p i at @p p in the model's frame (not
      /// checked).
      template <int dim>
      VoigtMatrix
      value(const unsigned int i, const Point<dim> &p) const;

      /**
       * The tensor of material @p i at @p p in @p c, checked: each
       * constant finite and below 1e20 Pa, the tensor positive definite
       * and, in 2-D, the model plane a mirror plane. Returns an empty
       * string, or a message that names the entry, the material, the point
       * and what is allowed.
       */
      template <int dim>
      std::string
      checked_value(const unsigned int i,
                    const Point<dim>  &p,
                    VoigtMatrix       &c) const;

      /**
       * The tensor that bounds of material @p i refer to (the stable step,
       * the fastest wave speed): its value at the origin x = y = z = 0
       * where that is allowed, otherwise the Kelvin identity times 1e10 Pa
       * (the energy density 1e10 eps : eps). The same on every process and
       * for every mesh.
       */
      const VoigtMatrix &
      reference(const unsigned int i) const;

      /// The EnergyRatio against reference(i).
      const EnergyRatio &
      energy_ratio(const unsigned int i) const;

      /// The <Material/Stiffness> field of material @p i (for the screen).
      const std::string &
      text(const unsigned int i) const;

    private:
      struct Field
      {
        Symmetry                 symmetry = Symmetry::isotropic;
        Tensor<2, 3>             axes;
        std::vector<std::string> keys;
        std::vector<double>      numbers;
        /// Null where the constant is a number.
        std::vector<std::shared_ptr<FunctionParser<3>>> functions;
        /// The tensor in the model's frame is linear in the constants:
        /// sum over k of constant k times basis[k] (the rotated tensor of
        /// constant k = 1, the others 0), so a value costs no rotation.
        std::vector<VoigtMatrix> basis;
        VoigtMatrix              reference{};
        EnergyRatio              energy_ratio;
        std::string              text;
        std::string              which;
      };

      std::vector<Field> fields;
      unsigned int       dim = 3;
    };
  } // namespace Material
} // namespace rupture

#endif
