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
                  // The parser's reason, without the general advice.
                  std::string reason = Utilities::message_of(error);
                  const auto  from   = reason.find("> (");
                  const auto  to     = reason.find(").", from);
                  if (from != std::string::npos && to != std::string::npos)
                    reason = reason.substr(from + 3, to - from - 3);
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



    std::map<std::string, double>
    TensorFields::constants(const Field &field, const Point<3> &x) const
    {
      std::map<std::string, double> c;
      for (unsigned int k = 0; k < field.keys.size(); ++k)
        c[field.keys[k]] =
          field.functions[k] ? field.functions[k]->value(x) : field.numbers[k];
      return c;
    }



    template <int dim_>
    VoigtMatrix
    TensorFields::value(const unsigned int i, const Point<dim_> &p) const
    {
      Assert(varies(i), ExcInternalError());
      const Field &f = fields[i];
      return rotate(voigt_matrix(f.symmetry, constants(f, padded(p))), f.axes);
    }



    template <int dim_>
    std::string
    TensorFields::checked_value(const unsigned int i,
                                const Point<dim_> &p,
                                VoigtMatrix       &c) const
    {
      const Field       &f = fields[i];
      std::ostringstream where;
      where << f.which << " at (" << p << ")";
      std::map<std::string, double> values;
      try
        {
          values = constants(f, padded(p));
        }
      catch (const ExceptionBase &error)
        {
          return "<Material/Stiffness>" + where.str() +
                 ": a function cannot be evaluated there (" +
                 Utilities::message_of(error) + ").";
        }
      for (const auto &[key, value] : values)
        if (!valid_constant(value))
          {
            std::ostringstream message;
            message << "<Material/Stiffness>" << where.str() << ": " << key
                    << " is ";
            if (std::isnan(value))
              message << "not a number (NaN)";
            else
              message << value;
            message << ". Allowed: finite values of at most 1e20 in "
                       "magnitude (Pa).";
            return message.str();
          }
      try
        {
          c = checked_stiffness(f.symmetry, values, f.axes, where.str());
        }
      catch (const ExceptionBase &error)
        {
          return Utilities::message_of(error);
        }
      if (dim == 2 && !model_plane_is_mirror_plane(c))
        return "Material" +
               where.str().substr(std::string(" of material").size()) +
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



    double
    TensorFields::ratio(const unsigned int i, const VoigtMatrix &c) const
    {
      Assert(varies(i), ExcInternalError());
      return fields[i].energy_ratio(c);
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
