// The fault's stiffness from the finite-element model of a plane-strain
// body with a dipping fault (BoundaryIntegral::PlaneStrainFiniteElements),
// checked against what is exact:
// - a crack deep in the body (centred 40 km down a fault of 60 km that
//   dips at 90 and 30 degrees, half-length a = 3 km) with the
//   elliptical slip of a uniform stress drop in an infinite body (mode II,
//   s = 2 (1 - nu) dtau / mu sqrt(a^2 - r^2)) must change the shear
//   traction by -dtau and the normal stress by nothing (the crack's plane
//   is one of antisymmetry), up to the free surface's and the box's
//   influence (about (a / 2 depth)^2, below 1e-2) and the mesh's error,
//   which falls with the node spacing (500, 250 m, degree 2);
// - K is symmetric with the tributary lengths (w_i K_ij = w_j K_ji, the
//   body's energy) and relieves the shear traction where it slips
//   (K_ii < 0);
// - on a vertical fault the slip changes no normal stress (a mirror
//   symmetry of the body), and thrust and normal slip of the same fault
//   give the same K and opposite normal stiffnesses.
// - the surface's displacement from a uniform thrust slip s of the fault
//   from the surface down to W = 10 km (the blocks not moving: a plate
//   value of 0) against the closed form of the half-space (independent of
//   Poisson's ratio; Freund and Barnett 1976): with the depth d = W
//   sin(dip) and zeta = (x - d cot(dip)) / d,
//     u_x = s / pi [cos(dip) (atan(zeta) - pi / 2 sgn(x))
//                   + (sin(dip) - zeta cos(dip)) / (1 + zeta^2)],
//     u_y = -s / pi [sin(dip) (atan(zeta) - pi / 2 sgn(x))
//                    + (cos(dip) + zeta sin(dip)) / (1 + zeta^2)],
//   at x = -8 ... 16 km (the trace x = 0 on the footwall's side) relative
//   to x = -16 km (the box, reaching 400 km, holds its far sides, which
//   moves the surface near the fault by about s W / (pi L), 1e-2 s, alike):
//   the error, relative to s, falls with the node spacing (500, 250 m);
//   and the blocks' rigid motion alone (a plate value of 1 m, no slip
//   relative to it) moves the surface by +-d / 2.

#include <rupture/boundary_integral/plane_strain_finite_elements.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

using rupture::BoundaryIntegral::PlaneStrainFiniteElements;

namespace
{
  const double mu = 32.04e9, lambda = 2670 * 6000. * 6000 - 2 * mu,
               nu = lambda / (2 * (lambda + mu)), dtau = 3e6, a = 3e3,
               centre = 40e3, W = 60e3;

  struct Errors
  {
    double shear = 0, normal = 0, asymmetry = 0, largest_diagonal = -1e300,
           largest_normal = 0;
  };

  Errors
  measure(const PlaneStrainFiniteElements &fault)
  {
    const unsigned int  n = fault.size();
    const auto          K = fault.rows(0, n), N = fault.normal_rows(0, n);
    std::vector<double> slip(n, 0.);
    for (unsigned int j = 0; j < n; ++j)
      {
        const double r = fault.depth(j) - centre;
        if (std::abs(r) < a)
          slip[j] = 2 * (1 - nu) * dtau / mu * std::sqrt(a * a - r * r);
      }
    Errors e;
    for (unsigned int i = 0; i < n; ++i)
      {
        double tau = 0, sigma = 0;
        for (unsigned int j = 0; j < n; ++j)
          {
            tau += K[i * n + j] * slip[j];
            sigma += N[i * n + j] * slip[j];
            const double wij = fault.length(i) * K[i * n + j],
                         wji = fault.length(j) * K[j * n + i];
            e.asymmetry =
              std::max(e.asymmetry,
                       std::abs(wij - wji) /
                         (fault.length(i) * std::abs(K[i * n + i])));
            e.largest_normal =
              std::max(e.largest_normal,
                       std::abs(N[i * n + j]) / std::abs(K[i * n + i]));
          }
        e.largest_diagonal = std::max(e.largest_diagonal, K[i * n + i]);
        if (std::abs(fault.depth(i) - centre) < 0.75 * a)
          {
            e.shear  = std::max(e.shear, std::abs(tau + dtau) / dtau);
            e.normal = std::max(e.normal, std::abs(sigma) / dtau);
          }
      }
    return e;
  }

