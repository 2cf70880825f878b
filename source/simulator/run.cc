#include <rupture/base/interruption.h>
#include <rupture/base/utilities.h>
#include <rupture/boundary_integral/simulation.h>
#include <rupture/simulator/parameter_messages.h>
#include <rupture/simulator/run.h>
#include <rupture/simulator/simulator.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>
#include <vector>

namespace rupture
{
  namespace
  {
    const char *usage =
      "Usage: rupture [options] file.prm\n"
      "       mpirun -np N rupture [options] file.prm\n"
      "\n"
      "Simulates earthquake rupture on a frictional fault in an elastic body,\n"
      "as set up in the parameter file file.prm.\n"
      "\n"
      "Options:\n"
      "  -h, --help                 print this message and exit\n"
      "  --print-parameters [FORMAT]\n"
      "                             print every parameter with its documentation\n"
      "                             and default, and exit. FORMAT is 'markdown'\n"
      "                             (the default; the source of doc/parameters.md)\n"
      "                             or 'prm' (a complete parameter file)\n"
      "  --set \"Section/Entry=value\"\n"
      "                             override one entry of file.prm; may be\n"
      "                             repeated, e.g. for parameter sweeps:\n"
      "                             --set \"Time integration/End time=2\"\n"
      "  --resume                   continue the run of file.prm from the newest\n"
      "                             checkpoint in its output directory\n"
      "                             (<Checkpoint/Interval>)\n"
      "  --refine N                 with --resume: continue on the checkpoint's\n"
      "                             mesh refined N more times everywhere (1 to\n"
      "                             3), its fields and the fault's state carried\n"
      "                             over, e.g. a loading phase computed coarse\n"
      "                             and its dynamic phase fine\n";



    /**
     * Follow the 'include' lines of a .prm file (deal.II parses an
     * included file by recursion, relative to the working directory, so a
     * file that includes itself, directly or through others, would never
     * end) and refuse a cycle or a chain deeper than 32 files.
     */
    void
    check_includes(const std::string &file, std::vector<std::string> &chain)
    {
      namespace fs = std::filesystem;
      std::error_code   error;
      const std::string key = fs::weakly_canonical(file, error).string();
      const auto        at  = std::find(chain.begin(), chain.end(), key);
      if (at != chain.end() || chain.size() >= 32)
        {
          std::string path;
          for (auto c = (at != chain.end() ? at : chain.begin());
               c != chain.end();
               ++c)
            path += "<" + fs::path(*c).filename().string() + "> includes ";
          path += "<" + fs::path(key).filename().string() + ">";
          AssertThrow(false,
                      ExcMessage(
                        at != chain.end() ?
                          "The parameter files include each other in a "
                          "cycle: " +
                            path +
                            ". Remove the 'include' line that closes it." :
                          "The parameter file <" + chain.front() +
                            "> includes files more than 32 deep. Allowed: "
                            "a chain of at most 32 included files."));
        }
      std::ifstream in(file);
      if (!in)
        return; // ParameterHandler reports a missing file itself.
      chain.push_back(key);
      std::string line;
      while (std::getline(in, line))
        {
          const std::string code =
            dealii::Utilities::trim(line.substr(0, line.find('#')));
          if (code.rfind("include ", 0) == 0 || code.rfind("INCLUDE ", 0) == 0)
            check_includes(dealii::Utilities::trim(code.substr(8)), chain);
        }
      chain.pop_back();
    }



    /**
     * Refuse a .json parameter file whose objects and arrays nest deeper
     * than any parameter file can (the JSON reader would recurse until the
     * stack overflows).
     */
    void
    check_json_depth(const std::string &file)
    {
      std::ifstream      in(file);
      std::ostringstream text;
      text << in.rdbuf();
      const std::string s       = text.str();
      unsigned int      depth   = 0;
      bool              quoted  = false;
      const unsigned    allowed = 64;
      for (std::size_t i = 0; i < s.size(); ++i)
        {
          const char c = s[i];
          if (quoted)
            {
              if (c == '\\')
                ++i;
              else if (c == '"')
                quoted = false;
            }
          else if (c == '"')
            quoted = true;
          else if (c == '{' || c == '[')
            {
              AssertThrow(++depth <= allowed,
                          ExcMessage(
                            "The parameter file <" + file +
                            "> nests its objects and arrays more "
                            "than " +
                            std::to_string(allowed) +
                            " deep. Allowed: JSON objects nested as "
                            "deep as the subsections of 'rupture "
                            "--print-parameters prm' (a few levels)."));
            }
          else if ((c == '}' || c == ']') && depth > 0)
            --depth;
        }
    }

