#include <rupture/base/utilities.h>
#include <rupture/material/anisotropic_input.h>
#include <rupture/material/spatial_factors.h>
#include <rupture/material/tensor_fields.h>

#include <cmath>
#include <sstream>

namespace rupture
{
  namespace Material
  {
    void
    TensorFields::parse(const AnisotropicEntries       &entries,
                        const std::vector<std::string> &names,
                        const unsigned int              dimension)
    {
      dim = dimension;
      fields.clear();
      fields.resize(names.size());
      for (unsigned int i = 0; i < names.size(); ++i)
        {
          if (entries.symmetry[i] == Symmetry::isotropic)
            continue;
          const std::string which =
            " of material " + std::to_string(i) + " (" + names[i] + ")";
          Field field;
          field.symmetry = entries.symmetry[i];
          field.text     = entries.stiffness[i];
          field.which    = which;
          bool any       = false;
          for (const auto &[key, text] : stiffness_texts(entries, i, which))
            {
              field.keys.push_back(key);
              double value = 0;
              if (read_number(text, value))
                {
                  field.numbers.push_back(value);
                  field.functions.emplace_back();
                  continue;
                }
              any = true;
              field.numbers.push_back(0);
              try
                {
                  field.functions.emplace_back(Utilities::parse_function<3>(
                    text, 1, "Material/Stiffness", "x,y,z"));
                }
              catch (const ExceptionBase &error)
                {
                  const std::string reason = Utilities::parser_reason(error);
                  AssertThrow(false,
                              ExcMessage("<Material/Stiffness>" + which + ": " +
                                         key + " = '" + text +
                                         "' is neither a number nor a "
                                         "function of x, y, z (" +
                                         reason +
                                         "). Allowed: a number (Pa) or a "
                                         "function of x, y, z."));
                }
            }
          if (!any)
            continue; // (anisotropic_stiffness() reads it.)
          field.axes = material_axes(entries, i, which);
          for (const std::string &key : field.keys)
            {
              std::map<std::string, double> unit;
              for (const std::string &other : field.keys)
                unit[other] = (other == key ? 1. : 0.);
              field.basis.push_back(
                rotate(voigt_matrix(field.symmetry, unit), field.axes));
            }
          // The reference: the tensor at the origin, where allowed.
          VoigtMatrix at_origin{};
          fields[i]                 = std::move(field);
          const std::string invalid = checked_value(i, Point<3>(), at_origin);
          Field            &f       = fields[i];
          if (invalid.empty())
            f.reference = at_origin;
          else
            for (unsigned int I = 0; I < 6; ++I)
              f.reference[I][I] = (I < 3 ? 1e10 : 0.5e10);
          f.energy_ratio = EnergyRatio(f.reference, dim);
        }
    }



    bool
    TensorFields::varies(const unsigned int i) const
    {
      return i < fields.size() && !fields[i].keys.empty();
    }



    bool
    TensorFields::varies() const
    {
      for (unsigned int i = 0; i < fields.size(); ++i)
        if (varies(i))
          return true;
      return false;
    }



    template <int dim_>
    VoigtMatrix
    TensorFields::value(const unsigned int i, const Point<dim_> &p) const
    {
      Assert(varies(i), ExcInternalError());
      const Field   &f = fields[i];
      const Point<3> x = padded(p);
      VoigtMatrix    c{};
      for (unsigned int k = 0; k < f.keys.size(); ++k)
        {
          const double value =
            f.functions[k] ? f.functions[k]->value(x) : f.numbers[k];
          for (unsigned int I = 0; I < 6; ++I)
            for (unsigned int J = 0; J < 6; ++J)
              c[I][J] += value * f.basis[k][I][J];
        }
      return c;
    }



    template <int dim_>
    std::string
    TensorFields::checked_value(const unsigned int i,
                                const Point<dim_> &p,
                                VoigtMatrix       &c) const
    {
      const Field &f     = fields[i];
      const auto   where = [&]() {
        std::ostringstream text;
        text << f.which << " at (" << p << ")";
        return text.str();
      };
      // (Messages are written for a failing point only.)
      const Point<3>      x = padded(p);
      std::vector<double> values(f.keys.size());
      try
        {
          for (unsigned int k = 0; k < f.keys.size(); ++k)
            values[k] =
              f.functions[k] ? f.functions[k]->value(x) : f.numbers[k];
        }
      catch (const ExceptionBase &error)
        {
          return "<Material/Stiffness>" + where() +
                 ": a function cannot be evaluated there (" +
                 Utilities::message_of(error) + ").";
        }
      c = VoigtMatrix{};
      for (unsigned int k = 0; k < f.keys.size(); ++k)
        {
          if (!valid_constant(values[k]))
            {
              std::ostringstream message;
              message << "<Material/Stiffness>" << where() << ": " << f.keys[k]
                      << " is ";
              if (std::isnan(values[k]))
                message << "not a number (NaN)";
              else
                message << values[k];
              message << ". Allowed: finite values of at most 1e20 in "
                         "magnitude (Pa).";
              return message.str();
            }
          for (unsigned int I = 0; I < 6; ++I)
            for (unsigned int J = 0; J < 6; ++J)
              c[I][J] += values[k] * f.basis[k][I][J];
        }
      // (A rotation keeps the Kelvin eigenvalues: the model's frame will
      // do; the message is that of numbers.)
      if (!positive_definite_enough(c, 1e-8))
        {
          std::map<std::string, double> named;
          for (unsigned int k = 0; k < f.keys.size(); ++k)
            named[f.keys[k]] = values[k];
          try
            {
              c = checked_stiffness(f.symmetry, named, f.axes, where());
            }
          catch (const ExceptionBase &error)
            {
              return Utilities::message_of(error);
            }
        }
      if (dim == 2 && !model_plane_is_mirror_plane(c))
        return "Material" + where().substr(std::string(" of material").size()) +
               " is anisotropic, and in the model's frame its tensor "
               "couples in-plane strains to out-of-plane shear stresses "
               "(C14, C15, C24, C25, C46 or C56 is not zero there): the "
               "plane of x and y is not a mirror plane, so in-plane and "
               "out-of-plane motions couple, which the 2-D plane-strain "
               "model cannot represent. Allowed: <Material/Stiffness> "
               "functions that keep those constants zero, or a 3-D run "
               "(<Dimension> = 3).";
      return "";
    }



    const VoigtMatrix &
    TensorFields::reference(const unsigned int i) const
    {
      Assert(varies(i), ExcInternalError());
      return fields[i].reference;
    }



    const EnergyRatio &
    TensorFields::energy_ratio(const unsigned int i) const
    {
      Assert(varies(i), ExcInternalError());
      return fields[i].energy_ratio;
    }



    const std::string &
    TensorFields::text(const unsigned int i) const
    {
      return fields[i].text;
    }



    template VoigtMatrix
    TensorFields::value<2>(const unsigned int, const Point<2> &) const;
    template VoigtMatrix
    TensorFields::value<3>(const unsigned int, const Point<3> &) const;
    template std::string
    TensorFields::checked_value<2>(const unsigned int,
                                   const Point<2> &,
                                   VoigtMatrix &) const;
    template std::string
    TensorFields::checked_value<3>(const unsigned int,
                                   const Point<3> &,
                                   VoigtMatrix &) const;
  } // namespace Material
} // namespace rupture
