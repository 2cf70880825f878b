#include <rupture/base/utilities.h>
#include <rupture/material/anisotropic_input.h>
#include <rupture/material/spatial_factors.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

namespace rupture
{
  namespace Material
  {
    namespace
    {
      std::string
      number(const double x)
      {
        std::ostringstream out;
        out << x;
        return out.str();
      }



      /// Fields separated by ';', empty ones kept; none for a blank text.
      std::vector<std::string>
      fields_or_none(const std::string &text)
      {
        if (dealii::Utilities::trim(text).empty())
          return {};
        return Utilities::split_fields(text);
      }



      /// One field per material: n given, one for all, or none (empty).
      std::vector<std::string>
      per_material(const std::string &entry,
                   const std::string &text,
                   const unsigned int n)
      {
        std::vector<std::string> fields = fields_or_none(text);
        AssertThrow(fields.size() <= 1 || fields.size() == n,
                    ExcMessage("The entry <Material/" + entry + "> has " +
                               std::to_string(fields.size()) +
                               " fields separated by ';', but <Material/"
                               "Names> lists " +
                               std::to_string(n) +
                               " materials. Give one field per material (an "
                               "empty one for an isotropic material), or a "
                               "single field for all of them."));
        if (fields.size() <= 1)
          return std::vector<std::string>(n, fields.empty() ? "" : fields[0]);
        return fields;
      }



      std::string
      allowed_list(const Symmetry symmetry)
      {
        return Utilities::join(constant_names(symmetry));
      }



      /// The named constants' texts of one material's <Stiffness> field.
      std::map<std::string, std::string>
      parse_texts(const std::string &field,
                  const Symmetry     symmetry,
                  const std::string &which)
      {
        const std::string entry = "<Material/Stiffness>" + which;
        const std::string name  = symmetry_names()[static_cast<int>(symmetry)];
        const std::vector<std::string>     needed = constant_names(symmetry);
        std::map<std::string, std::string> constants;
        for (const std::string &item : Utilities::split_top_level(field))
          {
            if (item.empty())
              continue;
            const std::size_t equal = item.find('=');
            AssertThrow(equal != std::string::npos,
                        ExcMessage(entry + " has the item '" + item +
                                   "', but each item must read 'Cij = "
                                   "value' (Pa; a number or a function of "
                                   "x, y, z). A " +
                                   name + " material takes " +
                                   allowed_list(symmetry) + "."));
            std::string key = dealii::Utilities::trim(item.substr(0, equal));
            std::transform(key.begin(), key.end(), key.begin(), ::toupper);
            AssertThrow(
              std::find(needed.begin(), needed.end(), key) != needed.end(),
              ExcMessage(entry + " gives '" +
                         dealii::Utilities::trim(item.substr(0, equal)) +
                         "', which a " + name +
                         " material does not take. Allowed: " +
                         allowed_list(symmetry) + "."));
            AssertThrow(constants.count(key) == 0,
                        ExcMessage(entry + " gives " + key + " twice."));
            const std::string text =
              dealii::Utilities::trim(item.substr(equal + 1));
            AssertThrow(!text.empty(),
                        ExcMessage(entry + " gives " + key +
                                   " no value. Allowed: a number (Pa) or a "
                                   "function of x, y, z."));
            constants[key] = text;
          }
        std::vector<std::string> missing;
        for (const std::string &key : needed)
          if (constants.count(key) == 0)
            missing.push_back(key);
        AssertThrow(missing.empty(),
                    ExcMessage(entry + " lacks " + Utilities::join(missing) +
                               ": a " + name + " material takes " +
                               allowed_list(symmetry) + "."));
        return constants;
      }



      Tensor<1, 3>
      unit_vector(const std::vector<double> &x,
                  const unsigned int         first,
                  const std::string         &what,
                  const std::string         &entry)
      {
        Tensor<1, 3> v;
        for (unsigned int d = 0; d < 3; ++d)
          v[d] = x[first + d];
        const double length = v.norm();
        AssertThrow(std::isfinite(length) && length > 0,
                    ExcMessage(entry + ": " + what +
                               " must be a non-zero vector of finite "
                               "components."));
        return v / length;
      }



