// deal.II's messages about parameters in the program's words.

#include <rupture/simulator/parameter_messages.h>

#include <deal.II/base/utilities.h>

#include <vector>

namespace rupture
{
  namespace ParameterMessages
  {
    namespace
    {
      /// The text between @p open and the next @p close after @p from in
      /// @p text; @p from moves past it. Empty if there is none.
      std::string
      between(const std::string &text,
              const std::string &open,
              const std::string &close,
              std::size_t       &from)
      {
        const auto begin = text.find(open, from);
        if (begin == std::string::npos)
          return "";
        const auto end = text.find(close, begin + open.size());
        if (end == std::string::npos)
          return "";
        from = end + close.size();
        return text.substr(begin + open.size(), end - begin - open.size());
      }

      /// "A...B" as words for @p kind ("a number"), leaving out the
      /// bounds that are the type's largest values.
      std::string
      range(const std::string &kind, const std::string &bounds)
      {
        const auto dots = bounds.find("...");
        if (dots == std::string::npos)
          return kind;
        const std::string low = dealii::Utilities::trim(bounds.substr(0, dots));
        const std::string high =
          dealii::Utilities::trim(bounds.substr(dots + 3));
        const auto unbounded = [](const std::string &b) {
          return b.find("MAX_") != std::string::npos || b == "2147483647" ||
                 b == "-2147483648" || b == "4294967295";
        };
        if (unbounded(low) && unbounded(high))
          return kind;
        if (unbounded(high))
          return kind + " of at least " + low;
        if (unbounded(low))
          return kind + " of at most " + high;
        return kind + " from " + low + " to " + high;
      }
    } // namespace



    std::string
    allowed_values(const std::string &description)
    {
      const std::string d = dealii::Utilities::trim(description);
      const auto inside = d.size() > 2 && d.front() == '[' && d.back() == ']' ?
                            dealii::Utilities::trim(d.substr(1, d.size() - 2)) :
                            d;
      const auto starts = [&](const std::string &prefix) {
        return inside.compare(0, prefix.size(), prefix) == 0;
      };
      const auto bounds = [&](const std::string &prefix) {
        std::string rest = inside.substr(prefix.size());
        const auto  open = rest.find(" (");
        return dealii::Utilities::trim(rest.substr(0, open));
      };
      if (starts("Double"))
        return range("a number", bounds("Double"));
      if (starts("Integer range"))
        return range("a whole number", bounds("Integer range"));
      if (starts("Bool"))
        return "true or false";
      if (starts("Selection"))
        {
          std::string words;
          for (const auto &choice : dealii::Utilities::split_string_list(
                 dealii::Utilities::trim(inside.substr(9)), '|'))
            words += (words.empty() ? "" : ", ") + choice;
          return "one of: " + words;
        }
      return "of the form " + d;
    }



    std::string
    reworded(const std::string &text, const std::string &path)
    {
      std::size_t at = 0;
      // An entry that was never declared (ParameterHandler::set()).
      if (text.find("You can't ask for entry <") != std::string::npos)
        return "<" + path +
               "> is not an entry of rupture (an unknown name, or one of "
               "another subsection).";
      // A value its pattern refuses (ParameterHandler::set()).
      if (text.find("does not match the given pattern") != std::string::npos &&
          text.find("The string <") != std::string::npos)
        {
          const std::string value = between(text, "The string <", ">", at);
          const std::string pattern =
            between(text, "the given pattern <", ">.", at);
          return "<" + path + "> = " + value + " is not allowed: it must be " +
                 allowed_values(pattern) + ".";
        }
      // The same from a .prm file (parse_input()): "Line <L> of file <F>:
      // The entry value V for the entry named N does not match the given
      // pattern: P".
      if (text.find("The entry value ") != std::string::npos &&
          text.find("does not match the given pattern: ") != std::string::npos)
        {
          const std::string line = between(text, "Line <", ">", at);
          const std::string file = between(text, "of file <", ">", at);
          const auto        v    = text.find("The entry value ") + 16;
          const auto        n    = text.find(" for the entry named ", v);
          const auto p = text.find(" does not match the given pattern: ", n);
          if (n == std::string::npos || p == std::string::npos)
            return text;
          const std::string value = text.substr(v, n - v);
          const std::string name  = text.substr(n + 21, p - n - 21);
          const std::string pattern =
            dealii::Utilities::trim(text.substr(p + 35));
          return (line.empty() ? "" : "Line " + line + " of <" + file + ">: ") +
                 "<" + name + "> = " + value + " is not allowed: it must be " +
                 allowed_values(pattern) + ".";
        }
      return text;
    }
  } // namespace ParameterMessages
} // namespace rupture
