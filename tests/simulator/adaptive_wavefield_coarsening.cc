// Coarsening by the criterion "wavefield" once the waves have left, on one
// process, on two and on three (the same meshes and output on each: the
// level balance is decided alike on every partition): a plane P pulse along a
// strip of 1 km Q1 cells (inputs/adaptive_wavefield_strip.prm) splits, runs to
// the absorbing ends and leaves through them. The cells are refined up to two
// levels where the pulses are (before the first step as far as the initial
// pulse needs, and in a band ahead of them) and coarsened behind them: the DoFs
// rise while the pulses cross the strip and fall back to the base mesh's once
// they have left (measured: 250 DoFs at the base, 1334 at the first step,
// 2166 at the peak, 250 at the end). Against a fixed mesh of the finest cells
// (250 m) everywhere, at three receivers: the adaptive mesh within 2 % (largest
// difference of the velocity, relative to the largest velocity there; 0.6 %),
// in 0.33 of the fixed mesh's DoF-steps; the energy balance closes with the
// interpolation's energy counted apart. (Before the band and the initial
// levels, the pulse's first steps on coarser cells left grid-scale waves
// behind that hardly move and kept every cell refined: manual 3.1.)

#include <deal.II/base/mpi.h>

#include "../tests.h"
#include "wavefield_runs.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

using namespace wavefield_runs;



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  const std::vector<std::string> names = {"r1", "r2", "r3"};
  const std::string at  = "r1: 0, 0; r2: 5000, 1000; r3: -9000, -1500";
  const auto        run = [&](const std::string              &directory,
                       const std::vector<std::string> &settings) {
    return wavefield_runs::run(
      "adaptive_wavefield_strip.prm", directory, at, settings, comm);
  };
  const int codes[2] = {run("fixed",
                            {"Scene/Box/Number of cells=96,16",
                             "Mesh refinement/Criteria="}),
                        run("adaptive", {})};
  if (!root)
    return 0;
  std::printf("exit codes: %d %d\n", codes[0], codes[1]);
  double worst = 0;
  for (const std::string &r : names)
    worst = std::max(worst,
                     difference(receiver("adaptive", r), receiver("fixed", r)));
  std::printf("receivers' largest difference from the fixed fine mesh %.3f, "
              "below 2 %%: %s\n",
              worst,
              yes(worst < 0.02));

  const std::vector<double> dofs =
    tests::read_adaptive_columns("adaptive/statistics").dofs;
  const double first = dofs.empty() ? 0 : dofs.front();
  const double last  = dofs.empty() ? 0 : dofs.back();
  const double peak =
    dofs.empty() ? 0 : *std::max_element(dofs.begin(), dofs.end());
  // The base mesh: 24 x 4 Q1 cells, 25 x 5 vertices, two components.
  const double base_dofs = 2 * 25 * 5;
  std::printf("DoFs at the first step %.0f, at the peak %.0f, at the end "
              "%.0f (the base mesh: %.0f); refined before the first step and "
              "further while the pulses cross, back to the base mesh at the "
              "end: %s\n",
              first,
              peak,
              last,
              base_dofs,
              yes(last == base_dofs && peak > first && first > 4 * base_dofs));

  const double fixed_steps =
    tests::find_number("fixed/log.txt", "Degrees of freedom:") *
    tests::read_statistics("fixed/statistics").size();
  const double steps = dof_steps("adaptive").first;
  std::printf("DoF-steps %.2f of the fixed mesh's, below 0.4: %s\n",
              steps / fixed_steps,
              yes(steps > 0 && steps < 0.4 * fixed_steps));
  // Exact: the same meshes on every number of processes.
  std::printf("DoF-steps %.0f\n", steps);

  const std::string log = tests::read_file("adaptive/log.txt");
  std::printf("energy balance closes: %s\n",
              yes(log.find("Energy balance error below 0.01 of the energy "
                           "scale: yes") != std::string::npos));
}
