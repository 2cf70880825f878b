#include <rupture/base/utilities.h>
#include <rupture/material/anisotropic_input.h>
#include <rupture/material/elastic_material.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <sstream>

namespace rupture
{
  namespace Material
  {
    double
    ElasticConstants::p_wave_speed() const
    {
      Assert(isotropic(), ExcInternalError());
      return std::sqrt((lambda + 2 * mu) / density);
    }



    double
    ElasticConstants::s_wave_speed() const
    {
      Assert(isotropic(), ExcInternalError());
      return std::sqrt(mu / density);
    }



    double
    ElasticConstants::youngs_modulus() const
    {
      Assert(isotropic(), ExcInternalError());
      return mu * (3 * lambda + 2 * mu) / (lambda + mu);
    }



    double
    ElasticConstants::poissons_ratio() const
    {
      Assert(isotropic(), ExcInternalError());
      return lambda / (2 * (lambda + mu));
    }



    template <int dim>
    SpeedRange
    ElasticConstants::wave_speeds() const
    {
      return (dim == 2) ? speeds_2d : speeds_3d;
    }



    template <int dim>
    SymmetricTensor<4, dim>
    ElasticConstants::stiffness() const
    {
      return stiffness_tensor<dim>(voigt);
    }



    template <int dim>
    SymmetricTensor<2, dim>
    ElasticConstants::stress(const SymmetricTensor<2, dim> &strain) const
    {
      if (isotropic())
        return lambda * trace(strain) * unit_symmetric_tensor<dim>() +
               2 * mu * strain;
      return stiffness<dim>() * strain;
    }



    namespace
    {
      /// The Christoffel matrix of @p c for a normal in @p dim dimensions.
      template <int dim>
      SymmetricTensor<2, dim>
      christoffel(const VoigtMatrix &c, const Tensor<1, dim> &n)
      {
        Tensor<1, 3> n3;
        for (unsigned int d = 0; d < dim; ++d)
          n3[d] = n[d];
        const SymmetricTensor<2, 3> g3 = christoffel_matrix(c, n3);
        SymmetricTensor<2, dim>     g;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int k = i; k < dim; ++k)
            g[i][k] = g3[i][k];
        return g;
      }
    } // namespace



    template <int dim>
    double
    ElasticConstants::shear_modulus_across(const Tensor<1, dim> &n) const
    {
      if (isotropic())
        return mu;
      const Tensor<1, dim>          unit = n / n.norm();
      const SymmetricTensor<2, dim> g    = christoffel<dim>(voigt, unit);
      return (trace(g) - unit * (g * unit)) / (dim - 1);
    }



    template <int dim>
    SymmetricTensor<2, dim>
    ElasticConstants::boundary_impedance(const Tensor<1, dim> &n) const
    {
      SymmetricTensor<2, dim> z;
      if (isotropic())
        {
          const double zp = density * p_wave_speed();
          const double zs = density * s_wave_speed();
          for (unsigned int c = 0; c < dim; ++c)
            {
              z[c][c] = zp * n[c] * n[c] + zs * (1 - n[c] * n[c]);
              for (unsigned int k = c + 1; k < dim; ++k)
                z[c][k] = (zp - zs) * n[c] * n[k];
            }
          return z;
        }
      // sqrt(rho Gamma) from the eigenpairs of Gamma.
      const auto pairs = eigenvectors(christoffel<dim>(voigt, n),
                                      SymmetricTensorEigenvectorMethod::jacobi);
      for (const auto &[value, vector] : pairs)
        {
          const double root = std::sqrt(density * std::max(value, 0.));
          for (unsigned int c = 0; c < dim; ++c)
            {
              z[c][c] += root * vector[c] * vector[c];
              for (unsigned int k = c + 1; k < dim; ++k)
                z[c][k] += root * vector[c] * vector[k];
            }
        }
      return z;
    }



