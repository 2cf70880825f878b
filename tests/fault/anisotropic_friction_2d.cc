// Anisotropic friction in 2-D (plane strain), where the friction set is an
// interval: with <Fault/Anisotropic friction/First direction> = 0, 0, 1
// (normal to the model plane) the fault's in-plane slip lies along the
// ellipse's second axis, so the strength is r S and the law sees r |slip|.
// For linear slip weakening that is the isotropic law with both friction
// coefficients times r and the slip-weakening distance over r. Checked in
// both fault models: traction at split nodes (explicit, the 2-D rupture of
// tests/simulator/inputs/adaptive_front.prm on its base mesh) and penalty
// contact (the quasi-static loading and implicit rupture of
// tests/fault/load_sequence.prm): r = 2 with the coefficients halved and
// the distance doubled against the prm's isotropic run, stations within
// round-off. A first direction in the model plane leaves the in-plane
// friction isotropic: the same run to the last digit.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
  // The largest difference of two tables (columns after the first, the
  // time) relative to the largest value of each column.
  double
  difference(const std::string &a, const std::string &b)
  {
    const auto x = tests::read_statistics(a), y = tests::read_statistics(b);
    if (x.size() != y.size() || x.empty())
      return 1e300;
    double worst = 0;
    for (unsigned int c = 1; c < x[0].size(); ++c)
      {
        double scale = 0, largest = 0;
        for (unsigned int i = 0; i < x.size(); ++i)
          {
            scale   = std::max(scale, std::abs(x[i][c]));
            largest = std::max(largest, std::abs(x[i][c] - y[i][c]));
          }
        if (scale > 0)
          worst = std::max(worst, largest / scale);
      }
    return worst;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  struct Case
  {
    std::string              title, prm;
    std::vector<std::string> common, halved, stations;
  };
  const std::vector<Case> cases = {
    {"traction at split nodes, explicit",
     std::string(SOURCE_DIR) + "/../simulator/inputs/adaptive_front.prm",
     {"--set",
      "Mesh refinement/Criteria=",
      "--set",
      "Time integration/End time=1.2"},
     {"--set",
      "Fault/Linear slip weakening/Static friction coefficient=(abs(x) <= "
      "5000) ? 0.3385 : 5e3",
      "--set",
      "Fault/Linear slip weakening/Dynamic friction coefficient=0.2625",
      "--set",
      "Fault/Linear slip weakening/Slip-weakening distance=0.8"},
     {"centre", "st030"}},
    {"penalty contact, quasi-static loading and implicit rupture",
     std::string(SOURCE_DIR) + "/load_sequence.prm",
     {},
     {"--set",
      "Fault/Linear slip weakening/Static friction coefficient=0.3 + "
      "0.025*abs(x - 1000)/1000",
      "--set",
      "Fault/Linear slip weakening/Dynamic friction coefficient=0.25",
      "--set",
      "Fault/Linear slip weakening/Slip-weakening distance=0.02"},
     {"centre", "side"}}};

  for (const Case &c : cases)
    {
      const std::string tag = std::to_string(&c - cases.data()) + "-";
      const auto        run = [&](const std::string              &directory,
                           const std::vector<std::string> &extra) {
        std::vector<std::string> args = {c.prm,
                                         "--set",
                                         "Output directory=" + tag + directory};
        args.insert(args.end(), c.common.begin(), c.common.end());
        args.insert(args.end(), extra.begin(), extra.end());
        return tests::run(args);
      };
      std::vector<std::string> anisotropic = c.halved;
      anisotropic.insert(anisotropic.end(),
                         {"--set",
                          "Fault/Anisotropic friction/Strength ratio=2",
                          "--set",
                          "Fault/Anisotropic friction/First direction=0, 0, "
                          "1"});
      const int isotropic_code = run("isotropic", {});
      const int normal_code    = run("normal", anisotropic);
      const int in_plane_code =
        run("in-plane",
            {"--set",
             "Fault/Anisotropic friction/Strength ratio=2",
             "--set",
             "Fault/Anisotropic friction/First direction=1, 0, 0"});
      if (!root)
        continue;
      std::printf("%s: exit codes %d %d %d\n",
                  c.title.c_str(),
                  isotropic_code,
                  normal_code,
                  in_plane_code);
      for (const std::string &s : c.stations)
        {
          const std::string file = "/" + s + ".dat";
          const std::string iso  = tag + "isotropic" + file;
          const auto        rows = tests::read_statistics(iso);
          double            slip = 0;
          for (const auto &row : rows)
            slip = std::max(slip, std::abs(row[1]));
          const double normal = difference(iso, tag + "normal" + file);
          std::printf(
            "  station %s: largest slip %.4f m; r = 2 across the plane "
            "against the isotropic law with mu_s, mu_d times 2 and d_c over "
            "2: %s; r = 2 along the plane against isotropic: %s\n",
            s.c_str(),
            slip,
            normal < 1e-8 ? "within 1e-8" : "DIFFERENT",
            difference(iso, tag + "in-plane" + file) == 0 ? "the same" :
                                                            "DIFFERENT");
        }
    }
}
