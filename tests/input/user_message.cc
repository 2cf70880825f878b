// What the user is shown when a run ends with an exception
// (Utilities::user_message()): the program's own checks (ExcMessage) are
// shown as they are, on one line; any other exception, one of deal.II's
// internal checks, becomes a diagnosis naming the library function, with
// none of deal.II's paragraph or stack trace.

#include <rupture/base/utilities.h>

#include <deal.II/base/exceptions.h>

#include <cstdio>
#include <functional>
#include <string>

namespace
{
  void
  library_function_that_fails()
  {
    AssertThrow(false, dealii::ExcInternalError());
  }

  void
  show(const char *title, const std::function<void()> &action)
  {
    try
      {
        action();
      }
    catch (const dealii::ExceptionBase &e)
      {
        const std::string m = rupture::Utilities::user_message(e);
        std::printf("%s:\n  %s\n  one line: %s; deal.II's dump in it: %s\n",
                    title,
                    m.c_str(),
                    m.find('\n') == std::string::npos ? "yes" : "no",
                    (m.find("Stacktrace") != std::string::npos ||
                     m.find("An error occurred") != std::string::npos ||
                     m.find("violated condition") != std::string::npos) ?
                      "yes" :
                      "no");
      }
  }
} // namespace

int
main()
{
  show("the program's own check", []() {
    AssertThrow(false,
                dealii::ExcMessage("<Material/Density> is 0 kg/m^3. Allowed: "
                                   "densities from 1e-3 to 1e6 kg/m^3."));
  });
  show("an internal check of the library", library_function_that_fails);
  show("an index out of range",
       []() { AssertThrow(5 < 3, dealii::ExcIndexRange(5, 0, 3)); });
}
