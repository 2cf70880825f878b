// Anisotropic friction at one fault point (Fault::anisotropic_return_map,
// penalty contact): the friction set is the ellipse |A^-1 tau| <= S with
// strength factors a_1 = 1 along e_1 and a_2 = r along e_2 = n x e_1, on an
// oblique fault plane in 3-D, with linear slip weakening (TPV3's law). A
// block under a shear load that turns through the fault plane:
//  - below the ellipse it sticks, also where the load exceeds the
//    isotropic strength S (along e_2 with r = 2);
//  - sliding, the traction lies on the ellipse, the slip increment is
//    along the normal of the ellipse at the traction (A^-2 tau), not along
//    the load, the slip the law sees is the dual norm |A slip|, and the
//    dissipated work tau . slip equals S |A slip| (the paper's eq. 5.2);
//  - the consistent tangent matches central finite differences: stick,
//    sliding along e_1, along e_2, at an angle, near zero normal stress;
//  - with r = 1 everything equals the isotropic return_map();
//  - a rate-and-state law with radiation damping eta, met at the step's
//    end and centred (the implicit midpoint rule): the friction's part of
//    the traction (less eta du / dt; of the step's mean traction when
//    centred) lies on the ellipse of the strength at the slip l = |A du|
//    (at half of it over half the step when centred), du along the
//    ellipse's normal there, the tangent matches finite differences, and
//    with r = 1 it equals return_map() with the same damping.

#include <rupture/fault/anisotropic_contact.h>
#include <rupture/friction/interface.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <cstdio>

using namespace dealii;
using namespace rupture::Fault;

namespace
{
  const char *
  name(const ContactStatus s)
  {
    return s == ContactStatus::stick ?
             "stick" :
             (s == ContactStatus::slip ? "slip" : "open");
  }

  std::unique_ptr<rupture::Friction::Interface>
  make_law(const std::string &weakening_distance = "0.4")
  {
    ParameterHandler prm;
    prm.enter_subsection("Fault");
    rupture::Friction::declare_parameters(prm);
    prm.set("Friction law", "linear slip weakening");
    prm.enter_subsection("Linear slip weakening");
    prm.set("Static friction coefficient", "0.677");
    prm.set("Dynamic friction coefficient", "0.525");
    prm.set("Slip-weakening distance", weakening_distance);
    prm.leave_subsection();
    auto law = rupture::Friction::create(prm);
    prm.leave_subsection();
    return law;
  }

  const double pn = 5e11, pt = 4e11, dt = 0.1;

  Tensor<1, 3>
  normal()
  {
    Tensor<1, 3> n;
    n[0] = 1. / 3;
    n[1] = 2. / 3;
    n[2] = 2. / 3;
    return n;
  }

