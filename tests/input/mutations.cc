// A bad-input suite generated from the shipped examples: each example in
// prm/ is shrunk to a few cells and steps by --set overrides, and then every
// one of its entries is mutated (values that are not finite, out of range,
// malformed, empty, garbage bytes, expressions that overflow or divide by
// zero, lists of the wrong length), and the file itself is broken (a missing
// or extra "end", a truncated file, garbage lines, an unknown entry). Every
// mutation must end with an "Error:" message that names what is wrong (the
// mutated entry, one checked together with it, or the broken file), or be
// a correct run: no signal, no raw library text in the message, no NaN or
// Inf in any file written (text tables and the binary arrays of the volume
// snapshots alike), no file outside the output directory, and, when the
// input is refused, the earlier results in the output directory left
// byte-identical.
//
// The output lists each case with its outcome (the entry the message names,
// or "ran"); a case that breaks a rule is printed with "VIOLATION".

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace
{
  struct Entry
  {
    std::string path, value;
    /// Line number of the "set" in the file.
    unsigned int line;
  };

  struct Base
  {
    std::string              name, file;
    std::vector<std::string> shrink;
  };

  std::string
  read(const std::string &file)
  {
    std::ifstream      in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  std::vector<std::string>
  lines_of(const std::string &text)
  {
    std::vector<std::string> lines;
    std::istringstream       in(text);
    std::string              line;
    while (std::getline(in, line))
      lines.push_back(line);
    return lines;
  }

  std::string
  trim(const std::string &s)
  {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos)
      return "";
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
  }

  /// The "set" entries of a parameter file with their section paths.
  std::vector<Entry>
  entries_of(const std::string &text)
  {
    std::vector<Entry>       result;
    std::vector<std::string> sections;
    const auto               lines = lines_of(text);
    for (unsigned int i = 0; i < lines.size(); ++i)
      {
        std::string line = lines[i];
        if (const auto hash = line.find('#'); hash != std::string::npos)
          line.erase(hash);
        line = trim(line);
        if (line.rfind("subsection ", 0) == 0)
          sections.push_back(trim(line.substr(11)));
        else if (line == "end" && !sections.empty())
          sections.pop_back();
        else if (line.rfind("set ", 0) == 0)
          {
            const auto eq = line.find('=');
            if (eq == std::string::npos)
              continue;
            std::string path;
            for (const auto &s : sections)
              path += s + "/";
            path += trim(line.substr(4, eq - 4));
            result.push_back({path, trim(line.substr(eq + 1)), i});
          }
      }
    return result;
  }

  /// Every name the message puts in angle brackets (entries, files, line
  /// numbers).
  std::vector<std::string>
  names_in(const std::string &message)
  {
    std::vector<std::string> names;
    for (std::size_t open = message.find('<'); open != std::string::npos;
         open             = message.find('<', open + 1))
      {
                    const auto close = message.find('>', open);
                    if (close == std::string::npos)
          break;
        if (close - open < 120)
          names.push_back(message.substr(open + 1, close - open - 1));
      }
    return names;
  }

  /// Entries that are checked together with another one, so that a message
  /// about a bad value of the first may name the second instead (a box's
  /// two corners and the layers inside it, lists with one value per
  /// material name, the fault plane that must cut the box).
  const std::vector<std::pair<std::string, std::vector<std::string>>>
    checked_together = {{"Scene/Box/Lower corner",
                         {"Scene/Box/Upper corner",
                          "Scene/Box/Layer interfaces",
                          "Fault/Plus side"}},
                        {"Scene/Box/Upper corner",
                         {"Scene/Box/Lower corner",
                          "Scene/Box/Layer interfaces",
                          "Fault/Plus side"}},
                        {"Fault/Plane point", {"Fault/Plus side"}},
                        {"Fault/Plane normal", {"Fault/Plus side"}},
                        {"Material/Names", {"Material/"}}};

  /// The name in the message that names the mutated @p entry: its whole
  /// path, its last components (a message about a line of the file names
  /// the entry as the file spells it), or an entry checked together with
  /// it; empty if there is none.
  std::string
  name_of_entry(const std::string &message, const std::string &entry)
  {
    const auto matches = [](const std::string &name, const std::string &path) {
      return name == path ||
             (path.size() > name.size() &&
              path.compare(path.size() - name.size(), name.size(), name) == 0 &&
              path[path.size() - name.size() - 1] == '/') ||
             // A prefix such as "Material/": any entry of that subsection.
             (!path.empty() && path.back() == '/' && name.rfind(path, 0) == 0);
    };
    const auto names = names_in(message);
    for (const auto &name : names)
      if (matches(name, entry))
        return name;
    for (const auto &name : names)
      for (const auto &[first, others] : checked_together)
        if (first == entry)
          for (const auto &other : others)
            if (matches(name, other))
              return name;
    return "";
  }

  bool
  looks_numeric(const std::string &value)
  {
    return !value.empty() &&
           value.find_first_not_of("0123456789.eE+-, ;:") == std::string::npos;
  }

  /// The mutated values tried for an entry, chosen by its kind.
  std::vector<std::string>
  mutated_values(const Entry &e)
  {
    if (e.value == "true" || e.value == "false")
      return {"maybe", "", "1e308"};
    if (looks_numeric(e.value))
      return {"nan",
              "-1",
              "0",
              "1e308",
              "-inf",
              "1e-300",
              "abc",
              "1, 2, 3, 4, 5",
              "",
              "1/0",
              std::string("\x01\xfe\xff", 3),
              "12abc"};
    if (e.value.find_first_of("xyzt(") != std::string::npos ||
        e.value.find('?') != std::string::npos)
      return {"1/0",
              "log(0)",
              "exp(1000)",
              "sqrt(-1)",
              "x +",
              "nan",
              "1e308*1e308",
              "",
              "(x > 0) ? 1e400 : 0",
              "y^y^y^y"};
    return {"", "no such choice", std::string("\x01\xfe", 2), "-1"};
  }

  /// Broken versions of the whole file: (what, text).
  std::vector<std::pair<std::string, std::string>>
  broken_files(const std::string &text)
  {
    std::vector<std::pair<std::string, std::string>> result;
    const auto                                       lines = lines_of(text);
    const auto join = [](const std::vector<std::string> &l) {
      std::string s;
      for (const auto &x : l)
        s += x + "\n";
      return s;
    };
    {
      auto l    = lines;
      auto last = std::find_if(l.rbegin(), l.rend(), [](const std::string &x) {
        return trim(x) == "end";
      });
      if (last != l.rend())
        l.erase(std::next(last).base());
      result.emplace_back("the last 'end' removed", join(l));
    }
    result.emplace_back("an extra 'end'", text + "end\n");
    result.emplace_back("cut in the middle", text.substr(0, text.size() / 2));
    result.emplace_back("a line of garbage bytes",
                        std::string("\x00\x01\xff\xfe\n", 5) + text);
    result.emplace_back("an unknown entry", text + "set Time stepping = 0.1\n");
    result.emplace_back("a set without a value", text + "set Dimension\n");
    result.emplace_back("an unclosed subsection",
                        text + "subsection Material\n");
    result.emplace_back("an unknown subsection",
                        text + "subsection Materials\nend\n");
    result.emplace_back("an include of a missing file",
                        "include no-such-file.prm\n" + text);
    result.emplace_back("only comments", "# nothing\n# here\n");
    return result;
  }

  /// Whether @p text holds a token that reads as a non-finite number.
  bool
  has_nonfinite_token(const std::string &text)
  {
    std::string token;
    for (std::size_t i = 0; i <= text.size(); ++i)
      {
        const char c = (i < text.size()) ? text[i] : ' ';
        if (std::isalnum(static_cast<unsigned char>(c)) || c == '.' ||
            c == '-' || c == '+')
          token += c;
        else
          {
            std::string t = token;
            if (!t.empty() && (t[0] == '-' || t[0] == '+'))
              t.erase(0, 1);
            std::transform(t.begin(), t.end(), t.begin(), ::tolower);
            if (t == "nan" || t == "inf" || t == "infinity" || t == "-nan")
              return true;
            token.clear();
          }
      }
    return false;
  }

  /// Whether a .vtu file (appended raw arrays with UInt64 headers, not
  /// compressed) holds a Float64 value that is not finite. Compressed
  /// files are not decoded (the runs here write none).
  bool
  vtu_has_nonfinite(const std::string &bytes, bool &decoded)
  {
    decoded                  = false;
    const std::size_t marker = bytes.find("<AppendedData encoding=\"raw\">");
    if (marker == std::string::npos ||
        bytes.find("compressor=") != std::string::npos)
      return has_nonfinite_token(bytes.substr(0, marker));
    const std::size_t data   = bytes.find('_', marker) + 1;
    const std::string header = bytes.substr(0, marker);
    decoded                  = true;
    std::size_t at           = 0;
    while ((at = header.find("<DataArray", at)) != std::string::npos)
      {
        const std::size_t end = header.find('>', at);
        const std::string tag = header.substr(at, end - at);
        at                    = end;
        if (tag.find("type=\"Float64\"") == std::string::npos ||
            tag.find("offset=\"") == std::string::npos)
          continue;
        const std::size_t offset =
          std::stoull(tag.substr(tag.find("offset=\"") + 8));
        std::uint64_t n = 0;
        std::memcpy(&n, bytes.data() + data + offset, 8);
        for (std::uint64_t k = 0; k < n / 8; ++k)
          {
            double v;
            std::memcpy(&v, bytes.data() + data + offset + 8 + 8 * k, 8);
            if (!std::isfinite(v))
              return true;
          }
      }
    return false;
  }

  /// Every file below @p dir, relative to it.
  std::set<std::string>
  files_below(const fs::path &dir)
  {
    std::set<std::string> result;
    if (fs::is_directory(dir))
      for (const auto &f : fs::recursive_directory_iterator(dir))
        result.insert(fs::relative(f.path(), dir).string());
    return result;
  }

  const char *raw_library_text[] = {"ExcInternalError",
                                    "An error occurred in line",
                                    "--------------------------------",
                                    "AztecOO",
                                    "Amesos",
                                    "std::bad_alloc",
                                    "basic_string",
                                    "stoi",
                                    "Additional information:",
                                    "Stacktrace",
                                    "does not match the given pattern",
                                    "you have not yet declared"};
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  if (!root)
    std::freopen("/dev/null", "w", stdout);

  const std::string prm_dir = std::string(SOURCE_DIR) + "/../../prm/";
  // Each example shrunk to a few cells and steps; every snapshot written,
  // uncompressed, so that its arrays can be read back.
  const std::vector<std::string> common = {"--set",
                                           "Output directory=out",
                                           "--set",
                                           "Test mode=true",
                                           "--set",
                                           "Output/Compression=none"};
  const std::vector<Base>        bases  = {
            {"tpv205-2d",
             "tpv205-2d/tpv205-2d.prm",
             {"Discretization/Polynomial degree=1",
              "Damping/Fault zone damping=0",
              "Scene/Box/Number of cells=12, 6",
              "Time integration/End time=0.8",
              "Output/Output interval=0.2"}},
            {"tpv101-2d",
             "tpv101-2d/tpv101-2d.prm",
             {"Scene/Box/Number of cells=12, 6",
              "Time integration/End time=0.8",
              "Output/Output interval=0.2"}},
            {"northeast-japan-fault-2d",
             "northeast-japan/northeast-japan-fault-2d.prm",
             {"Scene/Northeast Japan/Coarse cell size=100000",
              "Time integration/End time=0.2",
              "Time integration/Loading phase/End time=3.15576e9",
              "Output/Output interval=0.1"}},
            {"box-gravity",
             "box/box-gravity.prm",
             {"Discretization/Initial global refinement=0",
              "Time integration/End time=0.04"}},
            {"layered-box-3d",
             "box/layered-box-3d.prm",
             {"Discretization/Initial global refinement=0",
              "Time integration/End time=0.1",
              "Output/Output interval=0.05"}}};

  // RUPTURE_MUTATION_SHIFT=N (by hand, not in ctest) tries other values.
  const unsigned int shift =
    std::getenv("RUPTURE_MUTATION_SHIFT") ?
      std::atoi(std::getenv("RUPTURE_MUTATION_SHIFT")) :
      0;
  unsigned int n_cases = 0, n_errors = 0, n_runs = 0, n_violations = 0;
  // @p entry: the mutated entry (empty when the file itself is broken).
  const auto run_case = [&](const std::string &base_name,
                            const std::string &what,
                            const std::string &prm_text,
                            const Base        &base,
                            const std::string &override_,
                            const std::string &entry) {
    // The output directory holds an earlier run's results, which bad input
    // must leave byte-identical.
    if (root)
      {
        fs::remove_all("out");
        fs::create_directory("out");
        std::ofstream("out/statistics") << "earlier results\n";
        std::ofstream("out/log.txt") << "earlier log\n";
        std::ofstream("case.prm", std::ios::binary) << prm_text;
      }
    MPI_Barrier(comm);
    const auto before = files_below(".");

    std::vector<std::string> args = {"case.prm"};
    args.insert(args.end(), common.begin(), common.end());
    for (const auto &s : base.shrink)
      {
        args.push_back("--set");
        args.push_back(s);
      }
    if (!override_.empty())
      {
        args.push_back("--set");
        args.push_back(override_);
      }
    std::string errors;
    const int   code = tests::run_capture(args, errors);
    MPI_Barrier(comm);
    ++n_cases;

    // The rules.
    std::vector<std::string> violations;
    if (root)
      {
        if (code != 0 && errors.find("Error:") == std::string::npos)
          violations.emplace_back("no 'Error:' message");
        for (const char *raw : raw_library_text)
          if (errors.find(raw) != std::string::npos)
            violations.emplace_back(std::string("raw library text '") + raw +
                                    "'");
        for (const auto &f : files_below("."))
          if (!before.count(f) && f.rfind("out", 0) != 0)
            violations.emplace_back("wrote " + f +
                                    " outside the output "
                                    "directory");
        for (const auto &f : files_below("out"))
          {
            const fs::path p = fs::path("out") / f;
            if (!fs::is_regular_file(p))
              continue;
            if (p.extension() == ".tmp")
              violations.emplace_back("left " + f);
            const std::string bytes = read(p.string());
            bool              decoded;
            const bool        bad = (p.extension() == ".vtu") ?
                                      vtu_has_nonfinite(bytes, decoded) :
                                      has_nonfinite_token(bytes);
            // The log and parameters.prm repeat the input, which may hold
            // "nan" or "inf" as written by the user.
            if (bad && f != "log.txt" && f != "parameters.prm")
              violations.emplace_back("non-finite value in " + f);
          }
        // A refused input names its cause: the mutated entry (or one it
        // is checked with), or, for a broken file, the file. (A run that
        // started and then failed, e.g. a Newton iteration that did not
        // converge on a valid but different fault, names what to change
        // instead.)
        const bool refused =
          code != 0 && !fs::exists("out/.rupture-manifest.0");
        if (refused && !entry.empty() && name_of_entry(errors, entry).empty())
          violations.emplace_back("the message does not name <" + entry + ">");
        if (refused && entry.empty() &&
            errors.find("case.prm") == std::string::npos)
          violations.emplace_back("the message does not name the file");
        if (code == 0 && !fs::exists("out/statistics"))
          violations.emplace_back("exit 0 without statistics");
        // Refused input (the directory was never opened: no manifest)
        // leaves the earlier results as they were.
        if (code != 0 && !fs::exists("out/.rupture-manifest.0") &&
            (files_below("out") !=
               std::set<std::string>{"log.txt", "statistics"} ||
             read("out/statistics") != "earlier results\n" ||
             read("out/log.txt") != "earlier log\n"))
          violations.emplace_back("changed the earlier results in the "
                                  "output directory");
      }

    std::string outcome;
    if (code == 0)
      {
        outcome = "ran";
        ++n_runs;
      }
    else
      {
        ++n_errors;
        // The entry the message names, if any. An error after the output
        // directory was opened (a run that became unstable) is marked.
        const auto open  = errors.find('<');
        const auto close = errors.find('>', open);
        outcome          = fs::exists("out/.rupture-manifest.0") ?
                             "error during the run" :
                             "error";
        const std::string cause =
          entry.empty() ? "" : name_of_entry(errors, entry);
        if (!cause.empty())
          outcome += " naming <" + cause + ">";
        else if (open != std::string::npos && close != std::string::npos &&
                 close - open < 80)
          outcome += " naming " + errors.substr(open, close - open + 1);
      }
    // Garbage bytes are shown as '?'.
    const auto printable = [](std::string text) {
      for (char &c : text)
        if (static_cast<unsigned char>(c) < 32 ||
            static_cast<unsigned char>(c) > 126)
          c = '?';
      return text;
    };
    const std::string shown = printable(what);
    outcome                 = printable(outcome);
    std::printf("%s | %s | exit %d | %s\n",
                base_name.c_str(),
                shown.c_str(),
                code,
                outcome.c_str());
    // (A case that hangs shows as the last line.)
    std::fflush(stdout);
    for (const auto &v : violations)
      {
        ++n_violations;
        std::string first = errors.substr(0, 300);
        std::replace(first.begin(), first.end(), '\n', ' ');
        std::printf("  VIOLATION: %s\n  message: %s\n",
                    v.c_str(),
                    first.c_str());
      }
  };

  for (unsigned int b = 0; b < bases.size(); ++b)
    {
      const Base       &base    = bases[b];
      const std::string text    = read(prm_dir + base.file);
      const auto        entries = entries_of(text);
      AssertThrow(!entries.empty(), dealii::ExcMessage(base.file));
      // The example itself, shrunk, must run.
      run_case(base.name, "unchanged", text, base, "", "");
      // Three mutated values per entry, a different three for each entry
      // and each example.
      for (unsigned int k = 0; k < entries.size(); ++k)
        {
          const Entry &e = entries[k];
          if (e.path == "Output directory")
            continue;
          const auto values = mutated_values(e);
          for (unsigned int j = 0; j < 3; ++j)
            {
              const std::string &v =
                values[(3 * k + j + 5 * b + shift) % values.size()];
              run_case(base.name,
                       e.path + " = " + v,
                       text,
                       base,
                       e.path + "=" + v,
                       e.path);
            }
        }
      for (const auto &[what, broken] : broken_files(text))
        run_case(base.name, what, broken, base, "", "");
    }

  std::printf("%u cases: %u refused with a message, %u ran; %u violations\n",
              n_cases,
              n_errors,
              n_runs,
              n_violations);
  if (root)
    {
      fs::remove_all("out");
      fs::remove("case.prm");
    }
}
