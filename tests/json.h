// Reading the JSON files the program writes (summary.json) in the tests.
#ifndef rupture_tests_json_h
#define rupture_tests_json_h

#include <string>

namespace tests
{
  /// The value of "key" in a JSON text such as summary.json (its first
  /// occurrence, also inside a nested object; a string without its quotes,
  /// a number or literal as written), or "(missing)".
  inline std::string
  json_value(const std::string &text, const std::string &key)
  {
    const auto at = text.find("\"" + key + "\": ");
    if (at == std::string::npos)
      return "(missing)";
    const auto begin = at + key.size() + 4;
    if (text[begin] == '"')
      return text.substr(begin + 1, text.find('"', begin + 1) - begin - 1);
    return text.substr(begin, text.find_first_of(",}\n", begin) - begin);
  }
} // namespace tests

#endif
