#ifndef rupture_base_utilities_h
#define rupture_base_utilities_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rupture
{
  using namespace dealii;

  /**
   * Small helpers shared by all rooms: parsing user input into functions
   * and vectors, with error messages that name the offending entry.
   */
  namespace Utilities
  {
    /**
     * Turn the text of a .prm entry into a vector-valued function of
     * position and time with @p n_components components. The components are
     * separated by ';', the variables are x, y (, z) and t, and the constant
     * pi is known. An empty string is the zero function. @p entry_name is
     * used in the error message. @p variables overrides the variable names
     * (e.g. "x,y,z" for a function of position only).
     */
    template <int dim>
    std::unique_ptr<FunctionParser<dim>>
    parse_function(const std::string &expression,
                   const unsigned int n_components,
                   const std::string &entry_name,
                   const std::string &variables = "");

    /**
     * Parse a comma separated list of exactly @p dim numbers into a Tensor,
     * e.g. "0, 0, -9.81". If @p allow_single_value, a single number is
     * used for all components. The message names @p entry_name on error.
     */
    template <int dim>
    Tensor<1, dim>
    parse_vector(const std::string &text,
                 const std::string &entry_name,
                 const bool         allow_single_value = false);

    /**
     * Parse named points 'name: x, y[, z]; name: ...' (station and receiver
     * lists). Names must be non-empty, unique, and free of '/' and spaces
     * (they become file names). The message names @p entry_name on error.
     */
    template <int dim>
    std::vector<std::pair<std::string, Point<dim>>>
    parse_named_points(const std::string &text, const std::string &entry_name);

    /**
     * Split a comma separated list into trimmed, non-empty strings.
     */
    std::vector<std::string>
    split_list(const std::string &text, const char separator = ',');

    /**
     * Split @p text at every @p separator into trimmed fields, empty ones
     * kept (one per material in "a; ; b"); a blank text is one empty
     * field.
     */
    std::vector<std::string>
    split_fields(const std::string &text, const char separator = ';');

    /**
     * Split @p text at the commas outside parentheses into trimmed items,
     * empty ones kept: a list whose items may be functions with commas of
     * their own ("C11 = if(z < 0, 1e10, 2e10), C33 = 4e10").
     */
    std::vector<std::string>
    split_top_level(const std::string &text);

    /**
     * Parse a list of doubles. The message names @p entry_name on error.
     */
    std::vector<double>
    parse_doubles(const std::string &text, const std::string &entry_name);

    /**
     * Join strings with ", " for messages like "allowed names are ...".
     */
    std::string
    join(const std::vector<std::string> &items);

    /**
     * Write @p contents to @p filename through a temporary file that is
     * renamed at the end, so a crash never leaves a half-written file.
     */
    void
    write_file_atomically(const std::string &filename,
                          const std::string &contents);

    /**
     * The text of a deal.II exception without its source location and
     * stack trace, on one line: what the user is shown.
     */
    std::string
    message_of(const ExceptionBase &e);

    /// The reason parse_function() gives for an expression it refused
    /// (the function parser's own words), without the general advice
    /// around it: for messages that name the entry themselves.
    std::string
    parser_reason(const ExceptionBase &e);

    /**
     * What the user is shown for an exception that ends the run: the
     * program's own checks (ExcMessage) are messages already (message_of());
     * any other exception is one of the deal.II library's internal checks,
     * whose text (the violated condition, a paragraph on deal.II's
     * internals, a stack trace) means nothing to a user. It becomes a
     * diagnosis that says what usually leads there, with the library
     * function for a report.
     */
    std::string
    user_message(const ExceptionBase &e);

    /**
     * Collective: if @p error is not empty on any process of
     * @p communicator, every process throws the error of the lowest such
     * process (so that a check that fails on one process only stops all of
     * them instead of leaving the others waiting).
     */
    void
    throw_if_any(const std::string &error, const MPI_Comm communicator);
  } // namespace Utilities
} // namespace rupture

#endif
