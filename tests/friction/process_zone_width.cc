// The friction laws' estimate of the process (cohesive) zone at rest,
// (9 pi / 32) mu d / (Delta p), which the mesh criterion "process zone"
// refines to:
// - linear slip weakening at the parameters of SCEC TPV3/TPV205 (mu_s =
//   0.677, mu_d = 0.525, D_c = 0.4 m, 120 MPa, mu = 32.04 GPa): about
//   620 m, the width the literature quotes for them;
// - no weakening (mu_s = mu_d) or no pressure: infinite;
// - rate and state at TPV101's constants (b = 0.012, L = 0.02 m): mu L /
//   (b p) times 9 pi / 32;
// - every other law that gives one: the same formula with its own slip
//   scale and strength drop taken from its documented constants (the
//   shorter of the two zones of the law with two state variables);
// - Cochard-Madariaga rate weakening gives none (NaN, and says so).

#include <rupture/friction/interface.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>

using namespace dealii;

namespace
{
  std::unique_ptr<rupture::Friction::Interface>
  make(const std::string                        &law,
       const std::string                        &section,
       const std::map<std::string, std::string> &values)
  {
    ParameterHandler prm;
    prm.enter_subsection("Fault");
    rupture::Friction::declare_parameters(prm);
    prm.set("Friction law", law);
    prm.enter_subsection(section);
    for (const auto &[entry, value] : values)
      prm.set(entry, value);
    prm.leave_subsection();
    auto made = rupture::Friction::create(prm);
    prm.leave_subsection();
    return made;
  }

  const double shear_modulus = 32.04e9, pressure = 120e6;
  const double factor = 9 * numbers::PI / 32;

  double
  expected(const double slip_scale, const double drop)
  {
    return factor * shear_modulus * slip_scale / (drop * pressure);
  }

  const char *
  yes(const bool b)
  {
    return b ? "yes" : "no";
  }
} // namespace

int
main()
{
  const Point<3> x(0, 0, -7500);
  {
    auto                     law = make("linear slip weakening",
                    "Linear slip weakening",
                    {{"Static friction coefficient", "0.677"},
                                         {"Dynamic friction coefficient", "0.525"},
                                         {"Slip-weakening distance", "0.4"}});
    rupture::Friction::State state;
    law->initialize_state(x, state);
    const double w = law->process_zone_width(x, state, pressure, shear_modulus);
    std::printf("linear slip weakening, TPV3: %.4g m (expected %.4g m), "
                "has an estimate: %s\n",
                w,
                expected(0.4, 0.677 - 0.525),
                yes(law->has_process_zone_width()));
    std::printf(
      "  without pressure: %g; twice the pressure: half: %s\n",
      law->process_zone_width(x, state, 0, shear_modulus),
      yes(std::abs(
            law->process_zone_width(x, state, 2 * pressure, shear_modulus) / w -
            0.5) < 1e-12));
    auto                     flat = make("linear slip weakening",
                     "Linear slip weakening",
                     {{"Static friction coefficient", "0.6"},
                                          {"Dynamic friction coefficient", "0.6"}});
    rupture::Friction::State s;
    flat->initialize_state(x, s);
    std::printf("  mu_s = mu_d: %g\n",
                flat->process_zone_width(x, s, pressure, shear_modulus));
  }
  {
    auto                     law = make("rate and state", "Rate and state", {});
    rupture::Friction::State state;
    law->initialize_state(x, 0.6, state);
    std::printf("rate and state, TPV101: %.4g m (expected %.4g m)\n",
                law->process_zone_width(x, state, pressure, shear_modulus),
                expected(0.02, 0.012));
  }
  // The documented constants: {a, b, L, ...} (flash heating), {A, B, d_c,
  // ...} (Chester), {mu0, A, B, L, ...} (slowness law), {mu0, A, B1, B2,
  // d1, d2, Vc} (two state variables).
  const std::map<
    std::string,
    std::pair<std::string, std::function<double(const std::vector<double> &)>>>
    others = {
      {"flash heating",
       {"Flash heating",
        [](const std::vector<double> &c) { return expected(c[2], c[1]); }}},
      {"chester",
       {"Chester",
        [](const std::vector<double> &c) { return expected(c[2], c[1]); }}},
      {"slowness law",
       {"Slowness law",
        [](const std::vector<double> &c) { return expected(c[3], c[2]); }}},
      {"two state variables",
       {"Two state variables", [](const std::vector<double> &c) {
          return std::min(expected(c[4], c[2]), expected(c[5], c[3]));
        }}}};
  for (const auto &[name, how] : others)
    {
      auto                     law = make(name, how.first, {});
      rupture::Friction::State state;
      law->initialize_state(x, 0.6, state);
      const double w =
        law->process_zone_width(x, state, pressure, shear_modulus);
      const double e = how.second(state.parameters);
      std::printf("%s: %.4g m, from its constants: %s\n",
                  name.c_str(),
                  w,
                  yes(std::isfinite(w) && std::abs(w / e - 1) < 1e-12));
    }
  {
    auto law = make("cochard madariaga", "Cochard Madariaga", {});
    rupture::Friction::State state;
    law->initialize_state(x, 0.6, state);
    std::printf("cochard madariaga: has an estimate: %s, width is NaN: %s\n",
                yes(law->has_process_zone_width()),
                yes(std::isnan(
                  law->process_zone_width(x, state, pressure, shear_modulus))));
  }
}
