// A checkpoint continued on a refined mesh (--resume --refine 1), on one
// process and on two: the two-step sequence of fault/load_sequence.prm
// (2-D, cells of 125 m, quasi-static loading until a bonded zone slips,
// then 0.5 s of implicit dynamic rupture with penalty contact). The run
// writes a checkpoint in its loading phase (step 70); that checkpoint is
// continued on its mesh refined once (cells of 62.5 m), the displacement,
// the fault's state and the rest carried over, so that the end of the
// loading and the dynamic phase are computed on the fine mesh. Compared
// with the whole sequence on the coarse mesh and on the fine mesh from
// the start: the continued run ends its loading phase when the fine one
// does and its slip is within 1 % of the fine run's (measured: the same
// to 4 digits, where the coarse run's is 13 % and 22 % lower), its energy
// balance closes, and it reports the refined mesh. The same checkpoint
// continued on its mesh refined twice (--refine 2: both levels made at
// once, the state carried through the mesh between) against the sequence
// on cells of 31.25 m from the start. A checkpoint in a
// phase of the explicit scheme (whose stable step would change) is
// refused with the reason, its run's files untouched.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace
{
  struct Result
  {
    double loading_end = -1;
    double slip[2]     = {0, 0};
    bool   balance     = false;
  };

  Result
  result_of(const std::string &directory)
  {
    Result            r;
    const std::string log = directory + "/log.txt";
    r.loading_end         = tests::find_number(log,
                                       "*** Dynamic phase (implicit "
                                               "Newmark) from t = ");
    r.balance             = tests::read_file(log).find(
                  "Energy balance error below 1e-08 of the energy scale: "
                              "yes") != std::string::npos;
    const char *stations[2] = {"centre", "side"};
    for (unsigned int s = 0; s < 2; ++s)
      {
        const auto rows =
          tests::read_statistics(directory + "/" + stations[s] + ".dat");
        r.slip[s] = rows.empty() ? 0 : rows.back()[1];
      }
    return r;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const bool        root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  const std::string input =
    std::string(SOURCE_DIR) + "/../fault/load_sequence.prm";
  namespace fs = std::filesystem;

  // The coarse sequence, with checkpoints at steps 70 and 125 (its end).
  const std::vector<std::string> coarse = {input,
                                           "--set",
                                           "Output directory=continued",
                                           "--set",
                                           "Checkpoint/Interval=70"};
  // Nothing of an earlier run of the test may stand in for this one's.
  if (root)
    for (const char *d : {"continued", "twice", "pristine", "fine", "finest"})
      fs::remove_all(d);
  MPI_Barrier(comm);
  const int code_coarse = tests::run(coarse);
  MPI_Barrier(comm);
  Result coarse_result;
  if (root)
    {
      coarse_result = result_of("continued");
      fs::remove_all("continued/checkpoint/step-000000125");
      // A copy for the second continuation (a checkpoint continues in
      // its own output directory only).
      fs::copy("continued", "pristine", fs::copy_options::recursive);
    }
  MPI_Barrier(comm);

  // Continued from step 70 on the mesh refined twice; its directory then
  // becomes "twice", and the copy "continued" again.
  std::vector<std::string> twice = coarse;
  for (const std::string a : {"--resume", "--refine", "2"})
    twice.push_back(a);
  const int code_twice = tests::run(twice);
  MPI_Barrier(comm);
  if (root)
    {
      fs::rename("continued", "twice");
      fs::rename("pristine", "continued");
    }
  MPI_Barrier(comm);
  const int code_finest = tests::run({input,
                                      "--set",
                                      "Output directory=finest",
                                      "--set",
                                      "Scene/Box/Number of cells=64"});

  // Continued from step 70 on the mesh refined once.
  std::vector<std::string> resume = coarse;
  for (const std::string a : {"--resume", "--refine", "1"})
    resume.push_back(a);
  const int code_continued = tests::run(resume);

  // The fine sequence from the start.
  const int code_fine = tests::run({input,
                                    "--set",
                                    "Output directory=fine",
                                    "--set",
                                    "Scene/Box/Number of cells=32"});

  // A checkpoint in a phase of the explicit scheme is refused, before the
  // run's directory is touched.
  const std::vector<std::string> explicit_run = {
    std::string(SOURCE_DIR) + "/../fault/split_node_3d.prm",
    "--set",
    "Output directory=explicit",
    "--set",
    "Checkpoint/Interval=10",
    "--set",
    "Time integration/End time=0.4"};
  tests::run(explicit_run);
  const std::string summary =
    root ? tests::read_file("explicit/summary.json") : std::string();
  std::vector<std::string> refine_explicit = explicit_run;
  for (const std::string a : {"--resume", "--refine", "1"})
    refine_explicit.push_back(a);
  std::string errors;
  const int   code_explicit = tests::run_capture(refine_explicit, errors);
  if (!root)
    return 0;
  const Result continued = result_of("continued"), fine = result_of("fine"),
               twice_result = result_of("twice"), finest = result_of("finest");
  std::printf("exit codes: coarse %d, continued %d, fine %d, continued "
              "twice refined %d, finest %d\n",
              code_coarse,
              code_continued,
              code_fine,
              code_twice,
              code_finest);
  for (const std::string directory : {"continued", "twice"})
    {
      const std::string log = tests::read_file(directory + "/log.txt");
      const auto        at  = log.find("The checkpoint's mesh refined");
      std::printf("%s\n",
                  at == std::string::npos ?
                    "the refinement is not reported" :
                    log.substr(at, log.find('\n', at) - at).c_str());
    }
  std::printf("run        loading ends at (s)  slip at centre, side (m)  "
              "energy balance\n");
  const char   *names[5]   = {"coarse", "continued", "fine", "twice", "finest"};
  const Result *results[5] = {
    &coarse_result, &continued, &fine, &twice_result, &finest};
  for (unsigned int i = 0; i < 5; ++i)
    std::printf("%-10s %-20.1f %.4f, %.4f          %s\n",
                names[i],
                results[i]->loading_end,
                results[i]->slip[0],
                results[i]->slip[1],
                results[i]->balance ? "closes" : "does not close");
  std::printf("--refine on a checkpoint of the explicit scheme: exit code "
              "%d, %s; the run's summary untouched: %s\n",
              code_explicit,
              errors.find("--refine continues checkpoints of quasi-static "
                          "and implicit phases") != std::string::npos ?
                "refused with the reason" :
                "not refused",
              tests::read_file("explicit/summary.json") == summary ? "yes" :
                                                                     "no");
  for (unsigned int s = 0; s < 2; ++s)
    std::printf("slip at %s: the continued run within 1 %% of the fine one: "
                "%s, nearer to it than the coarse run: %s; twice refined "
                "within 1 %% of the finest: %s\n",
                s == 0 ? "centre" : "side",
                std::abs(continued.slip[s] - fine.slip[s]) <
                    0.01 * std::abs(fine.slip[s]) ?
                  "yes" :
                  "no",
                std::abs(continued.slip[s] - fine.slip[s]) <
                    std::abs(coarse_result.slip[s] - fine.slip[s]) ?
                  "yes" :
                  "no",
                std::abs(twice_result.slip[s] - finest.slip[s]) <
                    0.01 * std::abs(finest.slip[s]) ?
                  "yes" :
                  "no");
}
