#ifndef rupture_material_elastic_material_h
#define rupture_material_elastic_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <string>
#include <vector>

namespace rupture
{
  using namespace dealii;

  namespace Material
  {
    /**
     * The elastic constants of one material, in SI units.
     */
    struct ElasticConstants
    {
      std::string name;
      /// Density (kg/m^3).
      double density = 0;
      /// Lame's first parameter (Pa).
      double lambda = 0;
      /// Shear modulus (Pa).
      double mu = 0;

      /// P-wave speed (m/s).
      double
      p_wave_speed() const;
      /// S-wave speed (m/s).
      double
      s_wave_speed() const;
      /// Young's modulus (Pa).
      double
      youngs_modulus() const;
      /// Poisson's ratio.
      double
      poissons_ratio() const;
    };

    /**
     * Linear isotropic elasticity, one set of constants per material id.
     * The i-th entry of each list belongs to material id i of the scene.
     * Materials may be given by Young's modulus and Poisson's ratio (as in
     * the GeoFEM paper's Table 1) or by wave speeds (as in the SCEC
     * benchmarks).
     */
    class ElasticMaterials
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm);

      /**
       * The constants of material @p id. Throws a user error if the scene
       * uses a material id that has no entry.
       */
      const ElasticConstants &
      get(const types::material_id id) const;

      unsigned int
      n_materials() const;

      /**
       * Throw a clear error if a material id used by the mesh is not
       * described in the Material section.
       */
      void
      check_material_id(const types::material_id id) const;

      /**
       * One line per material for the screen: name, rho, vp, vs, E, nu.
       */
      std::string
      summary() const;

    private:
      std::vector<ElasticConstants> materials;
    };
  } // namespace Material
} // namespace rupture

#endif
