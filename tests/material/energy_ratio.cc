// The energy ratio of a stiffness tensor to a reference (Material::
// EnergyRatio: the largest eigenvalue of K_ref^-1 K of their Kelvin forms,
// which bounds the stable step and the fastest wave speed where anisotropic
// constants are functions of position), its certificate certainly_below()
// and LargestRatio, which solves the eigenvalue problem only where a tensor
// may raise the largest so far. Against LAPACK's generalized symmetric
// eigenvalues for random positive definite pairs in 3-D and 2-D (the
// in-plane rows 1, 2, 6); the certificate on either side of the ratio; the
// largest over a smooth path of tensors equal, to the last bit, to the
// maximum of the exact values, with the number of eigenvalue problems it
// solved.

#include <rupture/material/anisotropy.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

using namespace dealii;
using namespace rupture::Material;

namespace
{
  // A deterministic generator of numbers in [-1, 1).
  double
  next(std::uint64_t &state)
  {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 4503599627370496. - 1;
  }

  double
  weight(const unsigned int I)
  {
    return I < 3 ? 1. : std::sqrt(2.);
  }

  // A positive definite tensor: Kelvin form A A^T + 0.05 I, times 1e10.
  VoigtMatrix
  random_tensor(std::uint64_t &state)
  {
    double a[6][6];
    for (auto &row : a)
      for (double &x : row)
        x = next(state);
    VoigtMatrix c{};
    for (unsigned int I = 0; I < 6; ++I)
      for (unsigned int J = 0; J < 6; ++J)
        {
          double k = (I == J ? 0.05 : 0.);
          for (unsigned int m = 0; m < 6; ++m)
            k += a[I][m] * a[J][m];
          c[I][J] = 1e10 * k / (weight(I) * weight(J));
        }
    return c;
  }

  // The largest generalized eigenvalue of the Kelvin forms by LAPACK.
  double
  lapack_ratio(const VoigtMatrix &c,
               const VoigtMatrix &reference,
               const unsigned int dim)
  {
    const std::vector<unsigned int> rows =
      (dim == 2 ? std::vector<unsigned int>{0, 1, 5} :
                  std::vector<unsigned int>{0, 1, 2, 3, 4, 5});
    const unsigned int       n = rows.size();
    LAPACKFullMatrix<double> a(n, n), b(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          const double w = weight(rows[i]) * weight(rows[j]);
          a(i, j)        = c[rows[i]][rows[j]] * w;
          b(i, j)        = reference[rows[i]][rows[j]] * w;
        }
    std::vector<Vector<double>> vectors(n, Vector<double>(n));
    a.compute_generalized_eigenvalues_symmetric(b, vectors);
    double largest = 0;
    for (unsigned int i = 0; i < n; ++i)
      largest = std::max(largest, a.eigenvalue(i).real());
    return largest;
  }
} // namespace



int
main()
{
  std::uint64_t state = 2026;
  for (const unsigned int dim : {2u, 3u})
    {
      double       worst = 0;
      unsigned int above = 0, below = 0;
      for (unsigned int k = 0; k < 200; ++k)
        {
          const VoigtMatrix reference = random_tensor(state);
          const VoigtMatrix c         = random_tensor(state);
          const EnergyRatio ratio(reference, dim);
          const double      r = ratio(c);
          worst =
            std::max(worst, std::abs(r / lapack_ratio(c, reference, dim) - 1));
          above += ratio.certainly_below(c, r * (1 + 1e-9));
          below += ratio.certainly_below(c, r * (1 - 1e-9));
        }
      std::printf("%u-D, 200 random pairs: ratio against LAPACK within "
                  "1e-11: %s; certainly below ratio (1 + 1e-9): %u of 200, "
                  "below ratio (1 - 1e-9): %u of 200\n",
                  dim,
                  worst < 1e-11 ? "yes" : "no",
                  above,
                  below);

      // A smooth path of tensors c(s) = c0 + (0.4 sin(s) + 0.1 s / 10) dc,
      // weighted by 1 + 0.2 cos(3 s), with repeats (each tensor twice).
      const VoigtMatrix reference = random_tensor(state);
      const VoigtMatrix c0 = random_tensor(state), dc = random_tensor(state);
      const EnergyRatio ratio(reference, dim);
      LargestRatio      largest(ratio);
      double            exact    = 0;
      unsigned int      computed = 0, passed = 0;
      for (unsigned int k = 0; k < 1000; ++k)
        {
          const double s = 0.01 * (k / 2);
          VoigtMatrix  c = c0;
          for (unsigned int I = 0; I < 6; ++I)
            for (unsigned int J = 0; J < 6; ++J)
              c[I][J] += (0.4 * std::sin(s) + 0.01 * s) * dc[I][J];
          const double w = 1 + 0.2 * std::cos(3 * s + 0.5 * (k % 2));
          exact          = std::max(exact, ratio(c) * w);
          (largest.add(c, w) < 0 ? passed : computed) += 1;
        }
      std::printf("  largest over 1000 tensors of a path: equal to the "
                  "maximum of the exact values to the last bit: %s (%.6f); "
                  "%u passed over by the certificate, %u taken, %u "
                  "eigenvalue problems solved\n",
                  largest.largest() == exact ? "yes" : "no",
                  exact,
                  passed,
                  computed,
                  largest.solved());
    }
}
