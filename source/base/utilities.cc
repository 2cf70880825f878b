#include <rupture/base/utilities.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

namespace rupture
{
  namespace Utilities
  {
    template <int dim>
    std::unique_ptr<FunctionParser<dim>>
    parse_function(const std::string &expression,
                   const unsigned int n_components,
                   const std::string &entry_name,
                   const std::string &variable_names)
    {
      auto function = std::make_unique<FunctionParser<dim>>(n_components);
      std::vector<std::string> parts;
      if (dealii::Utilities::trim(expression).empty())
        parts.assign(n_components, "0");
      else
        parts = dealii::Utilities::split_string_list(expression, ';');

      AssertThrow(parts.size() == n_components,
                  ExcMessage("The entry <" + entry_name + "> has " +
                             std::to_string(parts.size()) +
                             " components separated by ';', but " +
                             std::to_string(n_components) +
                             " are needed in this dimension. Given: <" +
                             expression + ">."));

      const std::string variables =
        !variable_names.empty() ?
          variable_names :
          (dim == 1 ? "x,t" : (dim == 2 ? "x,y,t" : "x,y,z,t"));
      const std::map<std::string, double> constants = {{"pi", numbers::PI}};
      // The parser reports its errors on std::cerr; keep them for the
      // message instead.
      std::ostringstream parser_errors;
      std::streambuf    *old_cerr = std::cerr.rdbuf(parser_errors.rdbuf());
      bool               ok       = true;
      try
        {
          function->initialize(variables,
                               parts,
                               constants,
                               variables.find(",t") != std::string::npos);
          // Evaluate once so that errors such as unknown variables surface
          // here rather than in the middle of a run.
          Vector<double> value(n_components);
          function->vector_value(Point<dim>(), value);
        }
      catch (...)
        {
          ok = false;
        }
      std::cerr.rdbuf(old_cerr);
      if (!ok)
        {
          std::string reason = parser_errors.str();
          const auto  begin  = reason.find('<');
          const auto  end    = reason.find('>');
          reason = (begin != std::string::npos && end != std::string::npos) ?
                     " (" + reason.substr(begin + 1, end - begin - 1) + ")" :
                     "";
          AssertThrow(false,
                      ExcMessage("The entry <" + entry_name +
                                 "> could not be parsed as a function: <" +
                                 expression + ">" + reason +
                                 ". Allowed are expressions in the variables " +
                                 variables +
                                 " and the constant pi, one per component, "
                                 "separated by ';'."));
        }
      return function;
    }



    template <int dim>
    Tensor<1, dim>
    parse_vector(const std::string &text,
                 const std::string &entry_name,
                 const bool         allow_single_value)
    {
      std::vector<double> values = parse_doubles(text, entry_name);
      if (allow_single_value && values.size() == 1)
        values.assign(dim, values[0]);
      AssertThrow(values.size() == dim,
                  ExcMessage("The entry <" + entry_name + "> needs exactly " +
                             std::to_string(dim) +
                             " comma separated numbers in this dimension" +
                             (allow_single_value ? " (or a single one)" : "") +
                             ", but "
                             "was given <" +
                             text + ">."));
      Tensor<1, dim> result;
      for (unsigned int d = 0; d < dim; ++d)
        result[d] = values[d];
      return result;
    }



    std::vector<std::string>
    split_list(const std::string &text, const char separator)
    {
      std::vector<std::string> result;
      for (const auto &item :
           dealii::Utilities::split_string_list(text, separator))
        if (!dealii::Utilities::trim(item).empty())
          result.push_back(dealii::Utilities::trim(item));
      return result;
    }



    std::vector<std::string>
    split_fields(const std::string &text, const char separator)
    {
      std::vector<std::string> fields;
      std::size_t              start = 0;
      while (true)
        {
          const std::size_t end = text.find(separator, start);
          fields.push_back(dealii::Utilities::trim(
            text.substr(start, end == std::string::npos ? end : end - start)));
          if (end == std::string::npos)
            return fields;
          start = end + 1;
        }
    }



    std::vector<std::string>
    split_top_level(const std::string &text)
    {
      std::vector<std::string> items(1);
      int                      depth = 0;
      for (const char c : text)
        {
          depth += (c == '(') - (c == ')');
          if (c == ',' && depth == 0)
            items.emplace_back();
          else
            items.back() += c;
        }
      for (std::string &item : items)
        item = dealii::Utilities::trim(item);
      return items;
    }



    std::vector<double>
    parse_doubles(const std::string &text, const std::string &entry_name)
    {
      std::vector<double> values;
      for (const auto &item : split_list(text))
        {
          std::size_t pos   = 0;
          double      value = 0;
          try
            {
              value = std::stod(item, &pos);
            }
          catch (...)
            {
              pos = 0;
            }
          AssertThrow(pos == item.size() && pos > 0,
                      ExcMessage("The entry <" + entry_name +
                                 "> must be a comma separated list of "
                                 "numbers, but <" +
                                 item + "> is not a number."));
          AssertThrow(std::isfinite(value),
                      ExcMessage("The entry <" + entry_name +
                                 "> must be a comma separated list of finite "
                                 "numbers, but holds <" +
                                 item + ">."));
          values.push_back(value);
        }
      return values;
    }



    std::string
    join(const std::vector<std::string> &items)
    {
      std::string result;
      for (const auto &item : items)
        result += (result.empty() ? "" : ", ") + item;
      return result;
    }



