#ifndef rupture_base_registry_h
#define rupture_base_registry_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>
#include <vector>

namespace rupture
{
  using namespace dealii;

  namespace Utilities
  {
    /**
     * The list of components of one room (scenes, friction laws, ...) that
     * can be chosen by name in the parameter file. Each component registers
     * itself at static-initialisation time with its name, a description
     * for the parameter reference, its declare_parameters() and a factory
     * @p Factory (a function object, or a set of them for several
     * dimensions).
     */
    template <typename Factory>
    class Registry
    {
    public:
      struct Entry
      {
        std::string                             name;
        std::string                             description;
        std::function<void(ParameterHandler &)> declare;
        Factory                                 create;
      };

      bool
      add(Entry entry)
      {
        entries.push_back(std::move(entry));
        return true;
      }

      /// The names as a Patterns::Selection string, "a|b|c".
      std::string
      selection() const
      {
        std::string names;
        for (const auto &e : entries)
          names += (names.empty() ? "" : "|") + e.name;
        return names;
      }

      /// The names, in the order of registration.
      std::vector<std::string>
      names() const
      {
        std::vector<std::string> result;
        for (const auto &e : entries)
          result.push_back(e.name);
        return result;
      }

      /// One line "'name': description" per component.
      std::string
      descriptions() const
      {
        std::string text;
        for (const auto &e : entries)
          text += "\n'" + e.name + "': " + e.description;
        return text;
      }

      /// The name of the first component registered ("" if none).
      std::string
      first_name() const
      {
        return entries.empty() ? std::string() : entries.front().name;
      }

      /// Declare the parameters of every component.
      void
      declare_all(ParameterHandler &prm) const
      {
        for (const auto &e : entries)
          e.declare(prm);
      }

      /// The component called @p name; @p entry names the parameter in
      /// the error message.
      const Entry &
      find(const std::string &name, const std::string &entry) const
      {
        for (const auto &e : entries)
          if (e.name == name)
            return e;
        AssertThrow(false,
                    ExcMessage("Unknown component <" + name + "> in <" + entry +
                               ">; available: " + selection() + "."));
        return entries.front();
      }

    private:
      std::vector<Entry> entries;
    };
  } // namespace Utilities
} // namespace rupture

#endif