  PlaneStrainFiniteElements::Settings
  settings(const double h, const double dip, const bool thrust)
  {
    PlaneStrainFiniteElements::Settings s;
    s.fault_extent  = W;
    s.node_spacing  = h;
    s.degree        = 2;
    s.domain_size   = 2 * W;
    s.growth        = 1.2;
    s.dip           = dip;
    s.thrust        = thrust;
    s.shear_modulus = mu;
    s.lambda        = lambda;
    return s;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::freopen("/dev/null", "w", stdout);

  for (const double dip : {90., 30.})
    {
      double previous = 0;
      for (const double h : {500., 250.})
        {
          const PlaneStrainFiniteElements fault(settings(h, dip, true),
                                                MPI_COMM_WORLD);
          const Errors                    e = measure(fault);
          // (A normal stress at round-off, on the vertical fault, as a
          // bound: its digits differ between machines.)
          char normal[32];
          if (e.normal < 1e-10)
            std::snprintf(normal, sizeof(normal), "1e-10");
          else
            std::snprintf(normal, sizeof(normal), "%.1e", e.normal);
          std::printf(
            "dip %2.0f, nodes %6.1f m apart (%3u): shear traction within "
            "%.1e of -dtau over 0.75 a%s, normal stress within %s of 0; "
            "w_i K_ij = w_j K_ji within 1e-9: %s; K_ii < 0: %s\n",
            dip,
            h,
            fault.size(),
            e.shear,
            previous > 0 ?
              (e.shear < 0.7 * previous ? " (smaller)" : " (NOT smaller)") :
              "",
            normal,
            e.asymmetry < 1e-9 ? "yes" : "no",
            e.largest_diagonal < 0 ? "yes" : "no");
          if (dip == 90)
            std::printf("  vertical: the largest |N_ij| / |K_ii| is below "
                        "1e-9: %s\n",
                        e.largest_normal < 1e-9 ? "yes" : "no");
          previous = e.shear;
        }
    }

  // The surface's displacement against the half-space's closed form.
  const std::vector<double> surface = {
    -16e3, -8e3, -4e3, -2e3, 0, 2e3, 4e3, 8e3, 16e3};
  for (const double dip : {60., 30.})
    {
      double previous = 0;
      for (const double h : {500., 250.})
        {
          PlaneStrainFiniteElements::Settings s = settings(h, dip, true);
          s.fault_extent                        = 10e3;
          s.domain_size                         = 400e3;
          s.growth                              = 1.3;
          s.surface_points                      = surface;
          const PlaneStrainFiniteElements fault(s, MPI_COMM_WORLD);
          const std::vector<double>       slip(fault.size(), 1.);
          const double delta = dip * M_PI / 180, d = 10e3 * std::sin(delta);
          double       error = 0, rigid = 0;
          std::array<double, 2> offset = {{0, 0}};
          for (unsigned int k = 0; k < surface.size(); ++k)
            {
              const double x = surface[k], zeta = (x - d / std::tan(delta)) / d;
              const double sign  = x > 0 ? 1 : -1;
              const double angle = std::atan(zeta) - M_PI / 2 * sign;
              const double exact0 =
                             (std::cos(delta) * angle +
                              (std::sin(delta) - zeta * std::cos(delta)) /
                                (1 + zeta * zeta)) /
                             M_PI,
                           exact1 =
                             -(std::sin(delta) * angle +
                               (std::cos(delta) + zeta * std::sin(delta)) /
                                 (1 + zeta * zeta)) /
                             M_PI;
              const auto u = fault.surface_motion(k, slip, 0.);
              if (k == 0)
                offset = {{u[0] - exact0, u[1] - exact1}};
              error = std::max(error,
                               std::max(std::abs(u[0] - exact0 - offset[0]),
                                        std::abs(u[1] - exact1 - offset[1])));
              const auto r =
                fault.surface_motion(k,
                                     std::vector<double>(fault.size(), 0.),
                                     1.);
              rigid =
                std::max(rigid,
                         std::max(std::abs(r[0] + sign * 0.5 * std::cos(delta)),
                                  std::abs(r[1] -
                                           sign * 0.5 * std::sin(delta))));
            }
          std::printf(
            "dip %2.0f, nodes %5.1f m apart: the surface's "
            "displacement relative to x = -16 km within %.1e s of the "
            "half-space's%s; "
            "the rigid motion +-d / 2 within 1e-12: %s\n",
            dip,
            h,
            error,
            previous > 0 ?
              (error < 0.7 * previous ? " (smaller)" : " (NOT smaller)") :
              "",
            rigid < 1e-12 ? "yes" : "no");
          previous = error;
        }
    }

  // Thrust against normal slip of the same fault.
  for (const double dip : {60.})
    {
      const PlaneStrainFiniteElements thrust(settings(1000, dip, true),
                                             MPI_COMM_WORLD),
        normal(settings(1000, dip, false), MPI_COMM_WORLD);
      const unsigned int n  = thrust.size();
      const auto         Kt = thrust.rows(0, n), Kn = normal.rows(0, n),
                 Nt = thrust.normal_rows(0, n), Nn = normal.normal_rows(0, n);
      double shear = 0, opposite = 0, scale = 0, normal_scale = 0;
      for (std::size_t k = 0; k < Kt.size(); ++k)
        {
          shear        = std::max(shear, std::abs(Kt[k] - Kn[k]));
          opposite     = std::max(opposite, std::abs(Nt[k] + Nn[k]));
          scale        = std::max(scale, std::abs(Kt[k]));
          normal_scale = std::max(normal_scale, std::abs(Nt[k]));
        }
      std::printf("dip %2.0f: thrust and normal slip: the same K within "
                  "1e-12: %s; opposite normal stiffnesses within 1e-12: %s; "
                  "the normal stiffness is %s\n",
                  dip,
                  shear < 1e-12 * scale ? "yes" : "no",
                  opposite < 1e-12 * scale ? "yes" : "no",
                  normal_scale > 1e-3 * scale ? "not small" : "small");
    }
}
