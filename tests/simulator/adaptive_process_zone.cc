// The criterion "process zone" of <Mesh refinement>, the DoF budget and
// the time interval between adaptations, on the 2-D rupture of
// inputs/adaptive_front.prm (Q2, 1 km base cells; slip weakening with a
// process zone at rest of (9 pi/32) mu D_c / ((mu_s - mu_d) sigma_n) =
// 621 m where it ruptures, |x| <= 5 km, and a strength barrier beyond):
// - front and process zone, <Levels> = 4: the front's cells are refined
//   only as deep as 3 nodes per zone need (207 m: node spacing 125 m, two
//   levels), not four levels; with 6 nodes per zone (104 m) three levels
//   (62.5 m). Rupture times within 0.05 s of the front alone at two
//   levels (the same cells);
// - the process zone alone, <Levels> = 3: before the first step the whole
//   fault is refined, to 125 m where it ruptures and to the cap of three
//   levels (62.5 m) in the barrier, whose huge strength drop makes its
//   zone tiny by the estimate;
// - the same in orthotropic rock whose shear stiffness across the fault
//   is mu / 4 (C66; the estimate takes the tensor's modulus across the
//   fault): the zone is a quarter, and the cap of three levels is reached
//   where it ruptures;
// - a DoF budget below the front's peak: the run says the mesh stays
//   below it and never exceeds it;
// - adaptations every 0.1 s of time instead of every 10 steps: about one
//   per 0.1 s, and the same rupture times.

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
    std::vector<double>    adapted_at;   // times of the adaptations (s)
    double                 peak_dofs     = 0;
    unsigned int           n_adaptations = 0;
    bool                   held          = false;
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
    const std::string log = tests::read_file(directory + "/log.txt");
    std::vector<long> steps;
    const std::string key = "Mesh adapted after step ";
    for (std::size_t at = log.find(key); at != std::string::npos;
         at             = log.find(key, at + 1))
      {
                    ++r.n_adaptations;
                    steps.push_back(std::stol(log.substr(at + key.size())));
      }
    r.held = log.find("The mesh stays below") != std::string::npos;
    for (const double n :
         tests::read_adaptive_columns(directory + "/statistics").dofs)
      r.peak_dofs = std::max(r.peak_dofs, n);
    // Column 1 the step, 2 the time.
    for (const auto &row : tests::read_statistics(directory + "/statistics"))
      for (const long step : steps)
        if (step > 1 && std::lround(row[0]) == step)
          r.adapted_at.push_back(row[1]);
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

  // The largest difference of the rupture times of @p a and @p b at the
  // nodes both have, to 4 km.
  double
  time_difference(const Result &a, const Result &b)
  {
    double worst = 0;
    for (const auto &[x, t] : a.rupture_time)
      if (std::abs(x) <= 4000 && t < 1e8)
        {
          const auto other = b.rupture_time.find(x);
          if (other != b.rupture_time.end())
            worst = std::max(worst, std::abs(other->second - t));
        }
    return worst;
  }

  const char *
  yes(const bool b)
  {
    return b ? "yes" : "no";
  }

  // Where the rupture has passed by the end (1.2 s: the front is near
  // 3.5 km).
  bool
  inside(const double x)
  {
    return std::abs(x) < 3000;
  }

  bool
  barrier(const double x)
  {
    return std::abs(x) > 5500;
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
    return result_of(
      directory,
      tests::run_in(directory,
                    {input, "--set", "Time integration/End time=1.2"},
                    settings,
                    comm));
  };

  const Result front = run("front", {});
  const Result zone3 =
    run("zone3",
        {"Mesh refinement/Criteria=rupture front, process zone",
         "Mesh refinement/Levels=4"});
  const Result zone6 =
    run("zone6",
        {"Mesh refinement/Criteria=rupture front, process zone",
         "Mesh refinement/Levels=4",
         "Mesh refinement/Nodes per process zone=6"});
  const Result only = run("only",
                          {"Mesh refinement/Criteria=process zone",
                           "Mesh refinement/Levels=3",
                           "Time integration/End time=0.02"});
  // The same in orthotropic rock whose shear stiffness across the fault
  // (C66, the fault's normal being y) is a quarter of mu, the other
  // constants the isotropic rock's: the zone estimate is a quarter (155 m).
  const Result soft =
    run("soft",
        {"Mesh refinement/Criteria=process zone",
         "Mesh refinement/Levels=3",
         "Time integration/End time=0.02",
         "Material/Symmetry=orthotropic",
         "Material/Stiffness=C11 = 9.612e10, C22 = 9.612e10, C33 = 9.612e10, "
         "C12 = 3.2044e10, C13 = 3.2044e10, C23 = 3.2044e10, C44 = "
         "3.2038e10, C55 = 3.2038e10, C66 = 0.80095e10"});
  const Result budget =
    run("budget", {"Mesh refinement/Maximum degrees of freedom=2500"});
  const Result timed = run("timed", {"Mesh refinement/Time interval=0.1"});
  if (!root)
    return 0;

  std::printf("exit codes: front %d, zone3 %d, zone6 %d, only %d, budget %d, "
              "timed %d\n",
              front.code,
              zone3.code,
              zone6.code,
              only.code,
              budget.code,
              timed.code);
  std::printf("front alone, 2 levels: node spacing where it ruptures %.1f m\n",
              largest_gap(front.node_x, inside));
  for (const auto &[name, r] : {std::make_pair("3 nodes per zone", &zone3),
                                std::make_pair("6 nodes per zone", &zone6)})
    std::printf("front and process zone, %s, 4 levels allowed: node spacing "
                "where it ruptures %.1f m; rupture times to 4 km within "
                "0.05 s of the front alone: %s\n",
                name,
                largest_gap(r->node_x, inside),
                yes(time_difference(front, *r) < 0.05));
  std::printf("process zone alone, 3 levels allowed: node spacing where it "
              "ruptures %.1f m, in the barrier %.1f m, anywhere on the fault "
              "%.1f m\n",
              largest_gap(only.node_x, inside),
              largest_gap(only.node_x, barrier),
              largest_gap(only.node_x, [](double) { return true; }));
  std::printf("process zone alone in orthotropic rock with C66 = mu / 4 "
              "(exit code %d): node spacing where it ruptures %.1f m (the "
              "cap: 3 nodes per zone of 155 m need 52 m)\n",
              soft.code,
              largest_gap(soft.node_x, inside));
  std::printf("budget of 2500 DoFs (the front's peak: %.0f): held back and "
              "said so: %s; peak at most the budget: %s\n",
              front.peak_dofs,
              yes(budget.held),
              yes(budget.peak_dofs <= 2500));
  // Each adaptation of the timed run after the first step at the step
  // that crossed a multiple of 0.1 s (the step is 0.0072 s).
  bool on_time = !timed.adapted_at.empty();
  for (const double t : timed.adapted_at)
    on_time = on_time && std::fmod(t, 0.1) < 0.0072 + 1e-9;
  std::printf("every 0.1 s: %u adaptations that changed the mesh in 1.2 s "
              "(every 10 steps: %u), each after the step that crossed a "
              "multiple of 0.1 s: %s; rupture times to 4 km within 0.05 s of "
              "those: %s\n",
              timed.n_adaptations,
              front.n_adaptations,
              yes(on_time),
              yes(time_difference(front, timed) < 0.05));
}
