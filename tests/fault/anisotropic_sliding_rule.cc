// The subdifferential sliding rule of anisotropic friction at every node of
// a 3-D rupture, in both fault methods and for laws of the slip path and
// of the slip rate: the friction ellipse is twice as strong along e_2 =
// n x e_1 = -z as along e_1 = x and the prestress points 30 degrees from
// strike (anisotropic_split_nodes.prm, anisotropic_friction_3d.prm).
//  - At every output (every 0.1 s) and every node whose frictional slip
//    rate (fault surface field frictional_slip_rate) exceeds 1 mm/s, the
//    slip rate lies within 1 degree of the ellipse's normal at the node's
//    shear traction, A^-2 tau, computed here from the output's
//    shear_traction. (The normal of the traction's own direction would
//    be 10-20 degrees away: the rake test shows the turn.) There the
//    traction lies on the ellipse of the strength, |A^-1 tau| = mu
//    sigma_n (fields friction_coefficient, normal_traction), and the
//    dissipation tau . V equals S |A V| (the review paper's eq. 5.2).
//  - The isotropic limit: a strength ratio of 1 + 1e-12 runs the
//    anisotropic code (projection onto the ellipse, dual norms) and must
//    give the isotropic code's slip at every node at the end to 1e-7 of the
//    largest slip (the slip changes by about 1e-8 of it per 1e-12 of the
//    ratio in the penalty case: the limit is continuous).
// Rate and state: the regularised aging law (a = 0.008, b = 0.012, L = 5
// mm; a coarse miniature, not a benchmark), nucleated by a traction
// perturbation that grows over 0.2 s, with both split-node updates
// (centred, end of step). The penalty case (implicit) runs to 0.6 s only.
// A fifth case loads the penalty fault quasi-statically
// (inputs/anisotropic_quasi_static.prm: friction without weakening, the
// load 30 degrees from strike): the sliding rule only.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
  const std::vector<std::string> rate_and_state = {
    "Fault/Initial traction=75e6 * 0.8660254; -120e6; 75e6 * 0.5",
    "Fault/Friction law=rate and state",
    "Fault/Rate and state/Formulation=regularized",
    "Fault/Rate and state/Evolution law=aging",
    "Fault/Rate and state/Direct effect=0.008",
    "Fault/Rate and state/Evolution effect=0.012",
    "Fault/Rate and state/Characteristic slip distance=0.005",
    "Fault/Rate and state/Reference friction coefficient=0.6",
    "Fault/Rate and state/Reference slip rate=1e-6",
    "Fault/Rate and state/Initial slip rate=1e-12",
    "Fault/Traction perturbation/Traction=(x^2 + z^2 < 2.25e6) ? 2.5e7 * "
    "exp((x^2 + z^2) / (x^2 + z^2 - 2.25e6)) * 0.8660254 : 0; 0; (x^2 + z^2 "
    "< 2.25e6) ? 2.5e7 * exp((x^2 + z^2) / (x^2 + z^2 - 2.25e6)) * 0.5 : 0",
    "Fault/Traction perturbation/Time function=(t <= 0) ? 0 : ((t < 0.2) ? "
    "exp((t - 0.2)^2 / (t * (t - 0.4))) : 1)"};

  std::vector<std::string>
  with(std::vector<std::string> a, const std::vector<std::string> &b)
  {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  }

  /// Over the nodes sliding faster than 1 mm/s in @p vtu: the largest
  /// angle (degrees) between the frictional slip rate and A^-2 tau
  /// (@p largest), the largest relative distance of the traction from
  /// the ellipse of the strength, | |A^-1 tau| - mu sigma_n | / (mu
  /// sigma_n) (@p off_ellipse), and of the dissipation tau . V from
  /// S |A V| (@p off_dissipation), and their number @p n.
  void
  sliding_rule(const std::string &vtu,
               const double       ratio,
               double            &largest,
               double            &off_ellipse,
               double            &off_dissipation,
               unsigned int      &n)
  {
    const auto rate     = tests::vtu_field(vtu, "frictional_slip_rate");
    const auto shear    = tests::vtu_field(vtu, "shear_traction");
    const auto friction = tests::vtu_field(vtu, "friction_coefficient");
    const auto normal_t = tests::vtu_field(vtu, "normal_traction");
    for (unsigned int i = 0; 3 * i + 2 < rate.size(); ++i)
      {
        // e_1 = x, e_2 = -z.
        const double v1 = rate[3 * i], v2 = -rate[3 * i + 2];
        const double t1 = shear[3 * i], t2 = -shear[3 * i + 2];
        if (std::hypot(v1, v2) <= 1e-3)
          continue;
        const double normal = std::atan2(t2 / (ratio * ratio), t1);
        const double slip   = std::atan2(v2, v1);
        largest             = std::max(largest,
                           std::abs(std::remainder(slip - normal, 2 * M_PI)) *
                             180 / M_PI);
        const double S      = friction[i] * std::max(-normal_t[i], 0.);
        off_ellipse =
          std::max(off_ellipse, std::abs(std::hypot(t1, t2 / ratio) - S) / S);
        off_dissipation = std::max(off_dissipation,
                                   std::abs(t1 * v1 + t2 * v2 -
                                            S * std::hypot(v1, ratio * v2)) /
                                     (S * std::hypot(v1, ratio * v2)));
        ++n;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        split =
    std::string(SOURCE_DIR) + "/anisotropic_split_nodes.prm";
  const std::string penalty =
    std::string(SOURCE_DIR) + "/anisotropic_friction_3d.prm";
  struct Case
  {
    std::string              name, prm;
    std::vector<std::string> settings;
    bool                     limit = true;
  };
  const std::vector<Case> cases = {
    {"split nodes, slip weakening", split, {}},
    {"split nodes, rate and state, centred", split, rate_and_state},
    {"split nodes, rate and state, end of step",
     split,
     with(rate_and_state, {"Fault/Split-node friction time=end of step"})},
    {"penalty contact, slip weakening",
     penalty,
     {"Time integration/End time=0.6"}},
    {"penalty contact, quasi-static loading",
     std::string(SOURCE_DIR) + "/inputs/anisotropic_quasi_static.prm",
     {},
     false}};
  for (const auto &c : cases)
    {
      // The sliding rule with the ratio 2 of the files.
      tests::run_in("rule",
                    {c.prm},
                    with(c.settings, {"Fault/Output/Output interval=0.1"}));
      double       largest = 0, off_ellipse = 0, off_dissipation = 0;
      unsigned int n = 0;
      for (unsigned int step = 1; step <= 60; ++step)
        {
          char name[64];
          std::snprintf(name, sizeof(name), "rule/fault/fault_%05u.vtu", step);
          if (tests::file_exists(name))
            sliding_rule(tests::read_file(name),
                         2,
                         largest,
                         off_ellipse,
                         off_dissipation,
                         n);
        }
      if (!c.limit)
        {
          std::printf("%s:\n  sliding rule: more than 20 sliding "
                      "node-outputs: %s; slip rate within 1 degree of the "
                      "ellipse's normal at every one: %s (largest %.0e "
                      "degree); traction on the ellipse of the strength, "
                      "|A^-1 tau| = mu sigma_n, to 1e-6: %s; dissipation "
                      "tau . V = S |A V| to 1e-6: %s\n",
                      c.name.c_str(),
                      n > 20 ? "yes" : "no",
                      largest <= 1 ? "yes" : "no",
                      largest <= 1e-6 ? 1e-6 :
                                        (largest <= 1e-3 ? 1e-3 : largest),
                      off_ellipse <= 1e-6 ? "yes" : "no",
                      off_dissipation <= 1e-6 ? "yes" : "no");
          continue;
        }
      // The isotropic limit.
      std::vector<std::vector<double>> slip;
      for (const std::string ratio : {"1", "1.000000000001"})
        {
          tests::run_in("limit",
                        {c.prm},
                        with(c.settings,
                             {"Fault/Anisotropic friction/Strength ratio=" +
                                ratio,
                              "Fault/Output/Output interval=0.6"}));
          // The last output (0.6 s in the penalty case, 1.2 s else).
          const std::string last =
            tests::file_exists("limit/fault/fault_00060.vtu") ?
              "limit/fault/fault_00060.vtu" :
              "limit/fault/fault_00030.vtu";
          slip.push_back(tests::vtu_field(tests::read_file(last), "slip"));
        }
      double largest_slip = 0, difference = 0;
      for (unsigned int i = 0; i < slip[0].size() && i < slip[1].size(); ++i)
        {
          largest_slip = std::max(largest_slip, std::abs(slip[0][i]));
          difference = std::max(difference, std::abs(slip[0][i] - slip[1][i]));
        }
      std::printf(
        "%s:\n  sliding rule: more than 20 sliding node-outputs: %s; "
        "slip rate within 1 degree of the ellipse's normal at "
        "every one: %s (largest %.0e degree); traction on the ellipse of "
        "the strength, |A^-1 tau| = mu sigma_n, to 1e-6: %s; dissipation "
        "tau . V = S |A V| to 1e-6: %s\n  isotropic limit (ratio 1 + 1e-12 "
        "against 1): largest slip %.2f m, every node's slip equal to 1e-7 "
        "of it: %s\n",
        c.name.c_str(),
        n > 20 ? "yes" : "no",
        largest <= 1 ? "yes" : "no",
        largest <= 1e-6 ? 1e-6 : (largest <= 1e-3 ? 1e-3 : largest),
        off_ellipse <= 1e-6 ? "yes" : "no",
        off_dissipation <= 1e-6 ? "yes" : "no",
        largest_slip,
        !slip[0].empty() && slip[0].size() == slip[1].size() &&
            difference <= 1e-7 * largest_slip ?
          "yes" :
          "no");
    }
}
