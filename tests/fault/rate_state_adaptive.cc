// A mesh that follows a rate-and-state rupture: the reduced TPV101-2D of
// tpv101_2d_reduced.cc (aging law, smooth nucleation pulse, 40 km x 12 km,
// to t = 5 s) on 1 km cells whose fault cells are refined two levels at
// the front, against the same 1 km mesh with a static band of 250 m cells
// along the whole fault (the finest cells everywhere the adaptive mesh can
// put them; a mesh of 250 m cells throughout differs from both by up to
// 0.1 s at 6 km: the far field's cells matter too, and Q1 at 250 m is not
// converged). Rate-and-state nucleation has no
// patch above a static strength, so nothing is refined before the first
// step; the mesh must then be adapted at the first step at which a fault
// node slips faster than 1 mm/s, not only every <Interval> (here 40)
// steps. Checked: the first adaptation in the time loop comes before the
// hypocentre ruptures in the band run plus two base steps; the rupture
// times at 3 and 6 km are within 0.02 s of the band run's; the energy
// balance closes.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const std::string top = std::string(SOURCE_DIR) + "/../../";
  const std::string prm = top + "prm/tpv101-2d/tpv101-2d.prm";
  const auto        run = [&](const std::string              &directory,
                       const std::vector<std::string> &more) {
    std::vector<std::string> arguments = {
      prm,
      "--set",
      "Test mode=true",
      "--set",
      "Output directory=" + directory,
      "--set",
      "Output/Output interval=-1",
      "--set",
      "Discretization/Polynomial degree=1",
      "--set",
      "Damping/Fault zone damping=0",
      "--set",
      "Scene/Box/Lower corner=-20000, -6000",
      "--set",
      "Scene/Box/Upper corner=20000, 6000",
      "--set",
      "Fault/Output/Stations=faultst000: 0, 0; faultst030: 3000, 0; "
             "faultst060: 6000, 0",
      "--set",
      "Time integration/End time=5"};
    arguments.insert(arguments.end(), more.begin(), more.end());
    return tests::run(arguments);
  };
  const int band =
    run("band",
        {"--set",
         "Scene/Box/Number of cells=40, 12",
         "--set",
         "Discretization/Refinement region=(abs(y) < 600) ? 1 : 0",
         "--set",
         "Discretization/Refinement region levels=2"});
  const int adaptive = run("adaptive",
                           {"--set",
                            "Scene/Box/Number of cells=40, 12",
                            "--set",
                            "Mesh refinement/Criteria=rupture front",
                            "--set",
                            "Mesh refinement/Levels=2",
                            "--set",
                            "Mesh refinement/Interval=40"});
  if (!root)
    return 0;
  std::printf("exit codes: band %d, adaptive %d\n", band, adaptive);
  std::map<std::string, double> t_band, t_adaptive;
  for (const std::string name : {"000", "030", "060"})
    {
      t_band[name] = tests::rupture_time(
        tests::read_statistics("band/faultst" + name + ".dat"));
      t_adaptive[name] = tests::rupture_time(
        tests::read_statistics("adaptive/faultst" + name + ".dat"));
    }
  // The first adaptation in the time loop, from the screen log.
  std::ifstream log("adaptive/log.txt");
  std::string   line;
  long          first_step = -1;
  while (first_step < 0 && std::getline(log, line))
    {
      const auto at = line.find("Mesh adapted after step ");
      if (at != std::string::npos)
        {
          const long step = std::stol(line.substr(at + 24));
          if (step > 0)
            first_step = step;
        }
    }
  const auto stats         = tests::read_statistics("adaptive/statistics");
  double     time_of_first = -1, base_step = stats.front()[2];
  for (const auto &row : stats)
    if (std::lround(row[0]) == first_step)
      time_of_first = row[1];
  std::printf("first adaptation in the time loop after step %ld, before "
              "the hypocentre ruptures in the band run plus two base "
              "steps: %s\n",
              first_step,
              (time_of_first >= 0 &&
               time_of_first <= t_band["000"] + 2 * base_step) ?
                "yes" :
                "no");
  for (const std::string name : {"030", "060"})
    std::printf("station %s: ruptures %s, within 0.02 s of the band "
                "run's: %s\n",
                name.c_str(),
                t_adaptive[name] >= 0 ? "yes" : "no",
                (t_adaptive[name] >= 0 && t_band[name] >= 0 &&
                 std::abs(t_adaptive[name] - t_band[name]) < 0.02) ?
                  "yes" :
                  "no");
  std::ifstream again("adaptive/log.txt");
  while (std::getline(again, line))
    if (line.find("Energy balance error below") != std::string::npos)
      std::printf("%s\n", line.substr(line.find("Energy")).c_str());
}