  /// Check one load: the shear part of the initial traction has
  /// magnitude @p shear (Pa) at angle @p angle (degrees) from e_1.
  void
  check(const std::string                  &title,
        const rupture::Friction::Interface &law,
        const double                        ratio,
        const double                        angle,
        const double                        shear,
        const double                        pressure,
        const double                        slip_path)
  {
    const Tensor<1, 3> n = normal();
    FrictionEllipse<3> ellipse;
    ellipse.direction[0]              = 2. / 3;
    ellipse.direction[1]              = 1. / 3;
    ellipse.direction[2]              = -2. / 3;
    ellipse.a2                        = ratio;
    const Tensor<1, 3> e1             = ellipse.direction;
    const Tensor<1, 3> e2             = cross_product_3d(n, e1);
    const double       phi            = angle * M_PI / 180;
    const Tensor<1, 3> load_direction = std::cos(phi) * e1 + std::sin(phi) * e2;
    const Tensor<1, 3> t0             = -pressure * n + shear * load_direction;
    const Tensor<1, 3> delta          = 1e-5 * load_direction - 1e-7 * n;
    rupture::Friction::State state;
    state.slip_path = slip_path;
    const Tensor<1, 3> old_plastic;
    const Point<3>     x;

    const auto r = anisotropic_return_map<3>(
      delta, n, t0, pn, pt, old_plastic, state, law, x, dt, ellipse);

    // The traction against the ellipse, the slip direction against the
    // ellipse's normal and against the load.
    const double       tn  = r.traction * n;
    const Tensor<1, 3> tau = r.traction - tn * n;
    const double       t1 = tau * e1, t2 = tau * e2;
    const double       ellipse_norm = std::hypot(t1, t2 / ratio);
    const double       strength     = r.friction * std::max(-tn, 0.);
    const Tensor<1, 3> slip         = r.plastic_slip - old_plastic;
    const double       s1 = slip * e1, s2 = slip * e2;
    const double       dual_norm = std::hypot(s1, ratio * s2);
    // The normal of the ellipse at tau: A^-2 tau = (t1, t2 / r^2).
    const double normal_angle = std::atan2(t2 / (ratio * ratio), t1);
    const double slip_angle   = std::atan2(s2, s1);
    const double load_angle =
      std::atan2((r.trial_traction * e2), (r.trial_traction * e1));
    // Finite differences of the traction.
    double max_error = 0, scale = 0;
    for (unsigned int j = 0; j < 3; ++j)
      {
        const double h    = 1e-9;
        Tensor<1, 3> plus = delta, minus = delta;
        plus[j] += h;
        minus[j] -= h;
        const auto rp = anisotropic_return_map<3>(
          plus, n, t0, pn, pt, old_plastic, state, law, x, dt, ellipse);
        const auto rm = anisotropic_return_map<3>(
          minus, n, t0, pn, pt, old_plastic, state, law, x, dt, ellipse);
        for (unsigned int i = 0; i < 3; ++i)
          {
            const double fd = (rp.traction[i] - rm.traction[i]) / (2 * h);
            max_error = std::max(max_error, std::abs(fd - r.tangent[i][j]));
            scale     = std::max(scale, std::abs(r.tangent[i][j]));
          }
      }
    std::printf("r = %g, %-32s %-5s |A^-1 tau| %8.4f MPa, strength "
                "%8.4f MPa, |tau| %8.4f MPa\n",
                ratio,
                title.c_str(),
                name(r.status),
                ellipse_norm / 1e6,
                strength / 1e6,
                tau.norm() / 1e6);
    if (r.status == ContactStatus::slip)
      std::printf(
        "      on the ellipse: %s; slip along its normal (1e-6 "
        "rad): %s; angle slip-load %.2f deg; slip the law sees "
        "= |A slip|: %s; dissipation tau.slip = S |A slip|: %s\n",
        std::abs(ellipse_norm - strength) <= 1e-9 * strength ? "yes" : "no",
        std::abs(std::remainder(slip_angle - normal_angle, 2 * M_PI)) < 1e-6 ?
          "yes" :
          "no",
        std::abs(std::remainder(slip_angle - load_angle, 2 * M_PI)) * 180 /
          M_PI,
        std::abs(r.slip_increment - dual_norm) <= 1e-12 * dual_norm ? "yes" :
                                                                      "no",
        std::abs(tau * slip - strength * dual_norm) <=
            1e-9 * strength * dual_norm ?
          "yes" :
          "no");
    else
      std::printf("      inside the ellipse: %s\n",
                  ellipse_norm <= strength * (1 + 1e-12) ? "yes" : "no");
    std::printf("      tangent matches finite differences to 1e-5: %s\n",
                max_error <= 1e-5 * std::max(scale, 1.) ? "yes" : "no");

    if (ratio == 1)
      {
        const auto iso =
          return_map<3>(delta, n, t0, pn, pt, old_plastic, state, law, x, dt);
        std::printf("      equal to the isotropic return mapping: %s\n",
                    (iso.traction - r.traction).norm() <=
                          1e-10 * iso.traction.norm() &&
                        (iso.tangent - r.tangent).norm() <=
                          1e-8 * iso.tangent.norm() &&
                        (iso.plastic_slip - r.plastic_slip).norm() <=
                          1e-10 * (1e-12 + iso.plastic_slip.norm()) &&
                        iso.status == r.status ?
                      "yes" :
                      "no");
      }
  }

  std::unique_ptr<rupture::Friction::Interface>
  make_rate_law()
  {
    ParameterHandler prm;
    prm.enter_subsection("Fault");
    rupture::Friction::declare_parameters(prm);
    prm.set("Friction law", "rate and state");
    prm.enter_subsection("Rate and state");
    prm.set("Formulation", "regularized");
    prm.set("Evolution law", "aging");
    prm.set("Direct effect", "0.016");
    prm.set("Evolution effect", "0.012");
    prm.set("Characteristic slip distance", "0.02");
    prm.set("Reference friction coefficient", "0.6");
    prm.set("Reference slip rate", "1e-6");
    prm.set("Initial slip rate", "1e-9");
    prm.leave_subsection();
    auto law = rupture::Friction::create(prm);
    prm.leave_subsection();
    return law;
  }