      /// The material's axes as the columns of a rotation.
      Tensor<2, 3>
      parse_axes(const std::string &field,
                 const Symmetry     symmetry,
                 const std::string &which)
      {
        const std::string   entry = "<Material/Material axes>" + which;
        std::vector<double> x =
          Utilities::parse_doubles(field, "Material/Material axes");
        Tensor<1, 3> a[3];
        if (x.empty())
          return unit_symmetric_tensor<3>();
        if (x.size() == 3)
          {
            AssertThrow(symmetry == Symmetry::transversely_isotropic,
                        ExcMessage(
                          entry +
                          " has three numbers, which name a symmetry axis "
                          "and are allowed only for a transversely "
                          "isotropic material. Give six: the material's "
                          "1-axis, then its 2-axis."));
            a[2] = unit_vector(x, 0, "the symmetry axis", entry);
            // Any axis normal to it: the material is symmetric about a[2].
            const unsigned int smallest =
              std::min_element(x.begin(),
                               x.end(),
                               [](double p, double q) {
                                 return std::abs(p) < std::abs(q);
                               }) -
              x.begin();
            Tensor<1, 3> e;
            e[smallest] = 1;
            a[0]        = cross_product_3d(e, a[2]);
            a[0] /= a[0].norm();
          }
        else
          {
            AssertThrow(x.size() == 6,
                        ExcMessage(entry + " has " + std::to_string(x.size()) +
                                   " numbers. Allowed: none (the model's "
                                   "axes), three (the symmetry axis of a "
                                   "transversely isotropic material) or six "
                                   "(the material's 1-axis, then its "
                                   "2-axis)."));
            a[0] = unit_vector(x, 0, "the 1-axis", entry);
            a[2] = unit_vector(x, 3, "the 2-axis", entry);
            AssertThrow(std::abs(a[0] * a[2]) < 1e-6,
                        ExcMessage(entry +
                                   ": the 1-axis and the 2-axis must be "
                                   "orthogonal, but the cosine of their "
                                   "angle is " +
                                   number(a[0] * a[2]) + "."));
            // (a[2] held the 2-axis; make it exact, then the 3-axis.)
            const Tensor<1, 3> second = (a[2] - (a[2] * a[0]) * a[0]) /
                                        (a[2] - (a[2] * a[0]) * a[0]).norm();
            a[2] = cross_product_3d(a[0], second);
          }
        a[1] = cross_product_3d(a[2], a[0]);
        Tensor<2, 3> axes;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int p = 0; p < 3; ++p)
            axes[i][p] = a[p][i];
        return axes;
      }
    } // namespace



    AnisotropicEntries
    read_anisotropic_entries(ParameterHandler               &prm,
                             const std::vector<std::string> &names)
    {
      const unsigned int       n = names.size();
      AnisotropicEntries       entries;
      std::vector<std::string> classes =
        Utilities::split_list(prm.get("Symmetry"));
      AssertThrow(classes.size() == 1 || classes.size() == n,
                  ExcMessage("The entry <Material/Symmetry> has " +
                             std::to_string(classes.size()) +
                             " values, but <Material/Names> lists " +
                             std::to_string(n) +
                             " materials. Give one class per material, or a "
                             "single one for all of them."));
      if (classes.size() == 1)
        classes = std::vector<std::string>(n, classes[0]);
      const auto &known = symmetry_names();
      for (unsigned int i = 0; i < n; ++i)
        {
          const auto it = std::find(known.begin(), known.end(), classes[i]);
          AssertThrow(it != known.end(),
                      ExcMessage(
                        "<Material/Symmetry> of material " + std::to_string(i) +
                        " (" + names[i] + ") is '" + classes[i] +
                        "'. Allowed: " + Utilities::join(known) + "."));
          entries.symmetry.push_back(static_cast<Symmetry>(it - known.begin()));
        }
      entries.stiffness = per_material("Stiffness", prm.get("Stiffness"), n);
      entries.axes = per_material("Material axes", prm.get("Material axes"), n);
      // A field meant for an isotropic material is a mistake (typically
      // constants given without <Symmetry>), unless one field was given
      // for several materials of which some are anisotropic.
      const bool any_anisotropic =
        std::any_of(entries.symmetry.begin(),
                    entries.symmetry.end(),
                    [](const Symmetry s) { return s != Symmetry::isotropic; });
      for (const char *entry : {"Stiffness", "Material axes"})
        {
          const bool shared =
            (n > 1 && fields_or_none(prm.get(entry)).size() == 1);
          const std::vector<std::string> &fields =
            (std::string(entry) == "Stiffness" ? entries.stiffness :
                                                 entries.axes);
          for (unsigned int i = 0; i < n; ++i)
            AssertThrow(entries.symmetry[i] != Symmetry::isotropic ||
                          fields[i].empty() || (shared && any_anisotropic),
                        ExcMessage(std::string("<Material/") + entry +
                                   "> gives a field for material " +
                                   std::to_string(i) + " (" + names[i] +
                                   "), which <Material/Symmetry> makes "
                                   "isotropic. Set its <Material/Symmetry> "
                                   "to the class the constants describe "
                                   "(transversely isotropic, orthotropic or "
                                   "general), or leave the field empty."));
        }
      return entries;
    }



