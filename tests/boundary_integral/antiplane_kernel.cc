// The boundary-integral method's stiffness (BoundaryIntegral::
// AntiplaneHalfSpace) against an exact solution: a surface-breaking crack
// of depth a in the antiplane half-space with the elliptical slip
//   s(z) = (2 dtau / mu) sqrt(a^2 - z^2)
// is, with its image in the free surface, a whole-space crack of
// half-length a, whose stress drop is uniform: the traction changes by
// -dtau at every depth above a. The slip at the element centres, times K,
// must give -dtau; the error (largest over the upper 80 % of the crack,
// away from the tip's square-root singularity) falls with h. Also: below
// the crack the traction rises (the tip's stress concentration), and a
// slip uniform down to W makes exactly the traction of a slip -1 below W.

#include <rupture/boundary_integral/antiplane_half_space.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

int
main()
{
  const double mu = 32.04e9, dtau = 3e6, a = 10e3, W = 40e3;
  double       previous = 0;
  for (const double h : {500., 250., 125., 62.5})
    {
      const rupture::BoundaryIntegral::AntiplaneHalfSpace fault(W, h, mu);
      const unsigned int                                  n = fault.size();
      std::vector<double>                                 slip(n, 0.);
      for (unsigned int j = 0; j < n; ++j)
        {
          const double z = fault.centre(j);
          if (z < a)
            slip[j] = 2 * dtau / mu * std::sqrt(a * a - z * z);
        }
      double error = 0, below = 0;
      for (unsigned int i = 0; i < n; ++i)
        {
          double tau = 0;
          for (unsigned int j = 0; j < n; ++j)
            tau += fault.stiffness(i, j) * slip[j];
          const double z = fault.centre(i);
          if (z < 0.8 * a)
            error = std::max(error, std::abs(tau + dtau) / dtau);
          if (z > a && z < a + 2000)
            below = std::max(below, tau);
        }
      std::printf("h = %5.1f m (%3u elements): traction change within "
                  "%.2e of -dtau above 0.8 a%s; below the tip it rises "
                  "(%s)\n",
                  h,
                  n,
                  error,
                  previous > 0 ?
                    (error < 0.7 * previous ? ", smaller" : ", NOT smaller") :
                    "",
                  below > 0 ? "yes" : "no");
      previous = error;
    }

  // A unit slip on the whole of [0, W] makes the traction of a slip -1 on
  // [W, infinity): -mu / (2 pi) (1 / (W - z) + 1 / (W + z)).
  const rupture::BoundaryIntegral::AntiplaneHalfSpace fault(W, 1000., mu);
  double                                              worst = 0;
  for (unsigned int i = 0; i < fault.size(); ++i)
    {
      double sum = 0;
      for (unsigned int j = 0; j < fault.size(); ++j)
        sum += fault.stiffness(i, j);
      const double z     = fault.centre(i);
      const double exact = -mu / (2 * M_PI) * (1 / (W - z) + 1 / (W + z));
      worst = std::max(worst, std::abs(sum - exact) / std::abs(exact));
    }
  std::printf("uniform slip down to W: traction as the deep slip's within "
              "1e-9: %s\n",
              worst < 1e-9 ? "yes" : "no");
}
