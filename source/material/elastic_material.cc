#include <rupture/base/utilities.h>
#include <rupture/material/elastic_material.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace rupture
{
  namespace Material
  {
    double
    ElasticConstants::p_wave_speed() const
    {
      return std::sqrt((lambda + 2 * mu) / density);
    }



    double
    ElasticConstants::s_wave_speed() const
    {
      return std::sqrt(mu / density);
    }



    double
    ElasticConstants::youngs_modulus() const
    {
      return mu * (3 * lambda + 2 * mu) / (lambda + mu);
    }



    double
    ElasticConstants::poissons_ratio() const
    {
      return lambda / (2 * (lambda + mu));
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
                          "Density of each material (kg/m^3), > 0.");
        prm.declare_entry("P-wave speed",
                          "6000",
                          Patterns::Anything(),
                          "P-wave speed of each material (m/s). Used with the "
                          "parametrization 'wave speeds'. Must exceed "
                          "sqrt(2) times the S-wave speed, which keeps "
                          "Poisson's ratio in (0, 0.5) (a negative ratio "
                          "can be given with the parametrization \"Young's "
                          "modulus and Poisson's ratio\").");
        prm.declare_entry("S-wave speed",
                          "3464",
                          Patterns::Anything(),
                          "S-wave speed of each material (m/s), > 0. Used "
                          "with the parametrization 'wave speeds'.");
        prm.declare_entry("Young's modulus",
                          "8e10",
                          Patterns::Anything(),
                          "Young's modulus of each material (Pa), > 0. Used "
                          "with the parametrization \"Young's modulus and "
                          "Poisson's ratio\".");
        prm.declare_entry("Poisson's ratio",
                          "0.25",
                          Patterns::Anything(),
                          "Poisson's ratio of each material, in (-1, 0.5). "
                          "Used with the parametrization \"Young's modulus "
                          "and Poisson's ratio\".");
      }
      prm.leave_subsection();
    }



    namespace
    {
      /// A number as the screen shows it (six digits), not as to_string()'s
      /// fixed-point (300 digits for 1e300).
      std::string
      short_number(const double x)
      {
        std::ostringstream out;
        out << x;
        return out.str();
      }



      std::vector<double>
      read_list(ParameterHandler  &prm,
                const std::string &entry,
                const unsigned int n)
      {
        const std::vector<double> values =
          Utilities::parse_doubles(prm.get(entry), "Material/" + entry);
        AssertThrow(values.size() == n || values.size() == 1,
                    ExcMessage("The entry <Material/" + entry + "> has " +
                               std::to_string(values.size()) +
                               " values, but <Material/Names> lists " +
                               std::to_string(n) +
                               " materials. Give one value per material, or "
                               "a single value for all of them."));
        if (values.size() == 1)
          return std::vector<double>(n, values[0]);
        return values;
      }
    } // namespace



    void
    ElasticMaterials::parse_parameters(ParameterHandler &prm)
    {
      materials.clear();
      prm.enter_subsection("Material");
      {
        const std::vector<std::string> names =
          Utilities::split_list(prm.get("Names"));
        AssertThrow(!names.empty(),
                    ExcMessage("The entry <Material/Names> must name at least "
                               "one material."));
        const unsigned int  n       = names.size();
        std::vector<double> density = read_list(prm, "Density", n);

        materials.resize(n);
        const bool by_speeds = (prm.get("Parametrization") == "wave speeds");
        std::vector<double> a, b;
        if (by_speeds)
          {
            a = read_list(prm, "P-wave speed", n);
            b = read_list(prm, "S-wave speed", n);
          }
        else
          {
            a = read_list(prm, "Young's modulus", n);
            b = read_list(prm, "Poisson's ratio", n);
          }

        for (unsigned int i = 0; i < n; ++i)
          {
            ElasticConstants &m = materials[i];
            m.name              = names[i];
            const std::string which =
              " of material " + std::to_string(i) + " (" + names[i] + ")";
            {
              // Far outside this range the mass matrix over- or underflows
              // (a density of 1e308 times a cell's volume).
              std::ostringstream message;
              message << "<Material/Density>" << which << " is " << density[i]
                      << " kg/m^3. Allowed: densities from 1e-3 to 1e6 kg/m^3 "
                         "(SI units; rock is about 2700).";
              AssertThrow(density[i] >= 1e-3 && density[i] <= 1e6,
                          ExcMessage(message.str()));
            }
            m.density = density[i];
            if (by_speeds)
              {
                const double vp = a[i], vs = b[i];
                AssertThrow(vs > 0 && std::isfinite(vs),
                            ExcMessage("<Material/S-wave speed>" + which +
                                       " is " + short_number(vs) +
                                       ", but it must be > 0 (m/s)."));
                AssertThrow(vp > std::sqrt(2.) * vs && std::isfinite(vp),
                            ExcMessage(
                              "<Material/P-wave speed>" + which + " is " +
                              short_number(vp) +
                              " m/s, but it must exceed sqrt(2) times the "
                              "S-wave speed (" +
                              short_number(std::sqrt(2.) * vs) +
                              " m/s); otherwise Lame's lambda is negative "
                              "and Poisson's ratio is < 0 (this program "
                              "requires 0 < Poisson's ratio < 0.5 when "
                              "wave speeds are given)."));
                m.mu     = m.density * vs * vs;
                m.lambda = m.density * vp * vp - 2 * m.mu;
              }
            else
              {
                const double E = a[i], nu = b[i];
                AssertThrow(E > 0 && std::isfinite(E),
                            ExcMessage("<Material/Young's modulus>" + which +
                                       " is " + short_number(E) +
                                       ", but it must be > 0 (Pa)."));
                AssertThrow(nu > -1 && nu < 0.5,
                            ExcMessage("<Material/Poisson's ratio>" + which +
                                       " is " + short_number(nu) +
                                       ", but it must lie in (-1, 0.5); 0.5 "
                                       "is an incompressible material, "
                                       "which this displacement formulation "
                                       "cannot represent."));
                m.mu     = E / (2 * (1 + nu));
                m.lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
              }
            // Each value may be fine and their combination overflow (a
            // density of 1e308 times a squared wave speed).
            const double vp = m.p_wave_speed(), vs = m.s_wave_speed();
            const auto   number = [](const double x) {
              std::ostringstream out;
              out << x;
              return out.str();
            };
            // Wave speeds above the speed of light are a unit error (the
            // program works in SI units), and they would make the explicit
            // step, which scales with h / vp, vanishingly small.
            const double speed_of_light = 299792458;
            AssertThrow(std::isfinite(m.mu) && std::isfinite(m.lambda) &&
                          std::isfinite(vp) && std::isfinite(vs) && vp > 0 &&
                          vs > 0 && vp <= speed_of_light,
                        ExcMessage("The elastic constants" + which +
                                   " are out of range: from its "
                                   "<Material/Density>, <Material/P-wave "
                                   "speed> and <Material/S-wave speed> (or, "
                                   "by <Material/Parametrization>, "
                                   "<Material/Young's modulus> and "
                                   "<Material/Poisson's ratio>) (density " +
                                   number(m.density) +
                                   " kg/m^3) follow mu = " + number(m.mu) +
                                   " Pa, lambda = " + number(m.lambda) +
                                   " Pa, vp = " + number(vp) +
                                   " m/s and vs = " + number(vs) +
                                   " m/s. Allowed: values whose moduli and "
                                   "wave speeds are finite and positive, the "
                                   "wave speeds below the speed of light (in "
                                   "SI units: e.g. 2700 kg/m^3, 6000 and "
                                   "3464 m/s)."));
          }
      }
      prm.leave_subsection();
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
          out << "   Material " << i << " (" << m.name
              << "): rho = " << m.density
              << " kg/m^3, vp = " << std::setprecision(6) << m.p_wave_speed()
              << " m/s, vs = " << m.s_wave_speed()
              << " m/s, E = " << m.youngs_modulus()
              << " Pa, nu = " << m.poissons_ratio() << "\n";
        }
      return out.str();
    }
  } // namespace Material
} // namespace rupture
