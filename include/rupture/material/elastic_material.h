#ifndef rupture_material_elastic_material_h
#define rupture_material_elastic_material_h

#include <rupture/material/anisotropy.h>
#include <rupture/material/spatial_factors.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <string>
#include <vector>

namespace rupture
{
  using namespace dealii;

  namespace Material
  {
    struct AnisotropicEntries;

    /**
     * The elastic constants of one material, in SI units: isotropic
     * (Lame's constants) or anisotropic (a stiffness tensor in Voigt
     * notation, in the model's frame).
     */
    struct ElasticConstants
    {
      std::string name;
      /// Density (kg/m^3).
      double density = 0;
      /// Lame's first parameter (Pa); NaN for anisotropic materials.
      double lambda = 0;
      /// Shear modulus (Pa); NaN for anisotropic materials.
      double mu = 0;
      /// The class the material was given in (in its own frame).
      Symmetry symmetry = Symmetry::isotropic;
      /// The stiffness in the model's frame (for isotropic materials too).
      VoigtMatrix voigt{};
      /// The extreme phase speeds in 2-D (in-plane motion; only where the
      /// model plane is a mirror plane) and in 3-D (m/s).
      SpeedRange speeds_2d, speeds_3d;

      /// Whether the isotropic formulas (lambda, mu) apply.
      bool
      isotropic() const
      {
        return symmetry == Symmetry::isotropic;
      }

      /// P-wave speed (m/s), isotropic materials only.
      double
      p_wave_speed() const;
      /// S-wave speed (m/s), isotropic materials only.
      double
      s_wave_speed() const;
      /// Young's modulus (Pa), isotropic materials only.
      double
      youngs_modulus() const;
      /// Poisson's ratio, isotropic materials only.
      double
      poissons_ratio() const;

      /// The fastest and slowest phase speeds over all directions in
      /// @p dim dimensions (m/s); vp and vs for isotropic materials.
      template <int dim>
      SpeedRange
      wave_speeds() const;

      /// The stiffness tensor in @p dim dimensions (plane strain in 2-D).
      template <int dim>
      SymmetricTensor<4, dim>
      stiffness() const;

      /// The stress of a strain.
      template <int dim>
      SymmetricTensor<2, dim>
      stress(const SymmetricTensor<2, dim> &strain) const;

      /**
       * The shear stiffness across a plane of unit normal @p n: the mean
       * of the Christoffel matrix's eigenvalues in the plane (Gamma_ik =
       * a_ijkl n_j n_l projected onto it), which is mu for isotropic
       * materials. The fault's pairs use it where they need a shear
       * modulus (penalty bound, process zone, moment).
       */
      template <int dim>
      double
      shear_modulus_across(const Tensor<1, dim> &n) const;

      /**
       * The diagonal of the impedance matrix sqrt(rho Gamma(n)) of a
       * boundary of unit normal @p n: the dashpot of each displacement
       * component (rho vp n_c^2 + rho vs (1 - n_c^2) if isotropic).
       */
      template <int dim>
      Tensor<1, dim>
      boundary_impedance(const Tensor<1, dim> &n) const;
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

      /**
       * Read the section. @p dim is the model's dimension: 2-D runs
       * refuse anisotropic materials whose model plane is not a mirror
       * plane.
       */
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dim = 3);

      /// Whether any material is anisotropic.
      bool
      any_anisotropic() const;

      /**
       * Whether a material's constants vary in space (<Material/Stiffness
       * factor> or <Material/Density factor> is a function): then the
       * stiffness of material @p id at @p p is stiffness_factor() times
       * that of get(id), and its density density_factor() times get(id)'s.
       */
      bool
      varies_in_space() const
      {
        return factors.varies();
      }

      template <int dim>
      double
      stiffness_factor(const types::material_id id, const Point<dim> &p) const
      {
        return factors.stiffness(id, p);
      }

      template <int dim>
      double
      density_factor(const types::material_id id, const Point<dim> &p) const
      {
        return factors.density(id, p);
      }

      /**
       * Collective: check the spatial factors on the locally owned cells
       * of @p mesh (SpatialFactors::check()) and return the fastest phase
       * speed of the model in @p dim dimensions, the factors included.
       */
      template <int dim>
      double
      check_on_mesh(const Triangulation<dim> &mesh,
                    const unsigned int        degree,
                    const MPI_Comm            communicator) const;

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
       * One line per material for the screen: name, rho, vp, vs, E, nu;
       * for anisotropic materials the symmetry class and the extreme
       * phase speeds.
       */
      std::string
      summary() const;

    private:
      /// The constants of anisotropic material @p i (see parse_parameters).
      void
      set_anisotropic(ElasticConstants         &m,
                      const AnisotropicEntries &entries,
                      const unsigned int        i,
                      const std::string        &which) const;

      std::vector<ElasticConstants> materials;
      unsigned int                  dim = 3;
      SpatialFactors                factors;
    };
  } // namespace Material
} // namespace rupture

#endif
