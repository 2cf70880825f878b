// deal.II's complaints about parameters in the program's words
// (ParameterMessages): the allowed values of each kind of pattern the
// program declares, read from deal.II's own descriptions, and the messages
// of real ParameterHandler failures (an undeclared entry and a refused
// value through set(), a refused value in a parsed file with its line)
// reworded with the entry's path; a text of another kind stays as it is.

#include <rupture/base/utilities.h>
#include <rupture/simulator/parameter_messages.h>

#include <deal.II/base/parameter_handler.h>

#include <cstdio>
#include <string>

using namespace dealii;
using rupture::ParameterMessages::allowed_values;
using rupture::ParameterMessages::reworded;

namespace
{
  void
  show(const Patterns::PatternBase &pattern)
  {
    std::printf("%s -> %s\n",
                pattern.description().c_str(),
                allowed_values(pattern.description()).c_str());
  }

  template <typename Action>
  void
  fail(const std::string &path, const Action &action)
  {
    try
      {
        action();
        std::printf("no error\n");
      }
    catch (const ExceptionBase &e)
      {
        std::printf("%s\n",
                    reworded(rupture::Utilities::message_of(e), path).c_str());
      }
  }
} // namespace

int
main()
{
  show(Patterns::Double(0, 10));
  show(Patterns::Double());
  show(Patterns::Double(0));
  show(Patterns::Double(Patterns::Double::min_double_value, 1));
  show(Patterns::Integer(2, 3));
  show(Patterns::Integer());
  show(Patterns::Integer(1));
  show(Patterns::Bool());
  show(Patterns::Selection("finite elements|boundary integral"));
  show(Patterns::Anything());
  show(Patterns::List(Patterns::Double()));

  ParameterHandler prm;
  prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3));
  prm.enter_subsection("Damping");
  prm.declare_entry("Fault zone damping", "0", Patterns::Double(0, 10));
  fail("Damping/Fault zone damping",
       [&]() { prm.set("Fault zone damping", "11"); });
  fail("Damping/Fault zone dampng",
       [&]() { prm.set("Fault zone dampng", "1"); });
  prm.leave_subsection();
  fail("",
       [&]() { prm.parse_input_from_string("set Dimension = 4", "in.prm"); });
  std::printf("%s\n", reworded("Some other text.", "A/B").c_str());
  return 0;
}
