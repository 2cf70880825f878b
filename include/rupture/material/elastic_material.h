#ifndef rupture_material_elastic_material_h
#define rupture_material_elastic_material_h

#include <rupture/material/anisotropy.h>
#include <rupture/material/isotropic_fields.h>
#include <rupture/material/spatial_factors.h>
#include <rupture/material/tensor_fields.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <algorithm>
#include <cstdint>
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
       * The impedance matrix Z = sqrt(rho Gamma(n)) of a boundary of unit
       * normal @p n (Gamma the Christoffel matrix): the traction Z v that
       * absorbs a plane wave leaving along n, whatever its polarization
       * (rho vp n n + rho vs (I - n n) if isotropic). Its off-diagonal
       * entries couple the components where n is not an axis of the
       * material's symmetry.
       */
      template <int dim>
      SymmetricTensor<2, dim>
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
       * Whether a material's constants vary in space: an isotropic
       * material's <Density>, wave speeds or moduli given as functions of
       * position, an anisotropic material's <Stiffness> constants, or
       * <Material/Stiffness factor> or <Material/Density factor> a function.
       * Then at() gives a material's constants at a point, and get() is not to
       * be used for them.
       */
      bool
      varies_in_space() const
      {
        return factors.varies() || has_functions() || tensors.varies();
      }

      /// Whether some anisotropic material's constants (<Material/
      /// Stiffness>) are functions of position: its tensor's shape varies.
      bool
      has_tensor_functions() const
      {
        return tensors.varies();
      }

      /**
       * The constants of material @p id at @p p: those of get(id) with the
       * functions of position evaluated and the factors applied (the
       * stiffness times the stiffness factor, the density times the
       * density factor). Not checked (check_on_mesh() checks them at the
       * points of the mesh). Where anisotropic constants are functions its
       * wave speeds are those of the material's reference scaled by the
       * factors, not the point's (check_on_mesh() bounds those).
       */
      template <int dim>
      ElasticConstants
      at(const types::material_id id, const Point<dim> &p) const;

      /**
       * For bounds of the eigenvalues of cells whose constants vary (the
       * stable step): at @p p, a stiffness ratio s, a density ratio r and,
       * for a material whose isotropic constants are functions, lambda(p)
       * (NaN otherwise). Where only factors vary, s and r are the factors:
       * the elastic energy density at p is s times that of reference(id),
       * the density r times its density. Where isotropic constants are
       * functions, s = mu(p) and r = rho(p): over a set of points, the
       * energy density lambda tr(eps)^2 + 2 mu eps : eps is at most
       * max(s) times that of reference(id, max(lambda) / max(s)) for every
       * strain, and the density at least min(r) times reference()'s.
       * Not for an anisotropic material whose constants are functions
       * (extreme_ratios() bounds those).
       */
      template <int dim>
      std::array<double, 3>
      reference_ratios(const types::material_id id, const Point<dim> &p) const;

      /**
       * The constants that reference_ratios() refers to: get(id) where only
       * factors vary or an anisotropic material's constants are functions
       * (get() then holds the reference tensor); where isotropic constants are
       * functions, lambda =
       * @p kappa, mu = 1, density 1 (the energy density grows with
       * lambda, so any larger @p kappa bounds it as well).
       */
      ElasticConstants
      reference(const types::material_id id, const double kappa) const;

      /// Whether material @p id is anisotropic with constants that are
      /// functions of position.
      bool
      tensor_given_as_functions(const types::material_id id) const
      {
        return tensors.varies(id);
      }

      /**
       * A local reference for the stable step's bound where anisotropic
       * constants are functions: the tensor of material @p id at @p p
       * (without factors) rounded, its largest diagonal entry up to a
       * power of 1.01 and every entry to 1 % of that, as 22 integers that
       * identify it; none where the rounded tensor is not positive definite
       * enough (its smallest Kelvin eigenvalue below 1e-3 of its largest):
       * then the material's reference serves. The same on every process.
       */
      template <int dim>
      std::vector<std::int64_t>
      rounded_tensor(const types::material_id id, const Point<dim> &p) const;

      /// The tensor of the integers of rounded_tensor() that start at
      /// @p first in @p key.
      static VoigtMatrix
      rounded_tensor_value(const std::vector<std::int64_t> &key,
                           const std::size_t                first);

      /// The constants of material @p id with the tensor @p c (a value of
      /// rounded_tensor_value(), times the material's constant stiffness
      /// factor): the reference that local_ratios() refers to.
      ElasticConstants
      local_reference(const types::material_id id, const VoigtMatrix &c) const;

      /**
       * For an anisotropic material whose constants are functions: the
       * largest stiffness ratio s and the smallest density ratio r of
       * reference_ratios() over @p points, with the energy ratio against
       * @p local where it is given instead of the material's reference.
       * The eigenvalue problem is solved only at points that may raise
       * the largest s (LargestRatio): the same numbers, cheaper.
       */
      template <int dim>
      std::array<double, 2>
      extreme_ratios(const types::material_id       id,
                     const std::vector<Point<dim>> &points,
                     const EnergyRatio             *local) const;

      /// Whether isotropic constants are functions of position.
      bool
      has_functions() const
      {
        return std::find(functions.begin(), functions.end(), true) !=
               functions.end();
      }

      /// Whether material @p id's isotropic constants are functions of
      /// position (get(id) then holds no numbers: NaN).
      bool
      given_as_functions(const types::material_id id) const
      {
        return functions[id];
      }

      /**
       * Collective: check the constants on the locally owned cells of
       * @p mesh (the factors by SpatialFactors::check(); functions of
       * position at the same points: each value allowed, the material
       * positive definite), throwing on every process a message that
       * names the entry, the material and the point otherwise; return the
       * fastest phase speed of the model in @p dim dimensions.
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
      /**
       * check_on_mesh() for the anisotropic materials whose constants are
       * functions: at check_points() of their locally owned cells each
       * constant allowed, the tensor positive definite and, in 2-D, the
       * model plane a mirror plane; returns a bound of their fastest wave
       * speed.
       */
      template <int dim>
      double
      check_tensors(const Triangulation<dim> &mesh,
                    const unsigned int        degree,
                    const MPI_Comm            communicator) const;

      /// The constants of anisotropic material @p i (see parse_parameters).
      void
      set_anisotropic(ElasticConstants         &m,
                      const AnisotropicEntries &entries,
                      const unsigned int        i,
                      const std::string        &which) const;

      std::vector<ElasticConstants> materials;
      unsigned int                  dim = 3;
      SpatialFactors                factors;
      IsotropicFields               fields;
      TensorFields                  tensors;
      bool                          by_speeds = true;
      /// Whether material i is isotropic with constants given as functions
      /// (anisotropic materials ignore the isotropic entries).
      std::vector<bool> functions;
      /// Each material's own axes in model coordinates (the columns; the
      /// identity for isotropic materials and unturned frames).
      std::vector<Tensor<2, 3>> frames;
    };
  } // namespace Material
} // namespace rupture

#endif