  /// A rate-and-state point with radiation damping @p eta, loaded at
  /// @p angle degrees from e_1, centred or not.
  void
  check_rate(const rupture::Friction::Interface &law,
             const double                        ratio,
             const double                        angle,
             const bool                          centred)
  {
    const double       eta = 5e6, step = 0.01;
    const Tensor<1, 3> n = normal();
    FrictionEllipse<3> ellipse;
    ellipse.direction[0]     = 2. / 3;
    ellipse.direction[1]     = 1. / 3;
    ellipse.direction[2]     = -2. / 3;
    ellipse.a2               = ratio;
    const Tensor<1, 3> e1    = ellipse.direction;
    const Tensor<1, 3> e2    = cross_product_3d(n, e1);
    const double       phi   = angle * M_PI / 180;
    const Tensor<1, 3> load  = std::cos(phi) * e1 + std::sin(phi) * e2;
    const double       p     = 50e6;
    const Tensor<1, 3> t0    = -p * n + 20e6 * load;
    const Tensor<1, 3> delta = 1e-4 * load;
    // The shear at the step's start: along the load (so that r = 1 can be
    // compared with return_map(), which takes its part along the trial).
    const Tensor<1, 3>        old_shear = 25e6 * load;
    const Tensor<1, 3> *const old       = centred ? &old_shear : nullptr;
    rupture::Friction::State  state;
    const Point<3>            x;
    law.initialize_state(x, 0.6, state);
    const Tensor<1, 3> old_plastic;
    const auto         map = [&](const Tensor<1, 3> &d) {
      return anisotropic_return_map<3>(
        d, n, t0, pn, pt, old_plastic, state, law, x, step, ellipse, eta, old);
    };
    const auto         r   = map(delta);
    const Tensor<1, 3> du  = r.plastic_slip - old_plastic;
    const Tensor<1, 3> tau = r.traction - (r.traction * n) * n;
    // The friction's part of the (mean) traction, and the strength.
    const Tensor<1, 3> friction =
      (centred ? 0.5 * (old_shear + tau) : tau) - eta * du / step;
    const double l = std::hypot(du * e1, ratio * (du * e2));
    double       dS, dp;
    const double S  = centred ?
                        law.strength(x, state, 0.5 * l, 0.5 * step, p, dS, dp) :
                        law.strength(x, state, l, step, p, dS, dp);
    const double f1 = friction * e1, f2 = friction * e2;
    const double normal_angle = std::atan2(f2 / (ratio * ratio), f1);
    const double slip_angle   = std::atan2(du * e2, du * e1);
    double       max_error = 0, scale = 0;
    for (unsigned int j = 0; j < 3; ++j)
      {
        const double h    = 1e-10;
        Tensor<1, 3> plus = delta, minus = delta;
        plus[j] += h;
        minus[j] -= h;
        const auto rp = map(plus), rm = map(minus);
        for (unsigned int i = 0; i < 3; ++i)
          {
            const double fd = (rp.traction[i] - rm.traction[i]) / (2 * h);
            max_error = std::max(max_error, std::abs(fd - r.tangent[i][j]));
            scale     = std::max(scale, std::abs(r.tangent[i][j]));
          }
      }
    std::printf("r = %g, rate and state, eta %g, %s, load at %g deg: %s at "
                "%.3e m/s; friction's traction on the ellipse of S(l): %s; "
                "slip along its normal (1e-6 rad): %s; tangent matches "
                "finite differences to 1e-5: %s\n",
                ratio,
                eta,
                centred ? "centred" : "step's end",
                angle,
                name(r.status),
                l / step,
                std::abs(std::hypot(f1, f2 / ratio) - S) <= 1e-9 * S ? "yes" :
                                                                       "no",
                std::abs(std::remainder(slip_angle - normal_angle, 2 * M_PI)) <
                    1e-6 ?
                  "yes" :
                  "no",
                max_error <= 1e-5 * std::max(scale, 1.) ? "yes" : "no");
    if (ratio == 1)
      {
        const auto iso = return_map<3>(
          delta, n, t0, pn, pt, old_plastic, state, law, x, step, eta, old);
        // (Centred, the tangents differ across the load: return_map()
        // takes the old traction's part along the trial, which turns with
        // it, the ellipse's midpoint rule the old traction as it is.)
        const double tangent_difference =
          (iso.tangent - r.tangent).norm() / iso.tangent.norm();
        std::printf(
          "      equal to the isotropic return mapping (traction, "
          "slip, friction and its slope): %s; tangents differ by "
          "%s\n",
          (iso.traction - r.traction).norm() <= 1e-10 * iso.traction.norm() &&
              (iso.plastic_slip - r.plastic_slip).norm() <=
                1e-10 * iso.plastic_slip.norm() &&
              std::abs(iso.friction - r.friction) <= 1e-12 * iso.friction &&
              std::abs(iso.friction_derivative - r.friction_derivative) <=
                1e-8 * std::abs(iso.friction_derivative) &&
              iso.status == r.status ?
            "yes" :
            "no",
          tangent_difference <= 1e-8 ?
            "less than 1e-8" :
            (tangent_difference < 0.01 ? "0.1 to 1 %" : "more"));
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                       law = make_law();
  // 120 MPa compression: strength 81.24 MPa at rest (mu_s = 0.677).
  for (const double ratio : {1., 2.})
    {
      check("along e1, 60 MPa (below S)", *law, ratio, 0, 60e6, 120e6, 0);
      check("along e2, 90 MPa (S < 90 < 2 S)", *law, ratio, 90, 90e6, 120e6, 0);
      check("sliding along e1", *law, ratio, 0, 90e6, 120e6, 0);
      check("sliding along e2", *law, ratio, 90, 180e6, 120e6, 0);
      check("sliding at 30 degrees", *law, ratio, 30, 120e6, 120e6, 0.1);
      check(
        "sliding at 60 degrees, weakened", *law, ratio, 60, 150e6, 120e6, 1.0);
      check("near zero normal stress", *law, ratio, 45, 1e6, 1e3, 0.);
    }

  // Weakening steeper than the tangential penalty (L_d = 0.01 mm: slope
  // 1.8e12 Pa/m against p_t = 4e11), a load along e_1: the traction snaps
  // to the residual strength, the flag says so, and the tangent leaves
  // the slope out as return_map() does (so it is not the finite-difference
  // one there). With r = 1 traction and tangent equal return_map()'s; with
  // r = 2 the traction does (the load is along e_1, where the ellipse
  // meets the circle), the tangent not (its part across e_1 follows the
  // ellipse's curvature).
  const auto steep = make_law("1e-5");
  for (const double ratio : {1., 2.})
    {
      const Tensor<1, 3> n = normal();
      FrictionEllipse<3> ellipse;
      ellipse.direction[0]           = 2. / 3;
      ellipse.direction[1]           = 1. / 3;
      ellipse.direction[2]           = -2. / 3;
      ellipse.a2                     = ratio;
      const Tensor<1, 3>       t0    = -120e6 * n + 90e6 * ellipse.direction;
      const Tensor<1, 3>       delta = 3e-5 * ellipse.direction;
      rupture::Friction::State state;
      const auto               r   = anisotropic_return_map<3>(delta,
                                               n,
                                               t0,
                                               pn,
                                               pt,
                                               Tensor<1, 3>(),
                                               state,
                                               *steep,
                                               Point<3>(),
                                               dt,
                                               ellipse);
      const auto               iso = return_map<3>(
        delta, n, t0, pn, pt, Tensor<1, 3>(), state, *steep, Point<3>(), dt);
      std::printf("r = %g, steep weakening: %s, unstable softening flagged: "
                  "%s, traction equal to the isotropic return mapping's: "
                  "%s, tangent: %s\n",
                  ratio,
                  name(r.status),
                  r.unstable_softening ? "yes" : "no",
                  (iso.traction - r.traction).norm() <=
                      1e-10 * iso.traction.norm() ?
                    "yes" :
                    "no",
                  (iso.tangent - r.tangent).norm() <=
                      1e-8 * iso.tangent.norm() ?
                    "equal" :
                    "different");
    }

  const auto rate_law = make_rate_law();
  for (const double ratio : {1., 2.})
    for (const bool centred : {false, true})
      for (const double angle : {0., 40.})
        check_rate(*rate_law, ratio, angle, centred);
}
