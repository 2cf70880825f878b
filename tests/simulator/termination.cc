// Early ends of a run (the Termination subsection) and summary.json. The
// 1-D column of plane_wave.prm with TPV103's flash-heating law, explicit:
// a shear load ramps up to 9 (f = 0.9 under sigma = 10) over 1 s, which
// nucleates a dynamic rupture at once (slip rate up to about 19); from
// t = 3 s it drops to 1, below the weakened strength, and sliding stops
// near t = 3.9 s with about 35.7 m of slip. Each criterion must end the run
// where it says, cleanly (exit code 0, the last step's statistics
// written), with summary.json naming the reason; without criteria the run
// reaches its end time. A criterion that watches the fault is refused in a
// run without one, and a run that fails (an explicit step far above the
// stable limit) still writes summary.json, with status "failed". The
// summary's time step against its stable time step, and its energy
// balance's verdict, are checked too.

#include <deal.II/base/mpi.h>

#include "../json.h"
#include "../tests.h"

#include <cstdio>
#include <string>
#include <vector>

namespace
{
  /// The first line of @p text that is not empty.
  std::string
  first_line_of(const std::string &text)
  {
    const auto begin = text.find_first_not_of('\n');
    if (begin == std::string::npos)
      return "";
    return text.substr(begin, text.find('\n', begin) - begin);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const std::string prm =
    std::string(SOURCE_DIR) + "/../fault/inputs/plane_wave.prm";
  const std::vector<std::string> column = {
    "--set",
    "Fault/Model=traction at split nodes",
    "--set",
    "Fault/Initial traction=5; -10",
    "--set",
    "Fault/Traction perturbation/Traction=1; 0",
    "--set",
    "Fault/Traction perturbation/Time function=(t < 1) ? 4 * t : "
    "((t < 3) ? 4 : ((t < 4) ? 4 - 8 * (t - 3) : -4))",
    "--set",
    "Fault/Friction law=flash heating",
    "--set",
    "Fault/Flash heating/Direct effect=0.01",
    "--set",
    "Fault/Flash heating/Weakening slip rate=0.1",
    "--set",
    "Fault/Flash heating/Evolution effect=0.014",
    "--set",
    "Fault/Flash heating/Characteristic slip distance=0.05",
    "--set",
    "Fault/Flash heating/Reference friction coefficient=0.6",
    "--set",
    "Fault/Flash heating/Reference slip rate=1e-6",
    "--set",
    "Fault/Flash heating/Weakened friction coefficient=0.2",
    "--set",
    "Fault/Flash heating/Initial slip rate=1e-16",
    "--set",
    "Time integration/Scheme=explicit central difference",
    "--set",
    "Time integration/Time step=0",
    "--set",
    "Time integration/End time=8",
    "--set",
    "Output directory=output-termination"};

  struct Case
  {
    const char              *name;
    std::vector<std::string> sets;
  };
  const Case cases[] = {
    {"no criteria", {}},
    {"rupture died (0.5 s below 1 mm/s)",
     {"--set", "Termination/Rupture died after=0.5"}},
    {"rupture died, threshold 1 m/s",
     {"--set",
      "Termination/Rupture died after=0.5",
      "--set",
      "Termination/Slip rate threshold=1"}},
    {"runaway by slip (10 m)", {"--set", "Termination/Maximum slip=10"}},
    {"runaway by moment (1 N per m)",
     {"--set", "Termination/Maximum seismic moment=1"}},
    {"steady state (0.5 s, 0.02)",
     {"--set",
      "Termination/Steady state window=0.5",
      "--set",
      "Termination/Steady state tolerance=0.02"}},
    {"wall-clock limit (1e-9 min)",
     {"--set", "Termination/Wall-clock limit=1e-9"}},
    {"limits that are not reached",
     {"--set",
      "Termination/Maximum slip=1000",
      "--set",
      "Termination/Rupture died after=10"}},
    {"a fault criterion without a fault",
     {"--set", "Fault/Model=none", "--set", "Termination/Maximum slip=1"}},
    {"a steady-state tolerance of 2",
     {"--set",
      "Termination/Steady state window=1",
      "--set",
      "Termination/Steady state tolerance=2"}},
    {"a failing run (a step 9.8 times the stable one)",
     {"--set",
      "Time integration/Time step=0.2",
      "--set",
      "Time integration/Allow unstable time step=true"}}};

  for (const Case &c : cases)
    {
      std::vector<std::string> args = {prm};
      args.insert(args.end(), column.begin(), column.end());
      args.insert(args.end(), c.sets.begin(), c.sets.end());
      // (Rank 0 reads the files after each run; the others wait for it.)
      MPI_Barrier(MPI_COMM_WORLD);
      if (root)
        std::remove("output-termination/summary.json");
      std::string errors;
      const int   code = tests::run_capture(args, errors);
      if (!root)
        continue;
      std::printf("%s: exit code %d\n", c.name, code);
      if (!errors.empty())
        std::printf("  %.100s\n", first_line_of(errors).c_str());
      if (!tests::file_exists("output-termination/summary.json"))
        {
          std::printf("  no summary.json\n");
          continue;
        }
      const std::string summary =
        tests::read_file("output-termination/summary.json");
      const auto rows = tests::read_statistics("output-termination/statistics");
      std::printf("  status %s, end %s, steps %s, t = %.2f s\n",
                  tests::json_value(summary, "status").c_str(),
                  tests::json_value(summary, "end").c_str(),
                  tests::json_value(summary, "steps").c_str(),
                  std::stod(tests::json_value(summary, "time")));
      // The step against the stable one (the column runs at Courant 0.5;
      // the failing run at 0.2 s, 9.8 times the stable step), and the energy
      // balance's verdict, which only a run that ended normally reports.
      std::printf("  time step / stable time step = %.3f, energy balance "
                  "within its tolerance: %s\n",
                  std::stod(tests::json_value(summary, "time step")) /
                    std::stod(tests::json_value(summary, "stable time step")),
                  tests::json_value(summary, "within").c_str());
      if (tests::json_value(summary, "status") == "failed")
        {
          std::printf("  message starts: %.60s\n",
                      tests::json_value(summary, "message").c_str());
          continue;
        }
      std::printf("  message: %s\n",
                  tests::json_value(summary, "message").c_str());
      std::printf("  last statistics row at step %.0f (t = %.2f s)\n",
                  rows.back()[0],
                  rows.back()[1]);
      std::printf("  fault: max slip %.3f m, mean slip %.3f m, ruptured "
                  "length %.3f m, peak slip rate %.2f m/s\n",
                  std::stod(tests::json_value(summary, "max slip")),
                  std::stod(tests::json_value(summary, "mean slip")),
                  std::stod(tests::json_value(summary, "ruptured area")),
                  std::stod(tests::json_value(summary, "peak slip rate")));
    }
  return 0;
}
