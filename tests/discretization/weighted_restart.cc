// A run whose partition weighs the fault's cells (<Discretization/Fault
// cell weight>) keeps that partition when it continues from a checkpoint.
// deal.II's load() partitions a saved mesh by equal numbers of cells; the
// continued run then partitions it once more with the weights, carrying
// the motion and the fault's state, before its first step. On two ranks:
// the 3-D explicit split-node rupture of fault/split_node_3d.prm with
// weight 4, run through (30 steps) and with checkpoints every 10 steps,
// the newest removed as if the run had been killed after step 20, then
// resumed; the same for the implicit penalty rupture of
// fault/penalty_rupture_3d.prm (the energy sums' forces carried, not
// computed anew). The resumed run's last mesh has the uninterrupted run's
// cells and fault cells on each rank (summary.json), its weighted load is
// as even, and its statistics and station are the uninterrupted run's (to
// the last digit for the explicit run, within 1e-8 for the implicit one).
// The same for the 2-D quasi-static block of fault/inputs/stick_slip.prm
// (penalty contact, refined once, the fault at y = 250 m, 35 steps,
// killed after step 30; statistics within 1e-8).

#include <deal.II/base/mpi.h>

#include "../json.h"
#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace
{
  /// The text of list @p key of a summary.json ("[a, b]").
  std::string
  json_list(const std::string &text, const std::string &key)
  {
    const auto at = text.find("\"" + key + "\": [");
    if (at == std::string::npos)
      return "(missing)";
    const auto begin = at + key.size() + 4;
    return text.substr(begin, text.find(']', begin) - begin + 1);
  }

} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  // The explicit split-node rupture, then the implicit penalty one (whose
  // continued steps on two ranks end their Newton iterations with other
  // round-off, tests/simulator/checkpoint_restart: within 1e-8 there).
  // Then the 2-D quasi-static block of fault/inputs/stick_slip.prm (35
  // steps of 0.4 s; statistics only).
  for (const std::string name :
       {"split_node_3d", "penalty_rupture_3d", "stick_slip"})
    {
      const bool        quasi_static = (name == "stick_slip");
      const std::string prm          = std::string(SOURCE_DIR) + "/../fault/" +
                              (quasi_static ? "inputs/" : "") + name + ".prm";
      std::vector<std::string> settings = {"Discretization/Fault cell weight=4",
                                           quasi_static ?
                                             "Time integration/Time step=0.4" :
                                             "Time integration/End time=0.6",
                                           "Checkpoint/Interval=10"};
      // (The block refined once, its fault moved to y = 250 m so that a
      // partition by cells gives rank 0 every fault cell.)
      if (quasi_static)
        settings.insert(settings.end(),
                        {"Discretization/Initial global refinement=1",
                         "Fault/Plane point=0, 250"});
      tests::run_in("full", {prm}, settings);
      tests::run_in("stopped", {prm}, settings);
      // (The two newest checkpoints are kept: the last one goes.)
      if (root)
        std::filesystem::remove_all(quasi_static ?
                                      "stopped/checkpoint/step-000000035" :
                                      "stopped/checkpoint/step-000000030");
      MPI_Barrier(comm);
      std::vector<std::string> resume = {prm, "--resume"};
      for (const std::string &s : settings)
        resume.insert(resume.end(), {"--set", s});
      resume.insert(resume.end(), {"--set", "Output directory=stopped"});
      const int code = tests::run(resume);
      MPI_Barrier(comm);
      if (!root)
        continue;
      std::printf("%s:\n", name.c_str());
      const std::string log = tests::read_file("stopped/log.txt");
      const auto        at  = log.find("*** Continuing after step");
      std::printf("resumed: exit code %d, %s\n",
                  code,
                  at == std::string::npos ?
                    "no 'Continuing' line" :
                    log.substr(at, log.find('\n', at) - at).c_str());
      const auto line = [&](const std::string &start) {
        const auto p = log.find(start);
        return p == std::string::npos ? std::string("(missing)") :
                                        log.substr(p, log.find('\n', p) - p);
      };
      std::printf("%s\n", line("   Partitioned again").c_str());
      const std::string a = tests::read_file("full/summary.json"),
                        b = tests::read_file("stopped/summary.json");
      for (const std::string key : {"cells per rank", "fault cells per rank"})
        std::printf("%s: uninterrupted %s, resumed %s\n",
                    key.c_str(),
                    json_list(a, key).c_str(),
                    json_list(b, key).c_str());
      for (const std::string file : {"statistics", "center.dat"})
        {
          if (quasi_static && file != "statistics")
            continue;
          const double d =
            tests::relative_difference(tests::read_statistics("full/" + file),
                                       tests::read_statistics("stopped/" +
                                                              file));
          // (Exact for the explicit run; within 1e-8 for the implicit one,
          // where on some machines it may be exact too.)
          const bool exact = (name == "split_node_3d");
          std::printf("%s as the uninterrupted run's %s: %s\n",
                      file.c_str(),
                      exact ? "to the last digit" : "within 1e-8",
                      (exact ? d == 0 : d < 1e-8) ? "yes" : "no");
        }
    }
}
