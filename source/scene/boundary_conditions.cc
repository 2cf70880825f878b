#include <rupture/base/utilities.h>
#include <rupture/scene/boundary_conditions.h>

#include <deal.II/base/utilities.h>

#include <set>

namespace rupture
{
  namespace Scene
  {
    template <int dim>
    void
    BoundaryConditions<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      {
        prm.declare_entry("Fixed",
                          "",
                          Patterns::Anything(),
                          "Comma separated names of boundaries whose "
                          "displacement is held at its initial value "
                          "(normally zero) in all components.");
        prm.declare_entry(
          "Roller",
          "",
          Patterns::Anything(),
          "Boundaries on which only some displacement components are held, "
          "as 'name: components' pairs separated by commas, with the "
          "components as letters x, y, z, e.g. 'west: x, bottom: z, "
          "south: y'. The other components are free.");
        prm.declare_entry(
          "Prescribed velocity",
          "",
          Patterns::Anything(),
          "Boundaries moved at a prescribed velocity in all components "
          "(m/s), as 'name: vx; vy[; vz]' pairs separated by commas, e.g. "
          "'east: -2.508e-9; 0; 0' for plate motion. Each component may be "
          "a function of x, y (, z) and t, e.g. 'top: (t < 10) ? 0.1 : "
          "-0.1; 0' (use no commas inside an expression); the displacement "
          "increment of a step is the velocity at mid-step times dt.");
        prm.declare_entry(
          "Traction",
          "",
          Patterns::Anything(),
          "Boundaries loaded by a constant traction vector (Pa), as "
          "'name: tx; ty[; tz]' pairs separated by commas.");
        prm.declare_entry(
          "Absorbing",
          "",
          Patterns::Anything(),
          "Comma separated names of boundaries with Lysmer-Kuhlemeyer "
          "dashpots (normal impedance rho*vp, tangential rho*vs; in "
          "anisotropic rock the matrix sqrt(rho Gamma(n)) of the boundary's "
          "normal n, Gamma the Christoffel matrix) that let outgoing waves "
          "leave a truncated domain. Dynamic schemes only.");
      }
      prm.leave_subsection();
    }



    namespace
    {
      types::boundary_id
      lookup(const std::string                               &name,
             const std::string                               &entry,
             const std::map<std::string, types::boundary_id> &names)
      {
        const auto it = names.find(name);
        if (it == names.end())
          {
            std::vector<std::string> allowed;
            for (const auto &n : names)
              allowed.push_back(n.first);
            AssertThrow(false,
                        ExcMessage("<Boundary conditions/" + entry +
                                   "> names the boundary <" + name +
                                   ">, which this scene does not have. The "
                                   "scene's boundaries are: " +
                                   Utilities::join(allowed) + "."));
          }
        return it->second;
      }

      /**
       * Split "a: v, b: w" into (name, value) pairs.
       */
      std::vector<std::pair<std::string, std::string>>
      split_pairs(const std::string &text, const std::string &entry)
      {
        std::vector<std::pair<std::string, std::string>> result;
        for (const auto &item : Utilities::split_list(text))
          {
            const auto colon = item.find(':');
            AssertThrow(colon != std::string::npos,
                        ExcMessage("<Boundary conditions/" + entry +
                                   "> expects 'name: value' pairs, but <" +
                                   item + "> has no ':'."));
            result.emplace_back(dealii::Utilities::trim(item.substr(0, colon)),
                                dealii::Utilities::trim(
                                  item.substr(colon + 1)));
          }
        return result;
      }
    } // namespace



    template <int dim>
    void
    BoundaryConditions<dim>::parse_parameters(
      ParameterHandler                                &prm,
      const std::map<std::string, types::boundary_id> &names)
    {
      kinematic.clear();
      tractions.clear();
      absorbing.clear();
      std::map<types::boundary_id, std::string> used;
      const auto claim = [&](const std::string &name,
                             const std::string &entry) {
        const types::boundary_id id = lookup(name, entry, names);
        AssertThrow(used.count(id) == 0,
                    ExcMessage("The boundary <" + name +
                               "> appears in <Boundary conditions/" + entry +
                               "> and in <Boundary conditions/" + used[id] +
                               ">, but a boundary can have one condition "
                               "only."));
        used[id] = entry;
        return id;
      };

      prm.enter_subsection("Boundary conditions");
      {
        for (const auto &name : Utilities::split_list(prm.get("Fixed")))
          {
            Kinematic k;
            k.name = name;
            k.id   = claim(name, "Fixed");
            k.components.fill(true);
            kinematic.push_back(k);
          }

        for (const auto &[name, comps] :
             split_pairs(prm.get("Roller"), "Roller"))
          {
            Kinematic k;
            k.name = name;
            k.id   = claim(name, "Roller");
            k.components.fill(false);
            const std::string letters = (dim == 2 ? "xy" : "xyz");
            AssertThrow(!comps.empty(),
                        ExcMessage("<Boundary conditions/Roller> gives no "
                                   "components for <" +
                                   name + ">; allowed are the letters " +
                                   letters + "."));
            for (const char c : comps)
              {
                if (c == ' ')
                  continue;
                const auto d = letters.find(c);
                AssertThrow(d != std::string::npos,
                            ExcMessage("<Boundary conditions/Roller> gives "
                                       "the component <" +
                                       std::string(1, c) + "> for <" + name +
                                       ">; allowed are the letters " + letters +
                                       "."));
                k.components[d] = true;
              }
            kinematic.push_back(k);
          }

        for (const auto &[name, value] :
             split_pairs(prm.get("Prescribed velocity"), "Prescribed velocity"))
          {
            Kinematic k;
            k.name = name;
            k.id   = claim(name, "Prescribed velocity");
            k.components.fill(true);
            k.velocity = Utilities::parse_function<dim>(
              value, dim, "Boundary conditions/Prescribed velocity");
            kinematic.push_back(k);
          }

        for (const auto &[name, value] :
             split_pairs(prm.get("Traction"), "Traction"))
          {
            const types::boundary_id id   = claim(name, "Traction");
            std::string              list = value;
            std::replace(list.begin(), list.end(), ';', ',');
            tractions.emplace_back(id,
                                   Utilities::parse_vector<dim>(
                                     list, "Boundary conditions/Traction"));
          }

        for (const auto &name : Utilities::split_list(prm.get("Absorbing")))
          absorbing.push_back(claim(name, "Absorbing"));
      }
      prm.leave_subsection();
    }



    template class BoundaryConditions<2>;
    template class BoundaryConditions<3>;
  } // namespace Scene
} // namespace rupture