    void
    ElasticMaterials::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Material");
      {
        prm.declare_entry(
          "Names",
          "rock",
          Patterns::Anything(),
          "Comma separated names of the materials, for output only. The i-th "
          "entry of every list in this section describes material id i of "
          "the scene (for the Northeast-Japan scene: 0 = crust, 1 = mantle, "
          "2 = plate; for Gmsh meshes: the physical tag of the volume).");
        prm.declare_entry(
          "Parametrization",
          "wave speeds",
          Patterns::Selection(
            "wave speeds|Young's modulus and Poisson's ratio"),
          "How the elastic constants are given: by P- and S-wave speeds, or "
          "by Young's modulus and Poisson's ratio.");
        prm.declare_entry("Density",
                          "2670",
                          Patterns::Anything(),
                          "Density of each material (kg/m^3), from 1e-3 to "
                          "1e6: numbers separated by ',', or numbers and "
                          "functions of x, y, z (z = 0 in 2-D) separated by "
                          "';', one per material or one for all. Functions "
                          "make an isotropic material's constants vary in "
                          "space independently of each other (checked at "
                          "the points of the mesh); an anisotropic "
                          "material's density is a number (see <Density "
                          "factor>).");
        prm.declare_entry("P-wave speed",
                          "6000",
                          Patterns::Anything(),
                          "P-wave speed of each material (m/s). Used with the "
                          "parametrization 'wave speeds'. Must exceed "
                          "sqrt(2) times the S-wave speed, which keeps "
                          "Poisson's ratio in (0, 0.5) (a negative ratio "
                          "can be given with the parametrization \"Young's "
                          "modulus and Poisson's ratio\"). Numbers or "
                          "functions of x, y, z, as <Density>.");
        prm.declare_entry("S-wave speed",
                          "3464",
                          Patterns::Anything(),
                          "S-wave speed of each material (m/s), > 0. Used "
                          "with the parametrization 'wave speeds'. Numbers "
                          "or functions of x, y, z, as <Density>.");
        prm.declare_entry("Young's modulus",
                          "8e10",
                          Patterns::Anything(),
                          "Young's modulus of each material (Pa), > 0. Used "
                          "with the parametrization \"Young's modulus and "
                          "Poisson's ratio\". Numbers or functions of x, y, "
                          "z, as <Density>.");
        prm.declare_entry("Poisson's ratio",
                          "0.25",
                          Patterns::Anything(),
                          "Poisson's ratio of each material, in (-1, 0.5). "
                          "Used with the parametrization \"Young's modulus "
                          "and Poisson's ratio\". Numbers or functions of x, "
                          "y, z, as <Density>.");
        prm.declare_entry(
          "Symmetry",
          "isotropic",
          Patterns::Anything(),
          "The symmetry class of each material (comma separated, or one for "
          "all): isotropic (given by <Parametrization> and its entries), "
          "transversely isotropic, orthotropic or general (given by "
          "<Stiffness> in the material's own frame, which <Material axes> "
          "turns into the model's). In 2-D (plane strain) an anisotropic "
          "material needs the model plane to be a plane of mirror symmetry.");
        prm.declare_entry(
          "Stiffness",
          "",
          Patterns::Anything(),
          "The stiffness constants of each anisotropic material in Voigt "
          "notation (Pa; indices 1-6 for 11, 22, 33, 23, 13, 12 of the "
          "material's frame), as 'C11 = 1.6e11, C33 = ...'; materials "
          "separated by ';' (an empty field for an isotropic one), or one "
          "field for all. Transversely isotropic (symmetry axis along the "
          "material's 3-axis): C11, C33, C13, C44, C66 (C12 = C11 - 2 C66). "
          "Orthotropic: C11, C22, C33, C12, C13, C23, C44, C55, C66. "
          "General: all 21 Cij with i <= j. Each constant is a number or a "
          "function of x, y, z (z = 0 in 2-D; commas inside parentheses), "
          "so that the anisotropy itself may vary in space. The tensor must "
          "be positive definite (where constants are functions: at every "
          "point of the material's cells).");
        prm.declare_entry(
          "Material axes",
          "",
          Patterns::Anything(),
          "The orientation of each anisotropic material's frame in model "
          "coordinates (materials separated by ';', or one field for all): "
          "empty (the model's axes), three numbers (transversely isotropic "
          "only: the symmetry axis, i.e. the material's 3-axis), or six "
          "numbers (the material's 1-axis, then its 2-axis; orthogonal; the "
          "3-axis completes a right-handed frame). Vectors have three "
          "components also in 2-D, where the third is normal to the model "
          "plane.");
        prm.declare_entry(
          "Stiffness factor",
          "1",
          Patterns::Anything(),
          "Constants that vary in space: a factor of each material's whole "
          "stiffness (Lame's constants or the anisotropic tensor), a "
          "function of x, y, z (z = 0 in 2-D) or a number; materials "
          "separated by ';', or one for all. It must be positive on the "
          "material's cells. Wave speeds scale with the square root of "
          "<Stiffness factor> / <Density factor>.");
        prm.declare_entry(
          "Density factor",
          "1",
          Patterns::Anything(),
          "A factor of each material's density, a function of x, y, z (z = "
          "0 in 2-D) or a number; materials separated by ';', or one for "
          "all. It must be positive on the material's cells.");
      }
      prm.leave_subsection();
    }



    namespace
    {
      /// In m/s: wave speeds above it are a unit error.
      constexpr double speed_of_light = 299792458;



      /// A number as the screen shows it (six digits), not as to_string()'s
      /// fixed-point (300 digits for 1e300).
      std::string
      short_number(const double x)
      {
        std::ostringstream out;
        out << x;
        return out.str();
      }



      /**
       * Density and Lame's constants of an isotropic material of density
       * @p density from @p a and @p b (P- and S-wave speeds, or Young's
       * modulus and Poisson's ratio), unchecked.
       */
      void
      set_lame(ElasticConstants &m,
               const double      density,
               const double      a,
               const double      b,
               const bool        by_speeds)
      {
        m.density = density;
        if (by_speeds)
          {
            m.mu     = m.density * b * b;
            m.lambda = m.density * a * a - 2 * m.mu;
          }
        else
          {
            m.mu     = a / (2 * (1 + b));
            m.lambda = a * b / ((1 + b) * (1 - 2 * b));
          }
      }



      /// set_lame() and the tensor and wave speeds that follow, unchecked.
      void
      set_isotropic(ElasticConstants &m,
                    const double      density,
                    const double      a,
                    const double      b,
                    const bool        by_speeds)
      {
        set_lame(m, density, a, b, by_speeds);
        m.voigt         = isotropic_voigt_matrix(m.lambda, m.mu);
        const double vp = std::sqrt((m.lambda + 2 * m.mu) / m.density);
        const double vs = std::sqrt(m.mu / m.density);
        m.speeds_2d     = {vs, vp};
        m.speeds_3d     = {vs, vp};
      }



      /**
       * The message for a density not allowed, naming the entry and
       * which() (" of material 0 (rock)", perhaps with the point); empty if
       * allowed. which() is called only to write the message.
       */
      template <typename Which>
      std::string
      density_complaint(const double density, const Which &which)
      {
        // Far outside this range the mass matrix over- or underflows (a
        // density of 1e308 times a cell's volume).
        if (density >= 1e-3 && density <= 1e6)
          return "";
        std::ostringstream message;
        message << "<Material/Density>" << which() << " is " << density
                << " kg/m^3. Allowed: densities from 1e-3 to 1e6 kg/m^3 (SI "
                   "units; rock is about 2700).";
        return message.str();
      }



      /// Throws density_complaint() unless @p density is allowed.
      void
      check_density(const double density, const std::string &which)
      {
        const std::string complaint =
          density_complaint(density, [&]() { return which; });
        AssertThrow(complaint.empty(), ExcMessage(complaint));
      }



      /**
       * The one set of rules for isotropic values: the message for the
       * first of @p density, @p a, @p b (P- and S-wave speeds, or Young's
       * modulus and Poisson's ratio) that is not allowed, or for constants
       * that follow from them out of range, naming the entry and which();
       * empty if all are allowed. which() is called only to write the
       * message, so that checking many points costs a few operations each.
       */
      template <typename Which>
      std::string
      isotropic_complaint(const double density,
                          const double a,
                          const double b,
                          const bool   by_speeds,
                          const Which &which)
      {
        std::string complaint = density_complaint(density, which);
        if (!complaint.empty())
          return complaint;
        if (by_speeds)
          {
            const double vp = a, vs = b;
            if (!(vs > 0 && std::isfinite(vs)))
              return "<Material/S-wave speed>" + which() + " is " +
                     short_number(vs) + ", but it must be > 0 (m/s).";
            if (!(vp > std::sqrt(2.) * vs && std::isfinite(vp)))
              return "<Material/P-wave speed>" + which() + " is " +
                     short_number(vp) +
                     " m/s, but it must exceed sqrt(2) times the "
                     "S-wave speed (" +
                     short_number(std::sqrt(2.) * vs) +
                     " m/s); otherwise Lame's lambda is negative "
                     "and Poisson's ratio is < 0 (this program "
                     "requires 0 < Poisson's ratio < 0.5 when "
                     "wave speeds are given).";
          }
        else
          {
            const double E = a, nu = b;
            if (!(E > 0 && std::isfinite(E)))
              return "<Material/Young's modulus>" + which() + " is " +
                     short_number(E) + ", but it must be > 0 (Pa).";
            if (!(nu > -1 && nu < 0.5))
              return "<Material/Poisson's ratio>" + which() + " is " +
                     short_number(nu) +
                     ", but it must lie in (-1, 0.5); 0.5 "
                     "is an incompressible material, "
                     "which this displacement formulation "
                     "cannot represent.";
          }
        // Each value may be fine and their combination overflow (a
        // density of 1e308 times a squared wave speed).
        ElasticConstants m;
        set_lame(m, density, a, b, by_speeds);
        const double vp = m.p_wave_speed(), vs = m.s_wave_speed();
        // Wave speeds above the speed of light are a unit error (the
        // program works in SI units), and they would make the explicit
        // step, which scales with h / vp, vanishingly small.
        if (std::isfinite(m.mu) && std::isfinite(m.lambda) &&
            std::isfinite(vp) && std::isfinite(vs) && vp > 0 && vs > 0 &&
            vp <= speed_of_light)
          return "";
        return "The elastic constants" + which() +
               " are out of range: from its "
               "<Material/Density>, <Material/P-wave "
               "speed> and <Material/S-wave speed> (or, "
               "by <Material/Parametrization>, "
               "<Material/Young's modulus> and "
               "<Material/Poisson's ratio>) (density " +
               short_number(m.density) +
               " kg/m^3) follow mu = " + short_number(m.mu) +
               " Pa, lambda = " + short_number(m.lambda) +
               " Pa, vp = " + short_number(vp) +
               " m/s and vs = " + short_number(vs) +
               " m/s. Allowed: values whose moduli and "
               "wave speeds are finite and positive, the "
               "wave speeds below the speed of light (in "
               "SI units: e.g. 2700 kg/m^3, 6000 and "
               "3464 m/s).";
      }



      /// set_isotropic() with the values checked: throws
      /// isotropic_complaint() otherwise.
      void
      set_checked_isotropic(ElasticConstants  &m,
                            const double       density,
                            const double       a,
                            const double       b,
                            const bool         by_speeds,
                            const std::string &which)
      {
        const std::string complaint =
          isotropic_complaint(density, a, b, by_speeds, [&]() {
            return which;
          });
        AssertThrow(complaint.empty(), ExcMessage(complaint));
        set_isotropic(m, density, a, b, by_speeds);
      }



      /// The constants with the stiffness times @p s, the density times
      /// @p r.
      void
      scale(ElasticConstants &m, const double s, const double r)
      {
        m.lambda *= s;
        m.mu *= s;
        for (auto &row : m.voigt)
          for (double &x : row)
            x *= s;
        m.density *= r;
        for (SpeedRange *range : {&m.speeds_2d, &m.speeds_3d})
          {
            range->slowest *= std::sqrt(s / r);
            range->fastest *= std::sqrt(s / r);
          }
      }
    } // namespace



    void
    ElasticMaterials::parse_parameters(ParameterHandler  &prm,
                                       const unsigned int dimension)
    {
      materials.clear();
      dim = dimension;
      prm.enter_subsection("Material");
      {
        const std::vector<std::string> names =
          Utilities::split_list(prm.get("Names"));
        AssertThrow(!names.empty(),
                    ExcMessage("The entry <Material/Names> must name at least "
                               "one material."));
        const unsigned int n = names.size();
        materials.resize(n);
        by_speeds = (prm.get("Parametrization") == "wave speeds");
        fields.parse(prm, names, by_speeds);

        const AnisotropicEntries anisotropic =
          read_anisotropic_entries(prm, names);
        tensors.parse(anisotropic, names, dim);
        functions.assign(n, false);
        for (unsigned int i = 0; i < n; ++i)
          functions[i] = (anisotropic.symmetry[i] == Symmetry::isotropic &&
                          fields.varies(i));
        frames.assign(n, Tensor<2, 3>(unit_symmetric_tensor<3>()));
        factors.parse(prm, names);

        for (unsigned int i = 0; i < n; ++i)
          {
            ElasticConstants &m = materials[i];
            m.name              = names[i];
            const std::string which =
              " of material " + std::to_string(i) + " (" + names[i] + ")";
            const std::array<double, 3> v = fields.numbers(i);
            if (anisotropic.symmetry[i] != Symmetry::isotropic)
              {
                AssertThrow(!std::isnan(v[0]),
                            ExcMessage(
                              "<Material/Density>" + which +
                              " is a function, but the material is "
                              "anisotropic. Allowed: a number (its density "
                              "may vary in space by <Material/Density "
                              "factor>)."));
                check_density(v[0], which);
                m.density = v[0];
                set_anisotropic(m, anisotropic, i, which);
                frames[i] = material_axes(anisotropic, i, which);
                continue;
              }
            if (functions[i])
              {
                // Checked at the mesh's points (check_on_mesh()); the
                // constants themselves are at().
                m.density = m.lambda = m.mu =
                  std::numeric_limits<double>::quiet_NaN();
                continue;
              }
            set_checked_isotropic(m, v[0], v[1], v[2], by_speeds, which);
          }

        // Factors given as numbers are folded into the constants.
        for (unsigned int i = 0; i < n; ++i)
          {
            const double s = factors.constant_stiffness(i);
            const double r = factors.constant_density(i);
            if ((s == 1 && r == 1) || functions[i])
              continue;
            ElasticConstants &m = materials[i];
            scale(m, s, r);
            const SpeedRange  &v = (dim == 2 ? m.speeds_2d : m.speeds_3d);
            std::ostringstream message;
            message << "<Material/Stiffness factor> " << s
                    << " and <Material/Density factor> " << r << " of material "
                    << i << " (" << m.name << ") make its density " << m.density
                    << " kg/m^3 and its wave speeds " << v.slowest << " to "
                    << v.fastest
                    << " m/s. Allowed: densities from 1e-3 to 1e6 kg/m^3 "
                       "and speeds below the speed of light (SI units).";
            AssertThrow(m.density >= 1e-3 && m.density <= 1e6 &&
                          v.fastest <= speed_of_light,
                        ExcMessage(message.str()));
          }
      }
      prm.leave_subsection();
    }



    template <int dim_>
    ElasticConstants
    ElasticMaterials::at(const types::material_id id,
                         const Point<dim_>       &p) const
    {
      Assert(id < materials.size(), ExcIndexRange(id, 0, materials.size()));
      ElasticConstants m = materials[id];
      if (functions[id])
        {
          const std::array<double, 3> v = fields.values(id, p);
          set_isotropic(m, v[0], v[1], v[2], by_speeds);
        }
      else if (tensors.varies(id))
        {
          // (The constant factors are folded into the reference and the
          // density, not into the functions.)
          m.voigt               = tensors.value(id, p);
          const double constant = factors.constant_stiffness(id);
          if (constant != 1)
            for (auto &row : m.voigt)
              for (double &x : row)
                x *= constant;
        }
      const double s = factors.stiffness(id, p), r = factors.density(id, p);
      if (s != 1 || r != 1 || functions[id])
        scale(m,
              functions[id] ? s * factors.constant_stiffness(id) : s,
              functions[id] ? r * factors.constant_density(id) : r);
      return m;
    }



    ElasticConstants
    ElasticMaterials::reference(const types::material_id id,
                                const double             kappa) const
    {
      Assert(id < materials.size(), ExcIndexRange(id, 0, materials.size()));
      if (!functions[id])
        return materials[id];
      ElasticConstants r = materials[id];
      r.density          = 1;
      r.mu               = 1;
      r.lambda           = kappa;
      r.voigt            = isotropic_voigt_matrix(r.lambda, r.mu);
      r.speeds_2d = r.speeds_3d = {1, std::sqrt(r.lambda + 2)};
      return r;
    }



    template <int dim_>
    std::array<double, 3>
    ElasticMaterials::reference_ratios(const types::material_id id,
                                       const Point<dim_>       &p) const
    {
      // (A tensor given as functions takes extreme_ratios().)
      AssertThrow(!tensors.varies(id),
                  ExcMessage("reference_ratios() of a material whose "
                             "tensor varies: use extreme_ratios()."));
      if (!functions[id])
        return {factors.stiffness(id, p),
                factors.density(id, p),
                std::numeric_limits<double>::quiet_NaN()};
      const ElasticConstants m = at(id, p);
      return {m.mu, m.density, m.lambda};
    }



    template <int dim_>
    std::vector<std::int64_t>
    ElasticMaterials::rounded_tensor(const types::material_id id,
                                     const Point<dim_>       &p) const
    {
      // (In 2-D the in-plane rows alone: the others do not enter the
      // model.)
      const std::vector<unsigned int> rows =
        (dim_ == 2 ? std::vector<unsigned int>{0, 1, 5} :
                     std::vector<unsigned int>{0, 1, 2, 3, 4, 5});
      VoigtMatrix c       = tensors.value(id, p);
      double      largest = 0;
      for (const unsigned int I : rows)
        largest = std::max(largest, c[I][I]);
      if (!(largest > 1e-200 && largest < 1e200))
        return {};
      if (dim_ == 2)
        {
          // The out-of-plane part replaced by a decoupled multiple of the
          // identity, which the checks below then pass.
          for (unsigned int I = 0; I < 6; ++I)
            for (unsigned int J = 0; J < 6; ++J)
              {
                const bool in_plane = (I < 2 || I == 5) && (J < 2 || J == 5);
                if (!in_plane)
                  c[I][J] = (I == J ? largest : 0.);
              }
        }
      const double       bin = std::log(1.01);
      const std::int64_t exponent =
        static_cast<std::int64_t>(std::ceil(std::log(largest) / bin));
      std::vector<std::int64_t> key  = {exponent};
      const double              unit = 0.01 * std::exp(exponent * bin);
      for (unsigned int I = 0; I < 6; ++I)
        for (unsigned int J = I; J < 6; ++J)
          {
            const double x = c[I][J] / unit;
            // (|x| is at most about 100 for a positive definite tensor.)
            if (!(std::abs(x) < 1e6))
              return {};
            key.push_back(std::llround(x));
          }
      if (!positive_definite_enough(rounded_tensor_value(key, 0), 1e-3))
        return {};
      return key;
    }



    VoigtMatrix
    ElasticMaterials::rounded_tensor_value(const std::vector<std::int64_t> &key,
                                           const std::size_t first)
    {
      const double unit = 0.01 * std::exp(key[first] * std::log(1.01));
      VoigtMatrix  c{};
      std::size_t  k = first + 1;
      for (unsigned int I = 0; I < 6; ++I)
        for (unsigned int J = I; J < 6; ++J)
          c[I][J] = c[J][I] = key[k++] * unit;
      return c;
    }



    ElasticConstants
    ElasticMaterials::local_reference(const types::material_id id,
                                      const VoigtMatrix       &c) const
    {
      ElasticConstants m = materials[id];
      m.voigt            = c;
      const double s     = factors.constant_stiffness(id);
      for (auto &row : m.voigt)
        for (double &x : row)
          x *= s;
      return m;
    }



    template <int dim_>
    std::array<double, 2>
    ElasticMaterials::extreme_ratios(const types::material_id        id,
                                     const std::vector<Point<dim_>> &points,
                                     const EnergyRatio *local) const
    {
      LargestRatio s(local ? *local : tensors.energy_ratio(id));
      double       r = std::numeric_limits<double>::infinity();
      for (const Point<dim_> &p : points)
        {
          s.add(tensors.value(id, p), factors.stiffness(id, p));
          r = std::min(r, factors.density(id, p));
        }
      return {s.largest(), r};
    }



    template <int dim_>
    double
    ElasticMaterials::check_on_mesh(const Triangulation<dim_> &mesh,
                                    const unsigned int         degree,
                                    const MPI_Comm communicator) const
    {
      const std::vector<double> scale =
        factors.check(mesh, degree, communicator);
      double fastest = 0;
      for (unsigned int i = 0; i < materials.size(); ++i)
        if (!functions[i] && !tensors.varies(i))
          fastest =
            std::max(fastest,
                     scale[i] *
                       materials[i].template wave_speeds<dim_>().fastest);
      if (tensors.varies())
        fastest = std::max(fastest, check_tensors(mesh, degree, communicator));
      if (!has_functions())
        return dealii::Utilities::MPI::max(fastest, communicator);

      // Constants given as functions: every value allowed at every point
      // of the material's cells, the factors included, by the rules of
      // numbers (isotropic_complaint()). Messages are written for a
      // failing point only, which keeps this at a few function
      // evaluations per point.
      std::string error;
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->is_locally_owned() && error.empty() &&
            cell->material_id() < materials.size() &&
            functions[cell->material_id()])
          for (const Point<dim_> &p : check_points<dim_>(cell, degree))
            {
              const types::material_id    id    = cell->material_id();
              const std::array<double, 3> v     = fields.values(id, p);
              const auto                  which = [&]() {
                std::ostringstream text;
                text << " of material " << id << " (" << materials[id].name
                     << ") at (" << p << ")";
                return text.str();
              };
              error = isotropic_complaint(v[0], v[1], v[2], by_speeds, which);
              if (!error.empty())
                break;
              const double s = factors.stiffness(id, p) *
                               factors.constant_stiffness(id),
                           r = factors.density(id, p) *
                               factors.constant_density(id);
              ElasticConstants m;
              set_lame(m, v[0], v[1], v[2], by_speeds);
              const double vp = m.p_wave_speed() * std::sqrt(s / r);
              if (m.density * r >= 1e-3 && m.density * r <= 1e6 &&
                  vp <= speed_of_light)
                {
                  fastest = std::max(fastest, vp);
                  continue;
                }
              std::ostringstream message;
              message << "<Material/Stiffness factor> and <Material/"
                         "Density factor>"
                      << which() << " make its density " << m.density * r
                      << " kg/m^3 and its P-wave speed " << vp
                      << " m/s. Allowed: densities from 1e-3 to 1e6 "
                         "kg/m^3 and speeds below the speed of light "
                         "(SI units).";
              error = message.str();
              break;
            }
      Utilities::throw_if_any(error, communicator);
      return dealii::Utilities::MPI::max(fastest, communicator);
    }



    template <int dim_>
    double
    ElasticMaterials::check_tensors(const Triangulation<dim_> &mesh,
                                    const unsigned int         degree,
                                    const MPI_Comm communicator) const
    {
      // At every point of the material's cells: each constant allowed,
      // the tensor positive definite (in 2-D the model plane a mirror
      // plane), and the fastest wave speed bounded by the energy ratio to
      // the reference: rho(p) v^2 = eps : c(p) : eps for a unit strain
      // eps = sym(polarisation x direction), at most ratio(p) s(p) times
      // the reference's.
      // (The energy ratio's eigenvalue problem is solved only where a point
      // may raise the fastest speed so far: LargestRatio.)
      std::string                                error;
      double                                     fastest = 0;
      VoigtMatrix                                c;
      std::vector<std::unique_ptr<LargestRatio>> largest(materials.size());
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->is_locally_owned() && error.empty() &&
            cell->material_id() < materials.size() &&
            tensors.varies(cell->material_id()))
          for (const Point<dim_> &p : check_points<dim_>(cell, degree))
            {
              const types::material_id id = cell->material_id();
              error                       = tensors.checked_value(id, p, c);
              if (!error.empty())
                break;
              const double s = factors.stiffness(id, p),
                           r = factors.density(id, p);
              if (!largest[id])
                largest[id] =
                  std::make_unique<LargestRatio>(tensors.energy_ratio(id));
              // (The speed as before the certificate: ratio s / r.)
              const double ratio = largest[id]->add(c, s / r);
              if (ratio < 0)
                continue;
              const double v =
                std::sqrt(ratio * s / r) *
                materials[id].template wave_speeds<dim_>().fastest;
              if (v <= speed_of_light)
                {
                  fastest = std::max(fastest, v);
                  continue;
                }
              std::ostringstream message;
              message << "<Material/Stiffness> of material " << id << " ("
                      << materials[id].name << ") at (" << p
                      << ") with its <Material/Density> and factors allows "
                         "wave speeds up to "
                      << v
                      << " m/s. Allowed: speeds below the speed of light "
                         "(SI units: Pa and kg/m^3).";
              error = message.str();
              break;
            }
      Utilities::throw_if_any(error, communicator);
      return dealii::Utilities::MPI::max(fastest, communicator);
    }



    void
    ElasticMaterials::set_anisotropic(ElasticConstants         &m,
                                      const AnisotropicEntries &entries,
                                      const unsigned int        i,
                                      const std::string        &which) const
    {
      m.symmetry = entries.symmetry[i];
      m.lambda   = std::numeric_limits<double>::quiet_NaN();
      m.mu       = std::numeric_limits<double>::quiet_NaN();
      // (Constants that are functions: the reference tensor, whose class
      // of mirror planes check_on_mesh() checks at each point.)
      const bool function = tensors.varies(i);
      m.voigt             = function ? tensors.reference(i) :
                                       anisotropic_stiffness(entries, i, which);
      const bool mirror   = function || model_plane_is_mirror_plane(m.voigt);
      AssertThrow(
        dim == 3 || mirror,
        ExcMessage(
          "Material" + which.substr(std::string(" of material").size()) +
          " is anisotropic, and in the model's frame (after <Material/"
          "Material axes>) its tensor couples in-plane strains to "
          "out-of-plane shear stresses (C14, C15, C24, C25, C46 or C56 is "
          "not zero): the plane of x and y is not a mirror plane, so "
          "in-plane and out-of-plane motions couple, which the 2-D "
          "plane-strain model cannot represent. Orient the material so "
          "that one of its symmetry planes is the model plane (for a "
          "transversely isotropic one: its axis in the plane or normal to "
          "it), or run in 3-D (<Dimension> = 3)."));
      m.speeds_3d = speed_range<3>(m.voigt, m.density);
      if (mirror)
        m.speeds_2d = speed_range<2>(m.voigt, m.density);
      else
        m.speeds_2d = {std::numeric_limits<double>::quiet_NaN(),
                       std::numeric_limits<double>::quiet_NaN()};
      const SpeedRange  &s = (dim == 2 ? m.speeds_2d : m.speeds_3d);
      std::ostringstream message;
      message << "The stiffness given by <Material/Stiffness>" << which
              << " with its <Material/Density> (" << m.density
              << " kg/m^3) gives phase speeds from " << s.slowest << " to "
              << s.fastest
              << " m/s. Allowed: positive speeds below the speed of light "
                 "(SI units: Pa and kg/m^3).";
      AssertThrow(s.slowest > 0 && s.fastest <= speed_of_light &&
                    std::isfinite(s.fastest),
                  ExcMessage(message.str()));
    }



    bool
    ElasticMaterials::any_anisotropic() const
    {
      return std::any_of(materials.begin(),
                         materials.end(),
                         [](const ElasticConstants &m) {
                           return !m.isotropic();
                         });
    }



    const ElasticConstants &
    ElasticMaterials::get(const types::material_id id) const
    {
      Assert(id < materials.size(), ExcIndexRange(id, 0, materials.size()));
      return materials[id];
    }



    unsigned int
    ElasticMaterials::n_materials() const
    {
      return materials.size();
    }



    void
    ElasticMaterials::check_material_id(const types::material_id id) const
    {
      AssertThrow(id < materials.size(),
                  ExcMessage("The mesh uses material id " + std::to_string(id) +
                             ", but the Material section describes only " +
                             std::to_string(materials.size()) +
                             " material(s) (ids 0 to " +
                             std::to_string(materials.size() - 1) +
                             "). Add entries to <Material/Names> and the "
                             "property lists."));
    }



    std::string
    ElasticMaterials::summary() const
    {
      std::ostringstream out;
      for (unsigned int i = 0; i < materials.size(); ++i)
        {
          const auto &m = materials[i];
          if (tensors.varies(i))
            {
              const SpeedRange &s = (dim == 2 ? m.speeds_2d : m.speeds_3d);
              out << "   Material " << i << " (" << m.name
                  << "): rho = " << m.density << " kg/m^3, "
                  << symmetry_names()[static_cast<int>(m.symmetry)]
                  << ", constants that vary in space (functions of x, y, "
                     "z): "
                  << tensors.text(i) << "; the reference for bounds"
                  << " has phase speeds " << std::setprecision(6) << s.slowest
                  << " to " << s.fastest << " m/s\n";
              continue;
            }
          if (!m.isotropic())
            {
              // The extreme phase speeds over all directions (in 2-D: in
              // the model plane), then those along each model axis.
              const SpeedRange &s = (dim == 2 ? m.speeds_2d : m.speeds_3d);
              out << "   Material " << i << " (" << m.name
                  << "): rho = " << m.density << " kg/m^3, "
                  << symmetry_names()[static_cast<int>(m.symmetry)]
                  << ", phase speeds " << std::setprecision(6) << s.slowest
                  << " to " << s.fastest << " m/s;";
              for (unsigned int d = 0; d < dim; ++d)
                {
                  Tensor<1, 3> n;
                  n[d]                    = 1;
                  std::array<double, 3> v = phase_speeds(m.voigt, m.density, n);
                  if (dim == 2)
                    {
                      // In-plane polarisations only.
                      const auto w =
                        in_plane_phase_speeds(m.voigt, m.density, n);
                      v[0] = w[0];
                      v[1] = w[1];
                    }
                  out << " along "
                      << "xyz"[d] << ": " << v[0] << ", " << v[1];
                  if (dim == 3)
                    out << ", " << v[2];
                  out << " m/s" << (d + 1 < dim ? ";" : "\n");
                }
              // Where the material's frame is turned: its principal speeds
              // (qP, qS1, qS2 along each of its own axes, 3-D waves).
              if (i < frames.size() &&
                  (frames[i] - Tensor<2, 3>(unit_symmetric_tensor<3>()))
                      .norm() > 1e-12)
                {
                  out << "     along the material's own axes:";
                  for (unsigned int a = 0; a < 3; ++a)
                    {
                      Tensor<1, 3> n;
                      for (unsigned int d = 0; d < 3; ++d)
                        n[d] = frames[i][d][a] + 0.; // (no -0)
                      const std::array<double, 3> v =
                        phase_speeds(m.voigt, m.density, n);
                      out << " " << a + 1 << "-axis (" << n[0] << ", " << n[1]
                          << ", " << n[2] << "): " << v[0] << ", " << v[1]
                          << ", " << v[2] << " m/s" << (a < 2 ? ";" : "\n");
                    }
                }
              continue;
            }
          if (functions[i])
            {
              const auto &e = fields.entries();
              out << "   Material " << i << " (" << m.name
                  << "): constants that vary in space (functions of x, y, "
                     "z): "
                  << e[0] << " = " << fields.text(0, i) << ", " << e[1] << " = "
                  << fields.text(1, i) << ", " << e[2] << " = "
                  << fields.text(2, i) << "\n";
              continue;
            }
          out << "   Material " << i << " (" << m.name
              << "): rho = " << m.density
              << " kg/m^3, vp = " << std::setprecision(6) << m.p_wave_speed()
              << " m/s, vs = " << m.s_wave_speed()
              << " m/s, E = " << m.youngs_modulus()
              << " Pa, nu = " << m.poissons_ratio() << "\n";
        }
      if (factors.varies())
        out << "   Constants vary in space: <Material/Stiffness factor> and "
               "<Material/Density factor> multiply the values above.\n";
      return out.str();
    }


