// A mesh that follows the rupture front (<Mesh refinement/Criteria> =
// rupture front), on one process and on two: the 2-D rupture of
// inputs/adaptive_front.prm on 1 km cells whose fault cells are refined
// two levels where the fault slips and ahead of its front. Compared with
// the same rupture on fixed meshes of the finest size everywhere (h) and of
// twice it (2h):
// - rupture times at the fault's nodes to 5 km within 0.05 s of the fixed
//   fine run, final slips within 2 %, peak slip rates nearer to it than
//   the 2h run's (the fixed runs' own spread);
// - at least 3 times fewer DoFs at the peak than the fixed fine mesh;
// - the fault's nodes 125 m apart where it ruptured and 500 m apart
//   (the base mesh) beyond the barrier, more than a band away;
// - with a high slip-rate threshold and a short delay the mesh coarsens
//   behind the front (its DoFs fall after their peak) and the results stay
//   within the same bounds;
// - the energy balance closes, with the energy the interpolation added
//   counted apart and small;
// - with <Graded band> (rings one level coarser per band ahead of the
//   band), three levels and a band of 40 steps (several of the finest
//   cells wide): rupture times, final slips and peak slip rates as with
//   the plain band of the same levels, and one new mesh per adaptation
//   (the first one apart, which refines <Levels> times), fewer than the
//   plain band's, which refines some cells several levels at once;
// - a checkpoint written after an adaptation continues to the same end
//   (statistics and stations to 1e-12), also on two or three processes
//   when one process wrote it.
// On one, two and three processes the output is the same but for that
// count (the meshes are the same on any partition).

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace
{
  struct Result
  {
    int                    code = -1;
    std::map<long, double> rupture_time; // by along-strike position (m)
    std::vector<double>    node_x;       // the fault's nodes, sorted
    double                 slip[2] = {0, 0}, peak_rate[2] = {0, 0};
    double       peak_dofs = 0, last_dofs = 0, remeshing = 0, energy = 0;
    bool         balance       = false;
    unsigned int n_adaptations = 0;
  };

  Result
  result_of(const std::string &directory, const int code)
  {
    Result r;
    r.code = code;
    for (const auto &row :
         tests::read_statistics(directory + "/rupture_time.dat"))
      if (row.size() >= 3)
        {
          r.rupture_time[std::lround(row[0])] = row[2];
          r.node_x.push_back(row[0]);
        }
    std::sort(r.node_x.begin(), r.node_x.end());
    const char *stations[2] = {"centre", "st030"};
    for (unsigned int s = 0; s < 2; ++s)
      {
        const auto rows =
          tests::read_statistics(directory + "/" + stations[s] + ".dat");
        r.slip[s] = rows.empty() ? 0 : rows.back()[1];
        for (const auto &row : rows)
          r.peak_rate[s] = std::max(r.peak_rate[s], row[2]);
      }
    const std::string log = tests::read_file(directory + "/log.txt");
    r.balance = log.find("Energy balance error below 0.01 of the energy "
                         "scale: yes") != std::string::npos;
    for (std::size_t at = log.find("Mesh adapted after step");
         at != std::string::npos;
         at = log.find("Mesh adapted after step", at + 1))
      ++r.n_adaptations;
    const auto adaptive =
      tests::read_adaptive_columns(directory + "/statistics");
    for (const double n : adaptive.dofs)
      r.peak_dofs = std::max(r.peak_dofs, n);
    if (!adaptive.dofs.empty())
      {
        r.last_dofs = adaptive.dofs.back();
        r.remeshing = adaptive.remeshing.back();
      }
    // Columns (from 1): 5 kinetic, 6 strain.
    const auto rows = tests::read_statistics(directory + "/statistics");
    if (!rows.empty())
      r.energy = rows.back()[4] + rows.back()[5];
    return r;
  }

  // The largest gap between neighbouring fault nodes whose positions
  // satisfy @p where.
  template <typename Where>
  double
  largest_gap(const std::vector<double> &x, const Where &where)
  {
    double gap = 0;
    for (unsigned int i = 0; i + 1 < x.size(); ++i)
      if (where(x[i]) && where(x[i + 1]))
        gap = std::max(gap, x[i + 1] - x[i]);
    return gap;
  }

  const char *
  yes(const bool b)
  {
    return b ? "yes" : "no";
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                           comm = MPI_COMM_WORLD;
  const bool        root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  const std::string input =
    std::string(SOURCE_DIR) + "/inputs/adaptive_front.prm";
  namespace fs   = std::filesystem;
  const auto run = [&](const std::string              &directory,
                       const std::vector<std::string> &settings) {
    return tests::run_in(directory, {input}, settings, comm);
  };

  const int code_adaptive = run("adaptive", {});
  const int code_fine =
    run("fine",
        {"Scene/Box/Number of cells=64,32", "Mesh refinement/Criteria="});
  const int code_coarse =
    run("coarse",
        {"Scene/Box/Number of cells=32,16", "Mesh refinement/Criteria="});
  const std::vector<std::string> wide_band   = {"Mesh refinement/Levels=3",
                                                "Mesh refinement/Interval=40"};
  const int                      code_wide   = run("wide", wide_band);
  std::vector<std::string>       graded_band = wide_band;
  graded_band.push_back("Mesh refinement/Graded band=true");
  const int code_graded     = run("graded", graded_band);
  const int code_coarsening = run("coarsening",
                                  {"Mesh refinement/Slip rate threshold=1.5",
                                   "Mesh refinement/Coarsening delay=0.3"});
  // Checkpoints every 100 steps; the newest two are kept (step 200 and
  // the end). The end's is removed, as if the run had been killed after
  // step 200 (where the mesh was adapted before the checkpoint was
  // written), and so are the files the continued run must write again.
  // The checkpointed run is made by the first process alone, so that on
  // two processes the continued run changes their number (the mesh, the
  // DoFs and the fault's state are distributed anew).
  const unsigned int n_processes =
    dealii::Utilities::MPI::n_mpi_processes(comm);
  int         code_checkpoint = -1;
  std::string continued_from  = "none";
  if (root)
    {
      MPI_Comm first;
      MPI_Comm_dup(MPI_COMM_SELF, &first);
      fs::remove_all("continued");
      code_checkpoint = tests::run_on(first,
                                      {input,
                                       "--set",
                                       "Output directory=continued",
                                       "--set",
                                       "Checkpoint/Interval=100"});
      MPI_Comm_free(&first);
      std::vector<fs::path> written;
      for (const auto &entry : fs::directory_iterator("continued/checkpoint"))
        written.push_back(entry.path());
      std::sort(written.begin(), written.end());
      if (written.size() == 2)
        {
          fs::remove_all(written[1]);
          continued_from = written[0].filename().string();
        }
      fs::rename("continued/statistics", "uninterrupted-statistics");
      fs::rename("continued/st030.dat", "uninterrupted-st030.dat");
    }
  MPI_Barrier(comm);
  const int code_resumed = tests::run({input,
                                       "--set",
                                       "Output directory=continued",
                                       "--set",
                                       "Checkpoint/Interval=100",
                                       "--resume"});
  if (!root)
    return 0;

  const Result adaptive   = result_of("adaptive", code_adaptive);
  const Result fine       = result_of("fine", code_fine);
  const Result coarse     = result_of("coarse", code_coarse);
  const Result coarsening = result_of("coarsening", code_coarsening);
  const Result graded     = result_of("graded", code_graded);
  const Result wide       = result_of("wide", code_wide);
  std::printf("exit codes: adaptive %d, fine %d, coarse %d, coarsening %d, "
              "wide %d, graded %d, checkpointed %d, resumed %d\n",
              adaptive.code,
              fine.code,
              coarse.code,
              coarsening.code,
              wide.code,
              graded.code,
              code_checkpoint,
              code_resumed);

  const auto compare = [&](const char *name, const Result &r) {
    // Nodes that the mesh added after the rupture had reached them have
    // no rupture time of their own (written as 1e9): with the first
    // adaptation before the first step there should be none.
    double worst_time = 0, unknown_beyond = 0;
    for (const auto &[x, t] : fine.rupture_time)
      if (std::abs(x) <= 5000 && t < 1e8)
        {
          const auto other = r.rupture_time.find(x);
          // (A mesh coarsened behind the front has fewer nodes.)
          if (other == r.rupture_time.end())
            continue;
          if (other->second > 1e8)
            unknown_beyond = std::max<double>(unknown_beyond, std::abs(x));
          else
            worst_time = std::max(worst_time, std::abs(other->second - t));
        }
    bool slips = true, rates = true;
    for (unsigned int s = 0; s < 2; ++s)
      {
        slips = slips && std::abs(r.slip[s] - fine.slip[s]) <
                           0.02 * std::abs(fine.slip[s]);
        rates = rates && std::abs(r.peak_rate[s] - fine.peak_rate[s]) <=
                           std::abs(coarse.peak_rate[s] - fine.peak_rate[s]);
      }
    std::printf("%s: %s adaptations; nodes without a rupture time: %s; "
                "rupture times to 5 km within 0.05 s of the fine mesh's: %s; "
                "final slips within 2 %%: %s; peak slip rates nearer than "
                "the 2h mesh's: %s; energy balance closes: %s, the energy "
                "added by mesh changes below 5e-3 of the energy: %s\n",
                name,
                r.n_adaptations > 3 ? "more than 3" : "too few",
                unknown_beyond > 0 ? "some" : "none",
                yes(worst_time < 0.05),
                yes(slips),
                yes(rates),
                yes(r.balance),
                yes(std::abs(r.remeshing) < 5e-3 * r.energy));
  };
  compare("adaptive", adaptive);
  compare("coarsening", coarsening);
  std::printf("the 2h mesh, for comparison: rupture time at 3 km %.3f s "
              "(fine %.3f s, adaptive %.3f s)\n",
              coarse.rupture_time.at(3000),
              fine.rupture_time.at(3000),
              adaptive.rupture_time.at(3000));

  const double fine_dofs =
    tests::find_number("fine/log.txt", "Degrees of freedom: ");
  std::printf("DoFs: fixed fine mesh %.0f, adaptive at its peak %.0f: at "
              "least 3 times fewer: %s\n",
              fine_dofs,
              adaptive.peak_dofs,
              yes(3 * adaptive.peak_dofs <= fine_dofs));
  std::printf(
    "fault node spacing where the fault ruptured (|x| < 5 km): "
    "%.0f m; beyond the barrier (|x| > 6.5 km): %.0f m\n",
    largest_gap(adaptive.node_x, [](double x) { return std::abs(x) < 5000; }),
    largest_gap(adaptive.node_x, [](double x) { return std::abs(x) > 6500; }));
  std::printf("coarsening: DoFs fall after their peak: %s; node spacing at "
              "the centre at the end (|x| < 1 km): %.0f m\n",
              yes(coarsening.last_dofs < coarsening.peak_dofs),
              largest_gap(coarsening.node_x,
                          [](double x) { return std::abs(x) < 1000; }));

  // New meshes per adaptation, from summary.json.
  const auto meshes = [](const std::string &directory) {
    const std::string summary = directory + "/summary.json";
    return std::make_pair(tests::find_number(summary, "\"mesh adaptations\": "),
                          tests::find_number(summary, "\"meshes made\": "));
  };
  const auto [wide_adaptations, wide_meshes]     = meshes("wide");
  const auto [graded_adaptations, graded_meshes] = meshes("graded");
  double worst_time                              = 0;
  for (const auto &[x, t] : wide.rupture_time)
    if (std::abs(x) <= 5000 && t < 1e8)
      {
        const auto other = graded.rupture_time.find(x);
        worst_time       = other == graded.rupture_time.end() ?
                             1e9 :
                             std::max(worst_time, std::abs(other->second - t));
      }
  bool slips = true, rates = true;
  for (unsigned int s = 0; s < 2; ++s)
    {
      slips =
        slips && std::abs(graded.slip[s] - wide.slip[s]) < 5e-3 * wide.slip[s];
      rates = rates && std::abs(graded.peak_rate[s] - wide.peak_rate[s]) <
                         0.02 * wide.peak_rate[s];
    }
  std::printf("graded band against the plain band, three levels: rupture "
              "times to 5 km within 0.005 s: %s, final slips within 0.5 %%: "
              "%s, peak slip rates within 2 %%: %s; new meshes: plain %.0f "
              "in %.0f adaptations, graded %.0f in %.0f: one per adaptation "
              "but the first's three: %s\n",
              yes(worst_time < 5e-3),
              yes(slips),
              yes(rates),
              wide_meshes,
              wide_adaptations,
              graded_meshes,
              graded_adaptations,
              yes(graded_adaptations > 3 &&
                  graded_meshes <= graded_adaptations + 2 &&
                  graded_meshes < wide_meshes));

  // The continued run against the uninterrupted one.
  const auto same = [](const std::string &a, const std::string &b) {
    const auto ra = tests::read_statistics(a), rb = tests::read_statistics(b);
    if (ra.size() != rb.size() || ra.empty())
      return false;
    // The continued run numbers the DoFs of the loaded mesh in another
    // order: sums differ in their last bits, and the balance error and
    // the energy added by mesh changes (columns 9 and 25 of the statistics),
    // differences of energies, are compared at the energies' scale.
    for (unsigned int i = 0; i < ra.size(); ++i)
      for (unsigned int j = 0; j < ra[i].size(); ++j)
        {
          const double scale = ((j == 8 || j == 24) && ra[i].size() > 24) ?
                                 std::abs(ra[i][4]) + std::abs(ra[i][5]) +
                                   std::abs(ra[i][6]) + std::abs(ra[i][7]) :
                                 std::abs(ra[i][j]);
          if (j >= rb[i].size() ||
              std::abs(ra[i][j] - rb[i][j]) > 1e-12 * std::max(1., scale))
            return false;
        }
    return true;
  };
  std::printf("continued from the checkpoint %s of 1 process on %u: "
              "statistics within 1e-12: %s, station st030 within 1e-12: %s\n",
              continued_from.c_str(),
              n_processes,
              yes(same("uninterrupted-statistics", "continued/statistics")),
              yes(same("uninterrupted-st030.dat", "continued/st030.dat")));
}
