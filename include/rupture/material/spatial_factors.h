#ifndef rupture_material_spatial_factors_h
#define rupture_material_spatial_factors_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <memory>
#include <string>
#include <vector>

namespace rupture
{
  using namespace dealii;

  namespace Material
  {
    /**
     * Materials whose constants vary in space: per material, a stiffness
     * factor s(x) that multiplies the whole stiffness (Lame's constants or
     * the anisotropic tensor) and a density factor r(x) that multiplies
     * the density, functions of position (x, y, z; z = 0 in 2-D). Wave
     * speeds scale with sqrt(s / r), impedances with sqrt(s r). A factor
     * given as a number is folded into the material's constants when they
     * are read (ElasticMaterials), so only functions are evaluated later.
     */
    /// Whether @p text (blanks around it allowed) is a number; if so, it is
    /// stored in @p value.
    bool
    read_number(const std::string &text, double &value);

    /// @p p with zeros for the missing coordinates: the argument of a
    /// function of x, y, z (z = 0 in 2-D).
    template <int dim>
    inline Point<3>
    padded(const Point<dim> &p)
    {
      Point<3> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = p[d];
      return x;
    }

    /**
     * The points at which constants that vary in space are checked on a
     * cell: its Gauss and Gauss-Lobatto points of @p degree + 1 per
     * direction (those of the operators' quadratures; the latter include
     * the vertices and the faces' points of the absorbing boundaries'
     * impedance) and its centre (the stress output's).
     */
    template <int dim>
    std::vector<Point<dim>>
    check_points(const typename Triangulation<dim>::active_cell_iterator &cell,
                 const unsigned int degree);

    class SpatialFactors
    {
    public:
      /**
       * Read <Stiffness factor> and <Density factor> of the entered
       * subsection <Material> for the materials @p names: one field per
       * material separated by ';', or one for all. Throws a message naming
       * the entry and the material for a field that is not a function of
       * x, y, z, or a number that is not positive and finite.
       */
      void
      parse(ParameterHandler &prm, const std::vector<std::string> &names);

      /// Whether any factor is a function (not a number).
      bool
      varies() const;

      /// The number a factor was given as (1 for a function).
      double
      constant_stiffness(const unsigned int material) const;
      double
      constant_density(const unsigned int material) const;

      /// The factors of @p material at @p p (1 where given as a number:
      /// folded into the constants).
      template <int dim>
      double
      stiffness(const types::material_id material, const Point<dim> &p) const;
      template <int dim>
      double
      density(const types::material_id material, const Point<dim> &p) const;

      /**
       * Collective: check that the factors are positive and finite at
       * check_points() of the locally owned cells of @p mesh; throws on every
       * process a message naming the entry, the material and the point
       * otherwise. Also returns the largest of sqrt(s / r) over those points
       * for each material (1 where both are numbers), for wave speeds.
       */
      template <int dim>
      std::vector<double>
      check(const Triangulation<dim> &mesh,
            const unsigned int        degree,
            const MPI_Comm            communicator) const;

    private:
      std::vector<std::string>                        names;
      std::vector<std::unique_ptr<FunctionParser<3>>> stiffness_functions,
        density_functions;
      std::vector<double> stiffness_numbers, density_numbers;
    };
  } // namespace Material
} // namespace rupture

#endif
