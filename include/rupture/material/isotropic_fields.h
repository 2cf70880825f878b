#ifndef rupture_material_isotropic_fields_h
#define rupture_material_isotropic_fields_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace rupture
{
  using namespace dealii;

  namespace Material
  {
    /**
     * The three entries that give an isotropic material's constants
     * (<Density>, then <P-wave speed> and <S-wave speed>, or <Young's
     * modulus> and <Poisson's ratio>, by <Parametrization>), each a
     * number or a function of position (x, y, z; z = 0 in 2-D) per
     * material: a comma separated list of numbers, fields separated by
     * ';' (each a number or a function), or a single function for all
     * materials. Functions let the constants of one material vary
     * independently in space (a velocity model vp(x), vs(x), rho(x)).
     */
    class IsotropicFields
    {
    public:
      /**
       * Read the entries of the entered subsection <Material> for the
       * materials @p names. Throws a message naming the entry for a list
       * whose length is neither one nor the number of materials, or a
       * field that is neither a number nor a function of x, y, z.
       */
      void
      parse(ParameterHandler               &prm,
            const std::vector<std::string> &names,
            const bool                      by_speeds);

      /// The entries' names (density first).
      const std::array<std::string, 3> &
      entries() const
      {
        return entry_names;
      }

      /// Whether any entry of material @p i (of any material) is a function.
      bool
      varies(const unsigned int i) const;
      bool
      varies() const;

      /// The numbers of material @p i (NaN where an entry is a function).
      std::array<double, 3>
      numbers(const unsigned int i) const;

      /// The entries' values of material @p i at @p p.
      template <int dim>
      std::array<double, 3>
      values(const unsigned int i, const Point<dim> &p) const;

      /// The text of entry @p e of material @p i (for the screen).
      const std::string &
      text(const unsigned int e, const unsigned int i) const
      {
        return fields[e][i];
      }

    private:
      std::array<std::string, 3>              entry_names;
      std::array<std::vector<std::string>, 3> fields;
      std::array<std::vector<double>, 3>      number_values;
      std::array<std::vector<std::unique_ptr<FunctionParser<3>>>, 3> functions;
    };
  } // namespace Material
} // namespace rupture

#endif
