// The fault's stiffness from the finite-element model of the antiplane
// body (BoundaryIntegral::AntiplaneFiniteElements) against the same exact
// solution as antiplane_kernel: the surface-breaking crack of depth a with
// the elliptical slip s(z) = (2 dtau / mu) sqrt(a^2 - z^2) has a uniform
// stress drop dtau above a. The slip at the fault's nodes, times K, must
// give -dtau there; the error (largest over the upper 75 % of the crack)
// falls with the node spacing, at degrees 1 and 2. Also, at each size: K
// is symmetric with the tributary lengths (w_i K_ij = w_j K_ji, the body's
// energy), relieves the stress where it slips (K_ii < 0), and a slip
// uniform down to W makes the traction of a slip -1 below W,
// -mu / (2 pi) (1 / (W - z) + 1 / (W + z)), within what the box of finite
// size allows (the last lines: the box 200, 400 and 800 km wide, degree 2
// at 500 m).
// On two ranks (the columns shared out and exchanged) the output is the
// same.

#include <rupture/boundary_integral/antiplane_finite_elements.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using rupture::BoundaryIntegral::AntiplaneFiniteElements;

namespace
{
  const double mu = 32.04e9, dtau = 3e6, a = 10e3, W = 40e3;

  struct Errors
  {
    double crack = 0, asymmetry = 0, largest_diagonal = -1e300, deep = 0;
  };

  Errors
  measure(const AntiplaneFiniteElements &fault)
  {
    const unsigned int  n = fault.size();
    const auto          K = fault.rows(0, n);
    std::vector<double> slip(n, 0.);
    for (unsigned int j = 0; j < n; ++j)
      {
        const double z = fault.depth(j);
        if (z < a)
          slip[j] = 2 * dtau / mu * std::sqrt(a * a - z * z);
      }
    Errors e;
    for (unsigned int i = 0; i < n; ++i)
      {
        double tau = 0, sum = 0;
        for (unsigned int j = 0; j < n; ++j)
          {
            tau += K[i * n + j] * slip[j];
            sum += K[i * n + j];
            const double wij = fault.length(i) * K[i * n + j],
                         wji = fault.length(j) * K[j * n + i];
            e.asymmetry =
              std::max(e.asymmetry,
                       std::abs(wij - wji) /
                         (fault.length(i) * std::abs(K[i * n + i])));
          }
        e.largest_diagonal = std::max(e.largest_diagonal, K[i * n + i]);
        const double z     = fault.depth(i);
        if (z < 0.75 * a)
          e.crack = std::max(e.crack, std::abs(tau + dtau) / dtau);
        const double exact = -mu / (2 * M_PI) * (1 / (W - z) + 1 / (W + z));
        if (z < 0.5 * W)
          e.deep = std::max(e.deep, std::abs(sum - exact) / std::abs(exact));
      }
    return e;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::freopen("/dev/null", "w", stdout);

  for (const unsigned int degree : {1u, 2u})
    {
      double previous = 0;
      for (const double h : {1000., 500., 250.})
        {
          AntiplaneFiniteElements::Settings s;
          s.fault_depth   = W;
          s.node_spacing  = h;
          s.degree        = degree;
          s.shear_modulus = mu;
          const AntiplaneFiniteElements fault(s, MPI_COMM_WORLD);
          const Errors                  e = measure(fault);
          std::printf(
            "Q%u, nodes %5.1f m apart (%3u): traction change within %.2e "
            "of -dtau above 0.75 a%s; w_i K_ij = w_j K_ji within 1e-9: %s; "
            "K_ii < 0: %s; uniform slip within %.1e of the deep slip's\n",
            degree,
            h,
            fault.size(),
            e.crack,
            previous > 0 ?
              (e.crack < 0.7 * previous ? ", smaller" : ", NOT smaller") :
              "",
            e.asymmetry < 1e-9 ? "yes" : "no",
            e.largest_diagonal < 0 ? "yes" : "no",
            e.deep);
          previous = e.crack;
        }
    }

  // The box's size.
  for (const double L : {200e3, 400e3, 800e3})
    {
      AntiplaneFiniteElements::Settings s;
      s.fault_depth   = W;
      s.node_spacing  = 500;
      s.degree        = 2;
      s.domain_size   = L;
      s.shear_modulus = mu;
      const AntiplaneFiniteElements fault(s, MPI_COMM_WORLD);
      std::printf("box %3.0f km: uniform slip within %.1e of the deep "
                  "slip's above W / 2\n",
                  L / 1e3,
                  measure(fault).deep);
    }
}
