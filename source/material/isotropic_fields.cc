#include <rupture/base/utilities.h>
#include <rupture/material/isotropic_fields.h>
#include <rupture/material/spatial_factors.h>

#include <cmath>
#include <cstdlib>
#include <limits>

namespace rupture
{
  namespace Material
  {
    void
    IsotropicFields::parse(ParameterHandler               &prm,
                           const std::vector<std::string> &names,
                           const bool                      by_speeds)
    {
      entry_names          = {"Density",
                     by_speeds ? "P-wave speed" : "Young's modulus",
                     by_speeds ? "S-wave speed" : "Poisson's ratio"};
      const unsigned int n = names.size();
      for (unsigned int e = 0; e < 3; ++e)
        {
          const std::string        entry = "<Material/" + entry_names[e] + ">";
          const std::string        text  = prm.get(entry_names[e]);
          std::vector<std::string> list;
          if (text.find(';') != std::string::npos)
            list = Utilities::split_fields(text);
          else
            {
              // A comma separated list of numbers (empty items left out,
              // as ever), or one function (whose commas are inside
              // parentheses: if(y < 0, 1, 2)).
              const std::vector<std::string> items =
                Utilities::split_top_level(text);
              if (items.size() == 1)
                list = items;
              else
                for (const std::string &item : items)
                  {
                    double x;
                    AssertThrow(item.empty() || read_number(item, x),
                                ExcMessage(
                                  "The entry " + entry + " has the item '" +
                                  item +
                                  "' in a list separated by ',', which "
                                  "holds numbers only. Allowed: numbers "
                                  "separated by ',', or numbers and "
                                  "functions of x, y, z separated by ';' "
                                  "(one per material)."));
                    if (!item.empty())
                      list.push_back(item);
                  }
            }
          AssertThrow(list.size() == 1 || list.size() == n,
                      ExcMessage("The entry " + entry + " has " +
                                 std::to_string(list.size()) +
                                 " values, but <Material/Names> lists " +
                                 std::to_string(n) +
                                 " materials. Give one value per material "
                                 "(numbers separated by ',', or numbers and "
                                 "functions of x, y, z separated by ';'), or "
                                 "a single one for all of them."));
          if (list.size() == 1)
            list.assign(n, list[0]);
          fields[e] = list;
          number_values[e].assign(n, std::numeric_limits<double>::quiet_NaN());
          functions[e].clear();
          functions[e].resize(n);
          for (unsigned int i = 0; i < n; ++i)
            {
              AssertThrow(!list[i].empty(),
                          ExcMessage("The entry " + entry +
                                     " has no value for material " +
                                     std::to_string(i) + " (" + names[i] +
                                     "). Give a number or a function of x, "
                                     "y, z."));
              const std::string which = "The entry " + entry + " of material " +
                                        std::to_string(i) + " (" + names[i] +
                                        ") is '" + list[i] + "'";
              if (read_number(list[i], number_values[e][i]))
                {
                  AssertThrow(std::isfinite(number_values[e][i]),
                              ExcMessage(which +
                                         ", which is not a finite number. "
                                         "Allowed: finite numbers, or "
                                         "functions of x, y, z."));
                  continue;
                }
              AssertThrow(Utilities::split_top_level(list[i]).size() == 1,
                          ExcMessage(which +
                                     ": a field holds one number or one "
                                     "function; fields are separated by "
                                     "';'. Allowed: numbers separated by "
                                     "',', or numbers and functions of x, y, "
                                     "z separated by ';'."));
              try
                {
                  functions[e][i] = Utilities::parse_function<3>(
                    list[i], 1, "Material/" + entry_names[e], "x,y,z");
                }
              catch (const ExceptionBase &error)
                {
                  const std::string reason = Utilities::parser_reason(error);
                  AssertThrow(false,
                              ExcMessage(
                                "The entry " + entry + " of material " +
                                std::to_string(i) + " (" + names[i] + ") is '" +
                                list[i] +
                                "', neither a number nor a function of x, "
                                "y, z (" +
                                reason +
                                "). Allowed: numbers separated by ',', or "
                                "numbers and functions of x, y, z separated "
                                "by ';'."));
                }
            }
        }
    }



    bool
    IsotropicFields::varies(const unsigned int i) const
    {
      for (const auto &f : functions)
        if (i < f.size() && f[i])
          return true;
      return false;
    }



    bool
    IsotropicFields::varies() const
    {
      for (unsigned int i = 0; i < functions[0].size(); ++i)
        if (varies(i))
          return true;
      return false;
    }



    std::array<double, 3>
    IsotropicFields::numbers(const unsigned int i) const
    {
      return {number_values[0][i], number_values[1][i], number_values[2][i]};
    }



    template <int dim>
    std::array<double, 3>
    IsotropicFields::values(const unsigned int i, const Point<dim> &p) const
    {
      const Point<3>        x = padded(p);
      std::array<double, 3> v;
      for (unsigned int e = 0; e < 3; ++e)
        v[e] =
          functions[e][i] ? functions[e][i]->value(x) : number_values[e][i];
      return v;
    }



    template std::array<double, 3>
    IsotropicFields::values<2>(const unsigned int, const Point<2> &) const;
    template std::array<double, 3>
    IsotropicFields::values<3>(const unsigned int, const Point<3> &) const;
  } // namespace Material
} // namespace rupture