    /**
     * Parameter names are stored mangled in the property tree.
     */
    std::string
    demangle(const std::string &s)
    {
      std::string result;
      for (std::size_t i = 0; i < s.size(); ++i)
        if (s[i] == '_' && i + 2 < s.size() && std::isxdigit(s[i + 1]) &&
            std::isxdigit(s[i + 2]))
          {
            result +=
              static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          result += s[i];
      return result;
    }

    void
    print_markdown(const boost::property_tree::ptree &tree,
                   const std::string                 &path,
                   std::ostream                      &out)
    {
      // Entries first, then subsections.
      bool any_entry = false;
      for (const auto &[key, node] : tree)
        if (node.get_optional<std::string>("value"))
          {
            if (!any_entry)
              out << "\n## " << (path.empty() ? "Global parameters" : path)
                  << "\n\n";
            any_entry               = true;
            const std::string value = node.get<std::string>("default_value");
            out << "### `" << demangle(key) << "`\n\n"
                << "- Default: "
                << (value.empty() ? "(empty)" : "`" + value + "`") << "\n"
                << "- Allowed: " << node.get<std::string>("pattern_description")
                << "\n\n"
                << node.get<std::string>("documentation") << "\n\n";
          }
      for (const auto &[key, node] : tree)
        if (!node.get_optional<std::string>("value"))
          print_markdown(node,
                         (path.empty() ? "" : path + " / ") + demangle(key),
                         out);
    }

    void
    apply_override(ParameterHandler &prm, const std::string &assignment)
    {
      const auto equal = assignment.find('=');
      AssertThrow(equal != std::string::npos,
                  ExcMessage("The option --set \"" + assignment +
                             "\" has no '='. Allowed is --set "
                             "\"Section/Subsection/Entry=value\"."));
      const std::vector<std::string> path =
        dealii::Utilities::split_string_list(assignment.substr(0, equal), '/');
      // "=1", "/=1", "A//B=1": every part of the path must name something.
      AssertThrow(
        !path.empty() &&
          std::none_of(path.begin(),
                       path.end(),
                       [](const std::string &part) { return part.empty(); }) &&
          std::count(assignment.begin(), assignment.begin() + equal, '/') + 1 ==
            static_cast<long>(path.size()),
        ExcMessage("The option --set \"" + assignment +
                   "\" names no entry before '='. Allowed is --set "
                   "\"Section/Subsection/Entry=value\"."));
      const std::string value =
        dealii::Utilities::trim(assignment.substr(equal + 1));
      for (unsigned int i = 0; i + 1 < path.size(); ++i)
        prm.enter_subsection(path[i]);
      try
        {
          prm.set(path.back(), value);
        }
      catch (const ExceptionBase &e)
        {
          for (unsigned int i = 0; i + 1 < path.size(); ++i)
            prm.leave_subsection();
          AssertThrow(
            false,
            ExcMessage(
              "The option --set \"" + assignment + "\" was not accepted: " +
              ParameterMessages::reworded(Utilities::message_of(e),
                                          dealii::Utilities::trim(
                                            assignment.substr(0, equal))) +
              " See 'rupture --print-parameters' for the "
              "entries and their allowed values."));
        }
      for (unsigned int i = 0; i + 1 < path.size(); ++i)
        prm.leave_subsection();
    }

    /**
     * A communicator of its own for agreeing on an unexpected failure
     * (end_unexpected()), so that its collective operation never meets
     * another one of the run.
     */
    class FailureChannel
    {
    public:
      explicit FailureChannel(const MPI_Comm communicator)
      {
        MPI_Comm_dup(communicator, &channel);
      }
      ~FailureChannel()
      {
        MPI_Comm_free(&channel);
      }
      MPI_Comm
      get() const
      {
        return channel;
      }

    private:
      MPI_Comm channel;
    };



    /**
     * The end of a run, agreed between the processes on @p channel: each
     * comes with whether it @p failed (and @p what), or with its @p code.
     * A failure may be raised on one process only (an exception outside
     * the program's own collective checks, such as std::bad_alloc, or a
     * file that one process cannot write), while its partners wait in
     * their next collective operation for ever. So every process, finished
     * or failed, meets the others in a barrier of @p channel; a failed one
     * waits for up to ten seconds. If all come, they agree on what
     * happened: if all failed, the first process says why and the run ends
     * with an error as usual; if some failed, each of those says so,
     * naming itself. (Early ends, such as --help, come here too, so that
     * a failure while process 0 prints meets the others.) If not all come, the
     * failed process says so and aborts the run (MPI_Abort), so that the job
     * ends instead of hanging. Returns the exit code: 1 if any process failed.
     */
    int
    agree_on_end(const FailureChannel &channel,
                 const bool            failed,
                 const std::string    &what,
                 const int             code)
    {
      const MPI_Comm     comm = channel.get();
      const unsigned int n    = dealii::Utilities::MPI::n_mpi_processes(comm);
      const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
      if (n == 1)
        {
          if (failed)
            std::cerr << "\nError: " << what << std::endl;
          return failed ? 1 : code;
        }
      MPI_Request request;
      MPI_Ibarrier(comm, &request);
      int all = 0;
      if (!failed)
        {
          MPI_Wait(&request, MPI_STATUS_IGNORE);
          all = 1;
        }
      const auto start = std::chrono::steady_clock::now();
      while (!all && std::chrono::steady_clock::now() - start <
                       std::chrono::seconds(10))
        {
          MPI_Test(&request, &all, MPI_STATUS_IGNORE);
          if (!all)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
      const char *stop =
        (!what.empty() &&
         std::string(".?!").find(what.back()) != std::string::npos) ?
          " " :
          ". ";
      if (!all)
        {
          std::cerr << "\nError on process " << rank << " of " << n << ": "
                    << what << stop
                    << "The other processes did not come to the end "
                       "within ten seconds (they may wait for this one): "
                       "the run is aborted (MPI_Abort)."
                    << std::endl;
          MPI_Abort(comm, 1);
        }
      const unsigned int n_failed =
        dealii::Utilities::MPI::sum(failed ? 1u : 0u, comm);
      if (n_failed == n && rank == 0)
        std::cerr << "\nError: " << what << std::endl;
      else if (n_failed < n && failed)
        std::cerr << "\nError on process " << rank << " of " << n << ": "
                  << what << stop << "(The other processes did not fail.)"
                  << std::endl;
      return n_failed > 0 ? 1 : code;
    }



    template <int dim>
    void
    run_simulation(ParameterHandler  &prm,
                   const MPI_Comm     communicator,
                   const bool         resume,
                   const unsigned int refinements)
    {
      Simulator<dim> simulator(communicator, prm, resume, refinements);
      simulator.run();
    }
  } // namespace



  int
  run_program(const std::vector<std::string> &arguments,
              const MPI_Comm                  communicator)
  {
    const bool root =
      (dealii::Utilities::MPI::this_mpi_process(communicator) == 0);
    const FailureChannel failures(communicator);
    bool                 failed = false;
    std::string          what;
    int                  code = 0;
    try
      {
        std::string              parameter_file;
        std::string              print_format;
        std::vector<std::string> overrides;
        bool                     resume      = false;
        int                      refinements = 0;
        for (unsigned int i = 0; i < arguments.size(); ++i)
          {
            const std::string &arg = arguments[i];
            if (arg == "-h" || arg == "--help")
              {
                if (root)
                  std::cout << usage;
                return agree_on_end(failures, false, "", 0);
              }
            else if (arg == "--print-parameters")
              {
                print_format = "markdown";
                // The next word is the format unless it is an option or a
                // parameter file.
                if (i + 1 < arguments.size() && !arguments[i + 1].empty() &&
                    arguments[i + 1][0] != '-' &&
                    !(arguments[i + 1].size() > 4 &&
                      arguments[i + 1].compare(arguments[i + 1].size() - 4,
                                               4,
                                               ".prm") == 0))
                  {
                    print_format = arguments[++i];
                    AssertThrow(print_format == "markdown" ||
                                  print_format == "prm",
                                ExcMessage("The format <" + print_format +
                                           "> of --print-parameters is "
                                           "unknown. Allowed are 'markdown' "
                                           "and 'prm'."));
                  }
              }
            else if (arg == "--resume")
              resume = true;
            else if (arg == "--refine")
              {
                AssertThrow(i + 1 < arguments.size(),
                            ExcMessage("The option --refine needs a number "
                                       "of refinements (1 to 3)."));
                const std::string n = arguments[++i];
                try
                  {
                    std::size_t end = 0;
                    refinements     = std::stoi(n, &end);
                    if (end != n.size())
                      refinements = -1;
                  }
                catch (...)
                  {
                    refinements = -1;
                  }
                AssertThrow(refinements >= 1 && refinements <= 3,
                            ExcMessage("--refine " + n +
                                       ": the number of refinements must be "
                                       "1, 2 or 3."));
              }
            else if (arg == "--set")
              {
                AssertThrow(i + 1 < arguments.size(),
                            ExcMessage("The option --set needs an argument "
                                       "\"Section/Entry=value\"."));
                overrides.push_back(arguments[++i]);
              }
            else if (arg.rfind("--set=", 0) == 0)
              overrides.push_back(arg.substr(6));
            else if (!arg.empty() && arg[0] == '-')
              {
                AssertThrow(false,
                            ExcMessage("Unknown option <" + arg +
                                       ">. Allowed are --help, "
                                       "--print-parameters, --set, --resume "
                                       "and --refine; see 'rupture --help'."));
              }
            else
              {
                AssertThrow(parameter_file.empty(),
                            ExcMessage("More than one parameter file given (<" +
                                       parameter_file + "> and <" + arg +
                                       ">); rupture runs one at a time."));
                parameter_file = arg;
              }
          }

        ParameterHandler prm;
        Simulator<2>::declare_parameters(prm);
        BoundaryIntegral::declare_parameters(prm);

        if (!print_format.empty())
          {
            if (root)
              {
                if (print_format == "prm")
                  prm.print_parameters(std::cout, ParameterHandler::PRM);
                else
                  {
                    std::ostringstream json;
                    prm.print_parameters(json, ParameterHandler::JSON);
                    boost::property_tree::ptree tree;
                    std::istringstream          in(json.str());
                    boost::property_tree::read_json(in, tree);
                    std::cout << "# rupture parameter reference\n\n"
                              << "Generated by `rupture --print-parameters`; "
                                 "do not edit by hand. Every entry lists its "
                                 "default, the values it accepts and its "
                                 "meaning with units.\n";
                    print_markdown(tree, "", std::cout);
                  }
              }
            return agree_on_end(failures, false, "", 0);
          }

        AssertThrow(!parameter_file.empty(),
                    ExcMessage("No parameter file given. Run 'rupture "
                               "file.prm'; see 'rupture --help'."));
        AssertThrow(refinements == 0 || resume,
                    ExcMessage("--refine refines the mesh of the checkpoint "
                               "that --resume continues: give both."));
        {
          std::ifstream test(parameter_file);
          AssertThrow(test.good() &&
                        !std::filesystem::is_directory(parameter_file),
                      ExcMessage("The parameter file <" + parameter_file +
                                 "> does not exist, is a directory or cannot "
                                 "be read."));
          // A file that sets nothing would run the built-in defaults into
          // ./output: almost never what was meant (an empty file, the wrong
          // file, a sweep script that wrote nothing).
          // (.json and .xml files have a syntax of their own.)
          const auto ends_with = [&](const std::string &suffix) {
            return parameter_file.size() >= suffix.size() &&
                   parameter_file.compare(parameter_file.size() - suffix.size(),
                                          suffix.size(),
                                          suffix) == 0;
          };
          std::string line;
          bool        sets_something = ends_with(".json") || ends_with(".xml");
          while (!sets_something && std::getline(test, line))
            {
              const std::string code =
                dealii::Utilities::trim(line.substr(0, line.find('#')));
              sets_something = code.rfind("set ", 0) == 0 ||
                               code.rfind("include ", 0) == 0 ||
                               code.rfind("subsection ", 0) == 0;
            }
          AssertThrow(sets_something,
                      ExcMessage("The parameter file <" + parameter_file +
                                 "> sets no entry (it is empty or holds only "
                                 "comments), so the run would use the "
                                 "built-in defaults throughout. Give it at "
                                 "least one 'set Entry = value' line; "
                                 "'rupture --print-parameters prm' prints a "
                                 "complete file to start from."));
        }
        if (parameter_file.size() >= 5 &&
            parameter_file.compare(parameter_file.size() - 5, 5, ".json") == 0)
          check_json_depth(parameter_file);
        else
          {
            std::vector<std::string> chain;
            check_includes(parameter_file, chain);
          }
        // deal.II names the file and line of a .prm file's mistakes, but
        // not of a .json or .xml file's, and Boost's parsers name neither.
        const auto has_suffix = [&](const std::string &suffix) {
          return parameter_file.size() >= suffix.size() &&
                 parameter_file.compare(parameter_file.size() - suffix.size(),
                                        suffix.size(),
                                        suffix) == 0;
        };
        const bool        json = has_suffix(".json");
        const std::string in_file =
          (json || has_suffix(".xml")) ?
            "In the parameter file <" + parameter_file + ">: " :
            std::string();
        try
          {
            prm.parse_input(parameter_file, "", false, true);
          }
        catch (const boost::property_tree::file_parser_error &e)
          {
            AssertThrow(false,
                        ExcMessage(
                          "The parameter file <" + parameter_file + ">, line " +
                          std::to_string(e.line()) + ", is not " +
                          (json ? "valid JSON" : "valid XML") + ": " +
                          e.message() + ". " +
                          (json ? "Check the brackets, commas and quotes "
                                  "near that line." :
                                  "Check that every element near that line "
                                  "is closed and that the file has one root "
                                  "element.") +
                          " A .prm file ('rupture --print-parameters prm' "
                          "writes a complete one) is the usual form."));
          }
        catch (const ExceptionBase &e)
          {
            std::string text = Utilities::message_of(e);
            // deal.II wraps Boost's JSON error, "<unspecified file>(LINE):
            // WHAT", and names an unknown entry of a .json or .xml file in
            // words of its own.
            const auto json_at = text.find("<unspecified file>(");
            const auto unknown = text.find("You can't ask for entry <");
            if (json && json_at != std::string::npos)
              {
                const auto open  = text.find('(', json_at);
                const auto close = text.find("):", open);
                if (close != std::string::npos)
                  text = "line " + text.substr(open + 1, close - open - 1) +
                         " is not valid JSON: " +
                         dealii::Utilities::trim(text.substr(close + 2)) +
                         ". Check the brackets, commas and quotes near that "
                         "line.";
              }
            else if (unknown != std::string::npos)
              {
                const auto begin = unknown + 25;
                const auto end   = text.find('>', begin);
                text             = "<" + text.substr(begin, end - begin) +
                       "> is not an entry of rupture here (an unknown name, "
                       "or one of another subsection).";
              }
            else
              text = ParameterMessages::reworded(text, "");
            AssertThrow(false,
                        ExcMessage(in_file + text +
                                   " See 'rupture --print-parameters' for the "
                                   "entries and their allowed values."));
          }
        for (const auto &assignment : overrides)
          apply_override(prm, assignment);

        // From here on SIGTERM and SIGINT stop the run cleanly.
        const Interruption::Handlers handlers;
        const unsigned int           dimension = prm.get_integer("Dimension");
        if (BoundaryIntegral::chosen(prm))
          {
            AssertThrow(refinements == 0,
                        ExcMessage("--refine: the boundary-integral method "
                                   "(<Method> = boundary integral) has no "
                                   "mesh to refine."));
            BoundaryIntegral::run(prm, communicator, resume);
          }
        else if (dimension == 2)
          run_simulation<2>(prm, communicator, resume, refinements);
        else
          run_simulation<3>(prm, communicator, resume, refinements);
      }
    catch (const Interruption::Stopped &stopped)
      {
        if (root)
          std::cerr << "\n" << stopped.what() << std::endl;
        code = 128 + stopped.signal;
      }
    catch (const ExceptionBase &e)
      {
        failed = true;
        what   = Utilities::user_message(e);
      }
    catch (const std::exception &e)
      {
        failed = true;
        what   = e.what();
      }
    catch (...)
      {
        failed = true;
        what   = "An unknown exception was raised.";
      }
    return agree_on_end(failures, failed, what, code);
  }
} // namespace rupture