    std::map<std::string, std::string>
    stiffness_texts(const AnisotropicEntries &entries,
                    const unsigned int        index,
                    const std::string        &which)
    {
      return parse_texts(entries.stiffness[index],
                         entries.symmetry[index],
                         which);
    }



    Tensor<2, 3>
    material_axes(const AnisotropicEntries &entries,
                  const unsigned int        index,
                  const std::string        &which)
    {
      return parse_axes(entries.axes[index], entries.symmetry[index], which);
    }



    bool
    positive_definite_enough(const VoigtMatrix &c, const double fraction)
    {
      // The largest eigenvalue is at most the trace: K - fraction trace I
      // positive definite is enough (checked without eigenvalues).
      VoigtMatrix k{}, l{};
      double      trace = 0;
      for (unsigned int I = 0; I < 6; ++I)
        for (unsigned int J = 0; J < 6; ++J)
          k[I][J] = c[I][J] * (I < 3 ? 1. : std::sqrt(2.)) *
                    (J < 3 ? 1. : std::sqrt(2.));
      for (unsigned int I = 0; I < 6; ++I)
        trace += k[I][I];
      bool factorized = std::isfinite(trace) && trace > 0;
      for (unsigned int I = 0; I < 6 && factorized; ++I)
        for (unsigned int J = 0; J <= I && factorized; ++J)
          {
            double sum = k[I][J] - (I == J ? fraction * trace : 0.);
            for (unsigned int m = 0; m < J; ++m)
              sum -= l[I][m] * l[J][m];
            if (I == J)
              {
                factorized = sum > 0;
                l[I][I]    = factorized ? std::sqrt(sum) : 0.;
              }
            else
              l[I][J] = sum / l[J][J];
          }
      if (factorized)
        return true;
      const std::array<double, 6> e = kelvin_eigenvalues(c);
      return e[0] > fraction * e[5];
    }



    bool
    valid_constant(const double value)
    {
      return std::isfinite(value) && std::abs(value) < 1e20;
    }



    VoigtMatrix
    checked_stiffness(const Symmetry                       symmetry,
                      const std::map<std::string, double> &constants,
                      const Tensor<2, 3>                  &axes,
                      const std::string                   &which)
    {
      const VoigtMatrix own = voigt_matrix(symmetry, constants);
      if (positive_definite_enough(own, 1e-8))
        return rotate(own, axes);
      const std::array<double, 6> e = kelvin_eigenvalues(own);
      AssertThrow(false,
                  ExcMessage(
                    "The stiffness given by <Material/Stiffness>" + which +
                    " is not positive definite" +
                    (e[0] > 0 ? std::string(" enough") : std::string()) +
                    ": the eigenvalues of its Kelvin matrix (the energy of "
                    "unit strain modes) range from " +
                    number(e[0]) + " to " + number(e[5]) +
                    " Pa; allowed: all positive and the smallest at least "
                    "1e-8 of the largest, so that every strain stores "
                    "energy and wave speeds stay finite. (Transversely "
                    "isotropic: C11 > |C11 - 2 C66|, C33 (2 C11 - 2 C66) > "
                    "2 C13^2, C44 > 0, C66 > 0.)"));
      return rotate(own, axes);
    }



    VoigtMatrix
    anisotropic_stiffness(const AnisotropicEntries &entries,
                          const unsigned int        index,
                          const std::string        &which)
    {
      std::map<std::string, double> constants;
      for (const auto &[key, text] : stiffness_texts(entries, index, which))
        {
          double value = 0;
          AssertThrow(read_number(text, value) && valid_constant(value),
                      ExcMessage(
                        "<Material/Stiffness>" + which + ": " + key +
                        " must be one finite number of at most 1e20 in "
                        "magnitude (Pa) here, but it is '" +
                        text +
                        "'. (Constants that vary in space, functions of x, "
                        "y, z, are taken by the finite-element method, not by "
                        "the boundary-integral one.)"));
          constants[key] = value;
        }
      return checked_stiffness(entries.symmetry[index],
                               constants,
                               material_axes(entries, index, which),
                               which);
    }
  } // namespace Material
} // namespace rupture