#define RUPTURE_INSTANTIATE(dim)                                               \
  template SpeedRange              ElasticConstants::wave_speeds<dim>() const; \
  template SymmetricTensor<4, dim> ElasticConstants::stiffness<dim>() const;   \
  template SymmetricTensor<2, dim> ElasticConstants::stress<dim>(              \
    const SymmetricTensor<2, dim> &) const;                                    \
  template double ElasticConstants::shear_modulus_across<dim>(                 \
    const Tensor<1, dim> &) const;                                             \
  template SymmetricTensor<2, dim> ElasticConstants::boundary_impedance<dim>(  \
    const Tensor<1, dim> &) const;
    RUPTURE_INSTANTIATE(2)
    RUPTURE_INSTANTIATE(3)
#undef RUPTURE_INSTANTIATE
    template std::vector<std::int64_t>
    ElasticMaterials::rounded_tensor<2>(const types::material_id,
                                        const Point<2> &) const;
    template std::vector<std::int64_t>
    ElasticMaterials::rounded_tensor<3>(const types::material_id,
                                        const Point<3> &) const;
    template std::array<double, 2>
    ElasticMaterials::extreme_ratios<2>(const types::material_id,
                                        const std::vector<Point<2>> &,
                                        const EnergyRatio *) const;
    template std::array<double, 2>
    ElasticMaterials::extreme_ratios<3>(const types::material_id,
                                        const std::vector<Point<3>> &,
                                        const EnergyRatio *) const;
    template double
    ElasticMaterials::check_tensors<2>(const Triangulation<2> &,
                                       const unsigned int,
                                       const MPI_Comm) const;
    template double
    ElasticMaterials::check_tensors<3>(const Triangulation<3> &,
                                       const unsigned int,
                                       const MPI_Comm) const;
    template double
    ElasticMaterials::check_on_mesh<2>(const Triangulation<2> &,
                                       const unsigned int,
                                       const MPI_Comm) const;
    template double
    ElasticMaterials::check_on_mesh<3>(const Triangulation<3> &,
                                       const unsigned int,
                                       const MPI_Comm) const;
    template ElasticConstants
    ElasticMaterials::at<2>(const types::material_id, const Point<2> &) const;
    template ElasticConstants
    ElasticMaterials::at<3>(const types::material_id, const Point<3> &) const;
    template std::array<double, 3>
    ElasticMaterials::reference_ratios<2>(const types::material_id,
                                          const Point<2> &) const;
    template std::array<double, 3>
    ElasticMaterials::reference_ratios<3>(const types::material_id,
                                          const Point<3> &) const;
  } // namespace Material
} // namespace rupture
