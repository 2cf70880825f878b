// The default scene of contrib/run (prm/default/default.prm), shrunk to
// 1250 m cells, 200-year loading steps, dynamic steps of 0.05 s and 2 s of
// rupture (about 20 s in a Debug build): the loading phase must end when the
// weak patch reaches its strength, the dynamic phase must rupture well beyond
// the 3 km patch (a rupture, not a patch that slips alone), summary.json must
// say so, and contrib/plot-rupture must draw the picture contrib/run shows.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
  double
  json_number(const std::string &text, const std::string &key)
  {
    const auto at = text.find("\"" + key + "\": ");
    return at == std::string::npos ?
             -1 :
             std::atof(text.c_str() + at + key.size() + 4);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string top = std::string(SOURCE_DIR) + "/../../";
  const int         code =
    tests::run({top + "prm/default/default.prm",
                "--set",
                "Discretization/Initial global refinement=2",
                "--set",
                "Time integration/End time=2",
                "--set",
                "Time integration/Time step=0.05",
                "--set",
                "Time integration/Loading phase/Time step=6.31152e9",
                "--set",
                "Output directory=out",
                "--set",
                "Test mode=true"});
  std::printf("exit code %d\n", code);
  const std::string log = tests::read_file("out/log.txt");
  std::printf("the loading phase ended at the weak patch's strength: %s\n",
              log.find("reached its strength") != std::string::npos ? "yes" :
                                                                      "no");
  const std::string summary = tests::read_file("out/summary.json");
  const double      length  = json_number(summary, "ruptured area");
  std::printf("status finished: %s\n",
              summary.find("\"status\": \"finished\"") != std::string::npos ?
                "yes" :
                "no");
  std::printf("ruptured length %.0f m: beyond 4 times the patch: %s\n",
              length,
              length > 12000 ? "yes" : "no");
  std::printf("mean slip %.3f m, peak slip rate %.3f m/s\n",
              json_number(summary, "mean slip"),
              json_number(summary, "peak slip rate"));

  // The picture of contrib/run.
  const int status = std::system(
    (top + "contrib/plot-rupture out --output rupture.png > plot.txt 2>&1")
      .c_str());
  std::printf("contrib/plot-rupture: exit code %d, picture written: %s\n",
              WIFEXITED(status) ? WEXITSTATUS(status) : -1,
              tests::file_exists("rupture.png") ? "yes" : "no");
}
