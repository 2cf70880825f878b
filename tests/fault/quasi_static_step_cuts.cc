// A quasi-static step whose Newton iteration fails is cut in half and the
// run goes on: the spring-slider of inputs/spring_slider_cycles.prm with
// large steps (xi = 0.2, up to 1e7 s) fails to converge once, in the step
// of 2.5e6 s in which the second event nucleates (the slip rate grows by
// orders of magnitude within it). With <Solver/Maximum step cuts> = 4 (the
// default) the step is redone as two half steps, the controller goes on
// from the half step, and the run ends with both events, the second at
// the time the slider's equations give (4.5125 years; within 0.5 %). With
// no cuts allowed the same run stops in that step with a message that
// names the entry.

#include <deal.II/base/mpi.h>

#include "../json.h"
#include "../spring_slider_reference.h"
#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        prm =
    std::string(SOURCE_DIR) + "/inputs/spring_slider_cycles.prm";
  const std::vector<std::string> large = {
    "Time integration/End time=1.5e8",
    "Time integration/Step controller/State evolution fraction=0.2",
    "Time integration/Step controller/Maximum time step=1e7"};

  const int    code = tests::run_in("cuts", {prm}, large);
  const auto   log  = tests::read_file("cuts/log.txt");
  unsigned int cuts = 0;
  for (auto at = log.find("the step is cut in half"); at != std::string::npos;
       at      = log.find("the step is cut in half", at + 1))
    ++cuts;
  std::printf("with cuts: exit code %d, steps cut: %s\n",
              code,
              cuts > 0 ? "at least one" : "none");
  // summary.json counts the same cuts as the log, and the run closes its
  // energy balance (the implicit tolerance).
  const auto summary = tests::read_file("cuts/summary.json");
  std::printf("summary.json: step cuts as in the log: %s, energy balance "
              "within its tolerance (%s): %s\n",
              tests::json_value(summary, "step cuts") == std::to_string(cuts) ?
                "yes" :
                "no",
              tests::json_value(summary, "tolerance").c_str(),
              tests::json_value(summary, "within").c_str());

  // Events: the slip rate passes 1 mm/s (interpolated in ln V).
  const auto          rows = tests::read_statistics("cuts/statistics");
  std::vector<double> t, V;
  for (const auto &r : rows)
    {
      t.push_back(r[1]);
      V.push_back(r[15]);
    }
  const std::vector<double> starts = slider_reference::find_events(t, V).start;
  const double              year   = 3.15576e7;
  std::printf("events: %zu; the second at the slider's time within 0.5 %%: "
              "%s\n",
              starts.size(),
              starts.size() == 2 &&
                  std::abs(starts[1] / year / 4.5125 - 1) < 5e-3 ?
                "yes" :
                "no");

  std::vector<std::string> none = large;
  none.push_back("Solver/Maximum step cuts=0");
  std::string errors;
  const int   stopped = tests::run_capture({prm,
                                            "--set",
                                            "Output directory=no-cuts",
                                            "--set",
                                            none[0],
                                            "--set",
                                            none[1],
                                            "--set",
                                            none[2],
                                            "--set",
                                            none[3]},
                                         errors);
  std::printf("without cuts: exit code %d, the message names the entry: %s\n",
              stopped,
              errors.find("<Solver/Maximum step cuts> = 0") !=
                  std::string::npos ?
                "yes" :
                "no");
  return 0;
}
