// The criterion "wavefield" (<Mesh refinement/Criteria> = rupture front,
// wavefield), on one process and on two: the 2-D rupture of
// inputs/adaptive_front.prm (1 km Q2 cells, the fault's cells two levels
// finer at the front) radiates waves, which the criterion follows by
// refining cells anywhere, up to <Wavefield levels> = 2, where the jump of
// the velocity's normal derivative across their faces exceeds <Wavefield
// threshold>. Off-fault receivers against the same rupture on a fixed mesh
// of the finest cells everywhere (the largest difference of the velocity,
// relative to the largest velocity there; the percentages were measured on
// 2026-11-29, before <Wavefield band> and the initial levels before the
// first step, and the checks hold with both):
// - with the front alone (the body at 1 km) the receivers are 5-28 % off
//   (mean 19 %); with the wavefield at 3e-5 1/s the mean is 2 %, below a
//   fifth of it, and every receiver below the front alone's (1-4 % where
//   the front alone is 21-28 % off; 3 % against 4.8 % at the far receiver
//   r4, near the barrier; at 3e-4 1/s, not run here, the mean is 8 %);
// - the finest run makes fewer DoF-steps than the fixed mesh;
// - cells away from the fault are refined (more DoFs at the peak than with
//   the front alone), and the log gives the largest indicator at each
//   adaptation, for choosing the threshold.
// In 3-D, the wavefield alone follows a wave packet above a locked fault
// (inputs/adaptive_wavefield.prm, 2 km Q1 cells, one level) against a
// fixed mesh of 1 km cells: the coarse mesh is 44-84 % off at the
// receivers, the wavefield at 1e-5 1/s 1-7 %, at 3e-6 0.2-1.7 % (below a
// tenth of the coarse mesh's and below 1e-5's at every receiver), in fewer
// DoF-steps than the fixed mesh, with the energy balance closed. The
// packet refines the cells above the fault first, and the rounds that
// refine the other side alike carry the fields with their hanging nodes
// following the constraints (before, a debug build stopped in deal.II's
// transfer on two values for one DoF).

#include <deal.II/base/mpi.h>

#include "../tests.h"
#include "wavefield_runs.h"

#include <algorithm>
#include <cmath>
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
  const std::vector<std::string> names = {"r1", "r2", "r3", "r4"};
  const auto                     run = [&](const std::string              &input,
                       const std::string              &directory,
                       const std::string              &receivers,
                       const std::vector<std::string> &settings) {
    return wavefield_runs::run(input, directory, receivers, settings, comm);
  };

  // 2-D: the rupture's waves, the front followed as well.
  {
    const std::string
      in = "adaptive_front.prm",
      at = "r1: 2000, 2000; r2: -3000, -2500; r3: 0, 3500; r4: 6000, 3000";
    const std::string both =
      "Mesh refinement/Criteria=rupture front, wavefield";
    const int codes[3] = {run(in,
                              "2d/fixed",
                              at,
                              {"Scene/Box/Number of cells=64,32",
                               "Mesh refinement/Criteria="}),
                          run(in, "2d/front", at, {}),
                          run(in,
                              "2d/fine-threshold",
                              at,
                              {both,
                               "Mesh refinement/Wavefield threshold=3e-5",
                               "Mesh refinement/Wavefield levels=2"})};
    if (root)
      {
        std::printf("2-D exit codes: %d %d %d\n", codes[0], codes[1], codes[2]);
        const auto [means, every] =
          compare("2d", {"front", "fine-threshold"}, names, 1.);
        std::printf("receivers' mean difference from the fixed mesh at 3e-5 "
                    "1/s below a fifth of the front alone's: %s, and at every "
                    "receiver below it: %s\n",
                    yes(means[1] < 0.2 * means[0]),
                    yes(every));
        const double front_peak  = dof_steps("2d/front").second;
        const auto [steps, peak] = dof_steps("2d/fine-threshold");
        // The fixed mesh has no DoF column: its DoFs from the log.
        const double fixed_steps =
          tests::find_number("2d/fixed/log.txt", "Degrees of freedom:") *
          tests::read_statistics("2d/fixed/statistics").size();
        std::printf("DoF-steps at 3e-5 below the fixed mesh's: %s; peak DoFs "
                    "above the front alone's (cells away from the fault "
                    "refined): %s; the log gives the largest wavefield "
                    "indicator: %s\n",
                    yes(steps > 0 && steps < fixed_steps),
                    yes(peak > front_peak),
                    yes(tests::read_file("2d/fine-threshold/log.txt")
                          .find("largest wavefield indicator") !=
                        std::string::npos));
      }
  }

  // 3-D: a wave packet above a locked fault, the wavefield alone.
  {
    const std::string in = "adaptive_wavefield.prm",
                      at =
                        "r1: 0, 0, 500; r2: 2500, 0, 3000; r3: 0, 3000, 1000; "
                        "r4: -2000, -2000, 4000";
    const int codes[4] = {
      run(in,
          "3d/fixed",
          at,
          {"Scene/Box/Number of cells=12,12,12", "Mesh refinement/Criteria="}),
      run(in, "3d/coarse", at, {"Mesh refinement/Criteria="}),
      run(in,
          "3d/coarse-threshold",
          at,
          {"Mesh refinement/Wavefield threshold=1e-5"}),
      run(in,
          "3d/fine-threshold",
          at,
          {"Mesh refinement/Wavefield threshold=3e-6"})};
    if (root)
      {
        std::printf("3-D exit codes: %d %d %d %d\n",
                    codes[0],
                    codes[1],
                    codes[2],
                    codes[3]);
        const auto [means, every] = compare(
          "3d", {"coarse", "coarse-threshold", "fine-threshold"}, names, 0.1);
        std::printf("receivers' mean difference from the fixed fine mesh falls "
                    "from the coarse mesh to the wavefield at 1e-5 and 3e-6 "
                    "1/s: %s; at 3e-6 below a tenth of the coarse mesh's and "
                    "below 1e-5's at every receiver: %s\n",
                    yes(means[2] < means[1] && means[1] < means[0]),
                    yes(every));
        const double fixed_steps =
          tests::find_number("3d/fixed/log.txt", "Degrees of freedom:") *
          tests::read_statistics("3d/fixed/statistics").size();
        const auto        steps = dof_steps("3d/fine-threshold").first;
        const std::string log   = tests::read_file("3d/fine-threshold/log.txt");
        std::printf("DoF-steps at 3e-6 below the fixed fine mesh's: %s; "
                    "energy balance closes: %s\n",
                    yes(steps > 0 && steps < fixed_steps),
                    yes(log.find("Energy balance error below 0.01 of the "
                                 "energy scale: yes") != std::string::npos));
      }
  }
}
