#ifndef rupture_simulator_parameter_messages_h
#define rupture_simulator_parameter_messages_h

#include <string>

namespace rupture
{
  /**
   * deal.II's ParameterHandler words its complaints about an entry in its
   * own terms ("You can't ask for entry <X> you have not yet declared",
   * "The string <v> does not match the given pattern <[Double 0...10
   * (inclusive)]>"). These functions say the same in the program's words,
   * naming the entry by its whole path and its allowed values in plain
   * language.
   */
  namespace ParameterMessages
  {
    /**
     * The allowed values of a pattern's description ("[Double 0...10
     * (inclusive)]": "a number from 0 to 10"; "[Selection a|b ]": "one of
     * a, b"); a description it does not know is returned as it is.
     */
    std::string
    allowed_values(const std::string &description);

    /**
     * @p text (deal.II's message for the entry @p path, "Section/Entry")
     * in the program's words: an undeclared entry, a value that does not
     * match its pattern (also as parse_input() reports it, with the line
     * and file); any other text is returned unchanged.
     */
    std::string
    reworded(const std::string &text, const std::string &path);
  } // namespace ParameterMessages
} // namespace rupture

#endif
