// The fault's stiffness from the finite-element model of a plane-strain
// body with a dipping fault (BoundaryIntegral::PlaneStrainFiniteElements),
// checked against what is exact:
// - a crack deep in the body (centred 40 km down a fault of 60 km that
//   dips at 90, 60 and 30 degrees, half-length a = 3 km) with the
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
// On two ranks (the columns shared out and exchanged) the output is the
// same.

#include <rupture/boundary_integral/plane_strain_finite_elements.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

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

  for (const double dip : {90., 60., 30.})
    {
      double previous = 0;
      for (const double h : {500., 250.})
        {
          const PlaneStrainFiniteElements fault(settings(h, dip, true),
                                                MPI_COMM_WORLD);
          const Errors                    e = measure(fault);
          std::printf(
            "dip %2.0f, nodes %6.1f m apart (%3u): shear traction within "
            "%.1e of -dtau over 0.75 a%s, normal stress within %.1e of 0; "
            "w_i K_ij = w_j K_ji within 1e-9: %s; K_ii < 0: %s\n",
            dip,
            h,
            fault.size(),
            e.shear,
            previous > 0 ?
              (e.shear < 0.7 * previous ? " (smaller)" : " (NOT smaller)") :
              "",
            e.normal,
            e.asymmetry < 1e-9 ? "yes" : "no",
            e.largest_diagonal < 0 ? "yes" : "no");
          if (dip == 90)
            std::printf("  vertical: the largest |N_ij| / |K_ii| is below "
                        "1e-9: %s\n",
                        e.largest_normal < 1e-9 ? "yes" : "no");
          previous = e.shear;
        }
    }

  // Thrust against normal slip of the same fault.
  for (const double dip : {30.})
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