    void
    write_file_atomically(const std::string &filename,
                          const std::string &contents)
    {
      const std::string tmp     = filename + ".tmp";
      bool              written = false;
      {
        std::ofstream out(tmp);
        if (out)
          {
            out << contents;
            out.close();
            written = static_cast<bool>(out);
          }
      }
      // No temporary file outlives a failed write.
      if (!written || std::rename(tmp.c_str(), filename.c_str()) != 0)
        {
          std::remove(tmp.c_str());
          AssertThrow(false,
                      ExcMessage("Cannot write the file <" + filename +
                                 "> (through <" + tmp +
                                 ">): is the disk full or the directory not "
                                 "writable?"));
        }
    }



    template std::unique_ptr<FunctionParser<1>>
    parse_function<1>(const std::string &,
                      const unsigned int,
                      const std::string &,
                      const std::string &);
    template std::unique_ptr<FunctionParser<2>>
    parse_function<2>(const std::string &,
                      const unsigned int,
                      const std::string &,
                      const std::string &);
    template std::unique_ptr<FunctionParser<3>>
    parse_function<3>(const std::string &,
                      const unsigned int,
                      const std::string &,
                      const std::string &);
    template <int dim>
    std::vector<std::pair<std::string, Point<dim>>>
    parse_named_points(const std::string &text, const std::string &entry_name)
    {
      std::vector<std::pair<std::string, Point<dim>>> points;
      for (const auto &entry : split_list(text, ';'))
        {
          const auto colon = entry.find(':');
          AssertThrow(colon != std::string::npos,
                      ExcMessage("<" + entry_name +
                                 "> expects 'name: x, y[, z]' entries "
                                 "separated by ';', but <" +
                                 entry + "> has no ':'."));
          const std::string name =
            dealii::Utilities::trim(entry.substr(0, colon));
          AssertThrow(!name.empty() &&
                        name.find_first_of("/ \t") == std::string::npos,
                      ExcMessage("The name <" + name + "> in <" + entry_name +
                                 "> must be non-empty and have no '/' or "
                                 "spaces."));
          for (const auto &other : points)
            AssertThrow(other.first != name,
                        ExcMessage("The name <" + name +
                                   "> appears twice in <" + entry_name + ">."));
          points.emplace_back(
            name,
            Point<dim>(parse_vector<dim>(entry.substr(colon + 1),
                                         entry_name + " (" + name + ")")));
        }
      return points;
    }



    template std::vector<std::pair<std::string, Point<2>>>
    parse_named_points<2>(const std::string &, const std::string &);
    template std::vector<std::pair<std::string, Point<3>>>
    parse_named_points<3>(const std::string &, const std::string &);
    template Tensor<1, 2>
    parse_vector<2>(const std::string &, const std::string &, const bool);
    template Tensor<1, 3>
    parse_vector<3>(const std::string &, const std::string &, const bool);


    std::string
    message_of(const ExceptionBase &e)
    {
      std::ostringstream s;
      e.print_info(s);
      // Collapse the indentation deal.II puts in front of lines.
      std::string result;
      for (const auto &line :
           dealii::Utilities::split_string_list(s.str(), '\n'))
        if (!dealii::Utilities::trim(line).empty())
          result += (result.empty() ? "" : " ") + dealii::Utilities::trim(line);
      return result;
    }



    std::string
    parser_reason(const ExceptionBase &e)
    {
      std::string reason = message_of(e);
      const auto  from   = reason.find("> (");
      const auto  to     = reason.find(").", from);
      if (from != std::string::npos && to != std::string::npos)
        reason = reason.substr(from + 3, to - from - 3);
      return reason;
    }



    std::string
    user_message(const ExceptionBase &e)
    {
      // (By type: the name deal.II records is the expression as written,
      // "ExcMessage(...)" or "dealii::ExcMessage(...)".)
      if (dynamic_cast<const StandardExceptions::ExcMessage *>(&e))
        return message_of(e);
      // "... in function\n    <name>\n": the library function.
      const std::string what     = e.what();
      std::string       function = "an unknown function";
      if (const auto at = what.find("in function\n"); at != std::string::npos)
        {
          const auto begin = what.find_first_not_of(" ", at + 12);
          const auto end   = what.find('\n', begin);
          if (begin != std::string::npos)
            function = what.substr(begin, end - begin);
        }
      return "An internal check of the deal.II library failed (in " + function +
             "): the input led the library outside what it handles. Most "
             "often this is a mesh with degenerate or extreme cells "
             "(coordinates far outside the model's size in metres, layers "
             "much thinner than the cells, collapsed or inverted cells) or "
             "extreme material constants or time steps. Check <Scene>, "
             "<Material> and <Time integration>; if the input is sound, "
             "please report this message.";
    }



    void
    throw_if_any(const std::string &error, const MPI_Comm communicator)
    {
      const unsigned int n_ranks =
        dealii::Utilities::MPI::n_mpi_processes(communicator);
      const unsigned int mine =
        error.empty() ? n_ranks :
                        dealii::Utilities::MPI::this_mpi_process(communicator);
      const unsigned int first =
        dealii::Utilities::MPI::min(mine, communicator);
      if (first == n_ranks)
        return;
      const std::string message =
        dealii::Utilities::MPI::broadcast(communicator, error, first);
      AssertThrow(false, ExcMessage(message));
    }



  } // namespace Utilities
} // namespace rupture
