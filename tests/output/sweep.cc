// contrib/sweep on a small grid: prm/sweep/slip-weakening-2d.prm at 1 km
// cells, mu_d x L_d = {0.5, 0.57} x {0.25, 1, -1}, two cases at a time.
// The cases with L_d = -1 are refused by the program: they must be
// recorded as failed with the program's message, without stopping the
// others. The other four run to their outcome (mu_d = 0.57 with L_d = 1
// dies at nucleation; the early end by <Termination/Rupture died after>
// shows in the 'end' column). Then resuming: with one finished case's
// summary.json removed, a second run keeps the three other finished cases
// and runs that one and the two failed ones again. Last, sweep files that
// must be refused before anything runs, each with its message. The sweep's
// exit code is 1 while cases did not finish (here the refused ones).

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

namespace
{
  int
  shell(const std::string &command)
  {
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  void
  write(const std::string &file, const std::string &text)
  {
    std::ofstream(file) << text;
  }

  std::vector<std::string>
  split(const std::string &line, const char separator)
  {
    std::vector<std::string> items;
    std::string              item;
    bool                     quoted = false;
    for (const char c : line)
      if (c == '"')
        quoted = !quoted;
      else if (c == separator && !quoted)
        {
          items.push_back(item);
          item.clear();
        }
      else
        item += c;
    items.push_back(item);
    return items;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string top = std::string(SOURCE_DIR) + "/../../";
  // The test runs in build-*/tests/<room>/<name>.<build>/; the program of
  // this build is build-*/rupture.
  const std::string sweep = top + "contrib/sweep --rupture ../../../rupture ";
  const std::string head  = "base = " + top +
                           "prm/sweep/slip-weakening-2d.prm\n"
                           "output = out-sweep\n"
                           "set Scene/Box/Number of cells = 40, 20\n"
                           "set Fault/Output/Stations =\n"
                           "set Time integration/End time = 6\n"
                           "set Test mode = true\n";
  write("small.sweep",
        head + "title = test sweep\n"
               "vary mu_d: Fault/Linear slip weakening/Dynamic friction "
               "coefficient = 0.5, 0.57\n"
               "vary L_d: Fault/Linear slip weakening/Slip-weakening "
               "distance = 0.25, 1, -1\n"
               "derive S = (0.677 * 120 - 70) / (70 - mu_d * 120)\n"
               "nucleation size = 3000\n"
               "fault size = 30000\n");

  std::printf("first run: exit code %d\n",
              shell(sweep + "small.sweep --jobs 2 > run1.txt 2>&1"));
  {
    std::istringstream in(tests::read_file("out-sweep/summary.csv"));
    std::string        line;
    std::getline(in, line);
    const auto header = split(line, ',');
    std::printf("columns: %zu, first %s, %s, %s, %s\n",
                header.size(),
                header[0].c_str(),
                header[1].c_str(),
                header[2].c_str(),
                header[3].c_str());
    while (std::getline(in, line))
      {
        const auto f = split(line, ',');
        if (f.size() != header.size())
          {
            std::printf("a row of %zu fields\n", f.size());
            continue;
          }
        // case, mu_d, L_d, S, outcome, end, M0 ... message (last)
        std::printf("case %s (mu_d %s, L_d %s, S %s): %s; end '%s'; M0 %s; "
                    "message '%.70s'\n",
                    f[0].c_str(),
                    f[1].c_str(),
                    f[2].c_str(),
                    f[3].c_str(),
                    f[4].c_str(),
                    f[5].c_str(),
                    f[6].empty() ? "-" : f[6].c_str(),
                    f.back().c_str());
      }
  }
  for (const std::string file : {"summary.md",
                                 "outcome-map.png",
                                 "magnitude.png",
                                 "final-slip.png",
                                 "case-0000/case.prm",
                                 "case-0000/parameters.prm",
                                 "case-0000/run.txt",
                                 "case-0002/run.txt"})
    std::printf("%s: %s\n",
                file.c_str(),
                tests::file_exists("out-sweep/" + file) ? "written" :
                                                          "MISSING");

  // Resume: one finished case loses its summary.json.
  std::remove("out-sweep/case-0003/summary.json");
  shell(sweep + "small.sweep --jobs 2 > run2.txt 2>&1");
  {
    std::istringstream in(tests::read_file("run2.txt"));
    std::string        line;
    std::getline(in, line);
    // "6 cases in DIR: 3 done already, 3 to run, ..."
    std::printf("resume: %s\n", line.substr(line.find(": ") + 2).c_str());
    // The cases run two at a time and finish in any order (a loaded
    // machine changed it): sorted by case.
    std::vector<std::string> ran;
    while (std::getline(in, line))
      if (line.find("case-") != std::string::npos)
        ran.push_back(line.substr(line.find(']') + 1));
    std::sort(ran.begin(), ran.end());
    for (const std::string &r : ran)
      std::printf("  ran%s\n", r.c_str());
  }

  // Sweep files refused before anything runs.
  const std::vector<std::pair<std::string, std::string>> bad = {
    {"an unknown entry",
     "vary Fault/Linear slip weakening/Static friction = 0.6, 0.7\n"},
    {"an empty range",
     "sample = random 4\nvary Fault/Linear slip "
     "weakening/Slip-weakening distance = uniform 1 1\n"},
    {"an unknown key",
     "ranks per case = 2\nvary Material/Density = 2000, 3000\n"},
    {"a count that is not one",
     "vary Material/Density = range 2000 3000 zero\n"},
    {"'uniform' in a grid", "vary Material/Density = uniform 2000 3000\n"},
    {"nothing varied", "set Material/Density = 2000\n"},
    {"the output directory varied", "vary Output directory = a, b\n"}};
  for (const auto &[name, text] : bad)
    {
      write("bad.sweep", head + text);
      const int code =
        shell(sweep + "bad.sweep --output out-bad > bad.txt 2>&1");
      const std::string message = tests::read_file("bad.txt");
      std::printf("%s: exit code %d, ran nothing: %s\n  %s",
                  name.c_str(),
                  code,
                  tests::file_exists("out-bad") ? "no" : "yes",
                  message.c_str());
    }
  // A Latin-hypercube sample (listed only): one case in each quarter of
  // each range (mu_d in steps of 0.025; log10 L_d in steps of 0.25), and a
  // list of values that hold commas, separated by '|'.
  write(
    "latin.sweep",
    head +
      "sample = latin 4\nseed = 7\n"
      "vary mu_d: Fault/Linear slip weakening/Dynamic friction "
      "coefficient = uniform 0.5 0.6\n"
      "vary L_d: Fault/Linear slip weakening/Slip-weakening "
      "distance = loguniform 0.1 1\n"
      "vary corner: Scene/Box/Lower corner = -20000, -10000 | -25000, -10000\n");
  shell(sweep + "latin.sweep --dry-run > latin.txt 2>&1");
  {
    std::istringstream in(tests::read_file("latin.txt"));
    std::string        line;
    std::getline(in, line);
    std::printf("latin sample: %s\n",
                line.substr(0, line.find(" into")).c_str());
    while (std::getline(in, line))
      std::printf("%s\n", line.c_str());
  }

  // Another design into the sweep's directory would mix two sweeps.
  write("other.sweep", head + "vary Material/Density = 2000, 3000\n");
  const int         code    = shell(sweep + "other.sweep > other.txt 2>&1");
  const std::string message = tests::read_file("other.txt");
  std::printf("another sweep into out-sweep: exit code %d\n  %s\n",
              code,
              message
                .substr(message.find("holds"),
                        message.find(" from ") - message.find("holds"))
                .c_str());
}
