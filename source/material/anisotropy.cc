#include <rupture/material/anisotropy.h>

#include <deal.II/base/numbers.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace rupture
{
  namespace Material
  {
    namespace
    {
      /// The Voigt index of the tensor indices (i, j), from 0.
      constexpr unsigned int
      voigt_index(const unsigned int i, const unsigned int j)
      {
        return (i == j) ? i : 6 - i - j;
      }

      /// The entry name of C(I, J), I <= J, counted from 0.
      std::string
      entry_name(const unsigned int I, const unsigned int J)
      {
        return "C" + std::to_string(std::min(I, J) + 1) +
               std::to_string(std::max(I, J) + 1);
      }

      /// a_ijkl of the Voigt matrix.
      double
      component(const VoigtMatrix &c,
                const unsigned int i,
                const unsigned int j,
                const unsigned int k,
                const unsigned int l)
      {
        return c[voigt_index(i, j)][voigt_index(k, l)];
      }

      /// The eigenvalues (ascending) of a symmetric 3x3 matrix.
      std::array<double, 3>
      eigenvalues_ascending(const SymmetricTensor<2, 3> &a)
      {
        // Jacobi's method: accurate also for repeated eigenvalues (the
        // shear waves of isotropic and transversely isotropic media),
        // where the closed form loses half the digits.
        const auto pairs =
          eigenvectors(a, SymmetricTensorEigenvectorMethod::jacobi);
        std::array<double, 3> e = {
          {pairs[0].first, pairs[1].first, pairs[2].first}};
        std::sort(e.begin(), e.end());
        return e;
      }

      /// Speeds from the eigenvalues of Gamma / rho, negative ones as 0.
      double
      speed(const double eigenvalue, const double density)
      {
        return std::sqrt(std::max(eigenvalue, 0.) / density);
      }

      /**
       * The smallest and largest of @p f over the unit circle (2-D) or
       * sphere (3-D), parametrised by angles: a grid, then a local search
       * around the best grid point whose step halves down to 1e-7 rad.
       */
      template <int dim>
      std::pair<double, double>
      extremes_over_directions(
        const std::function<double(const Tensor<1, 3> &)> &f)
      {
        const auto direction = [](const double theta, const double phi) {
          Tensor<1, 3> n;
          if (dim == 2)
            {
              n[0] = std::cos(phi);
              n[1] = std::sin(phi);
            }
          else
            {
              n[0] = std::sin(theta) * std::cos(phi);
              n[1] = std::sin(theta) * std::sin(phi);
              n[2] = std::cos(theta);
            }
          return n;
        };
        const double step = (dim == 2 ? 2. : 3.) * numbers::PI / 180;
        const int n_phi = static_cast<int>(std::round(2 * numbers::PI / step));
        const int n_theta     = (dim == 2 ? 1 : n_phi / 2 + 1);
        double    best[2]     = {std::numeric_limits<double>::max(),
                                 -std::numeric_limits<double>::max()};
        double    where[2][2] = {{0, 0}, {0, 0}};
        for (int t = 0; t < n_theta; ++t)
          for (int p = 0; p < n_phi; ++p)
            {
              const double theta = (dim == 2 ? 0. : t * step);
              const double phi   = p * step;
              const double value = f(direction(theta, phi));
              if (value < best[0])
                {
                  best[0]     = value;
                  where[0][0] = theta;
                  where[0][1] = phi;
                }
              if (value > best[1])
                {
                  best[1]     = value;
                  where[1][0] = theta;
                  where[1][1] = phi;
                }
            }
        for (unsigned int which = 0; which < 2; ++which)
          {
            const double sign = (which == 0 ? -1. : 1.);
            for (double h = step; h > 1e-7; h /= 2)
              {
                bool moved = true;
                while (moved)
                  {
                    moved = false;
                    for (int dt = -1; dt <= 1; ++dt)
                      for (int dp = -1; dp <= 1; ++dp)
                        {
                          if ((dt == 0 && dp == 0) || (dim == 2 && dt != 0))
                            continue;
                          const double theta = where[which][0] + dt * h;
                          const double phi   = where[which][1] + dp * h;
                          const double value = f(direction(theta, phi));
                          if (sign * (value - best[which]) > 0)
                            {
                              best[which]     = value;
                              where[which][0] = theta;
                              where[which][1] = phi;
                              moved           = true;
                            }
                        }
                  }
              }
          }
        return {best[0], best[1]};
      }
    } // namespace



    const std::vector<std::string> &
    symmetry_names()
    {
      static const std::vector<std::string> names = {"isotropic",
                                                     "transversely isotropic",
                                                     "orthotropic",
                                                     "general"};
      return names;
    }



    std::vector<std::string>
    constant_names(const Symmetry symmetry)
    {
      switch (symmetry)
        {
          case Symmetry::isotropic:
            return {};
          case Symmetry::transversely_isotropic:
            return {"C11", "C33", "C13", "C44", "C66"};
          case Symmetry::orthotropic:
            return {
              "C11", "C22", "C33", "C12", "C13", "C23", "C44", "C55", "C66"};
            case Symmetry::general: {
              std::vector<std::string> names;
              for (unsigned int I = 0; I < 6; ++I)
                for (unsigned int J = I; J < 6; ++J)
                  names.push_back(entry_name(I, J));
              return names;
            }
        }
      return {};
    }



    VoigtMatrix
    voigt_matrix(const Symmetry                       symmetry,
                 const std::map<std::string, double> &constants)
    {
      VoigtMatrix c{};
      const auto  set =
        [&c](const unsigned int I, const unsigned int J, const double value) {
          c[I][J] = value;
          c[J][I] = value;
        };
      const auto get = [&constants](const std::string &name) {
        const auto it = constants.find(name);
        return (it == constants.end()) ? 0. : it->second;
      };
      if (symmetry == Symmetry::transversely_isotropic)
        {
          const double c11 = get("C11"), c66 = get("C66");
          set(0, 0, c11);
          set(1, 1, c11);
          set(0, 1, c11 - 2 * c66);
          set(2, 2, get("C33"));
          set(0, 2, get("C13"));
          set(1, 2, get("C13"));
          set(3, 3, get("C44"));
          set(4, 4, get("C44"));
          set(5, 5, c66);
        }
      else
        for (unsigned int I = 0; I < 6; ++I)
          for (unsigned int J = I; J < 6; ++J)
            set(I, J, get(entry_name(I, J)));
      return c;
    }



    VoigtMatrix
    isotropic_voigt_matrix(const double lambda, const double mu)
    {
      VoigtMatrix c{};
      for (unsigned int I = 0; I < 3; ++I)
        {
          for (unsigned int J = 0; J < 3; ++J)
            c[I][J] = lambda;
          c[I][I] += 2 * mu;
          c[I + 3][I + 3] = mu;
        }
      return c;
    }



    VoigtMatrix
    rotate(const VoigtMatrix &c, const Tensor<2, 3> &axes)
    {
      // a'_ijkl = R_ip R_jq R_kr R_ls a_pqrs, R_ip the i-th model
      // component of material axis p, summed one index at a time.
      using T4 =
        std::array<std::array<std::array<std::array<double, 3>, 3>, 3>, 3>;
      T4 a{}, b{};
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = 0; l < 3; ++l)
              a[i][j][k][l] = component(c, i, j, k, l);
      for (unsigned int slot = 0; slot < 4; ++slot)
        {
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 3; ++j)
              for (unsigned int k = 0; k < 3; ++k)
                for (unsigned int l = 0; l < 3; ++l)
                  {
                    double             sum    = 0;
                    const unsigned int idx[4] = {i, j, k, l};
                    for (unsigned int p = 0; p < 3; ++p)
                      {
                        unsigned int src[4] = {i, j, k, l};
                        src[slot]           = p;
                        sum += axes[idx[slot]][p] *
                               a[src[0]][src[1]][src[2]][src[3]];
                      }
                    b[i][j][k][l] = sum;
                  }
          a = b;
        }
      VoigtMatrix r{};
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = k; l < 3; ++l)
              r[voigt_index(i, j)][voigt_index(k, l)] = a[i][j][k][l];
      // Symmetric to round-off; make it exactly so.
      for (unsigned int I = 0; I < 6; ++I)
        for (unsigned int J = I + 1; J < 6; ++J)
          r[I][J] = r[J][I] = 0.5 * (r[I][J] + r[J][I]);
      return r;
    }



    std::array<double, 6>
    kelvin_eigenvalues(const VoigtMatrix &c)
    {
      LAPACKFullMatrix<double> k(6, 6);
      for (unsigned int I = 0; I < 6; ++I)
        for (unsigned int J = 0; J < 6; ++J)
          k(I, J) = c[I][J] * (I < 3 ? 1. : std::sqrt(2.)) *
                    (J < 3 ? 1. : std::sqrt(2.));
      k.compute_eigenvalues();
      std::array<double, 6> e;
      for (unsigned int I = 0; I < 6; ++I)
        e[I] = k.eigenvalue(I).real();
      std::sort(e.begin(), e.end());
      return e;
    }



    namespace
    {
      /// The Kelvin form's weight of Voigt index @p I (sqrt 2 for shears).
      double
      kelvin_weight(const unsigned int I)
      {
        return I < 3 ? 1. : std::sqrt(2.);
      }



      /// The largest eigenvalue of the symmetric n x n matrix @p a (cyclic
      /// Jacobi rotations; @p a is overwritten).
      double
      largest_symmetric_eigenvalue(VoigtMatrix &a, const unsigned int n)
      {
        for (unsigned int sweep = 0; sweep < 60; ++sweep)
          {
            double off = 0, diagonal = 0;
            for (unsigned int p = 0; p < n; ++p)
              {
                diagonal += a[p][p] * a[p][p];
                for (unsigned int q = p + 1; q < n; ++q)
                  off += a[p][q] * a[p][q];
              }
            if (off <= 1e-32 * diagonal)
              break;
            for (unsigned int p = 0; p < n; ++p)
              for (unsigned int q = p + 1; q < n; ++q)
                {
                  if (a[p][q] == 0)
                    continue;
                  const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
                  const double t =
                    (theta >= 0 ? 1. : -1.) /
                    (std::abs(theta) + std::sqrt(theta * theta + 1));
                  const double cs = 1 / std::sqrt(t * t + 1), sn = t * cs;
                  for (unsigned int k = 0; k < n; ++k)
                    {
                      const double akp = a[k][p], akq = a[k][q];
                      a[k][p] = cs * akp - sn * akq;
                      a[k][q] = sn * akp + cs * akq;
                    }
                  for (unsigned int k = 0; k < n; ++k)
                    {
                      const double apk = a[p][k], aqk = a[q][k];
                      a[p][k] = cs * apk - sn * aqk;
                      a[q][k] = sn * apk + cs * aqk;
                    }
                }
          }
        double largest = a[0][0];
        for (unsigned int p = 1; p < n; ++p)
          largest = std::max(largest, a[p][p]);
        return largest;
      }
    } // namespace



    EnergyRatio::EnergyRatio(const VoigtMatrix &reference,
                             const unsigned int dim)
    {
      if (dim == 2)
        {
          n    = 3;
          rows = {{0, 1, 5, 0, 0, 0}};
        }
      // Cholesky factor L of the reference's Kelvin form, then its inverse.
      VoigtMatrix l{};
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b <= a; ++b)
          {
            double sum = reference[rows[a]][rows[b]] * kelvin_weight(rows[a]) *
                         kelvin_weight(rows[b]);
            for (unsigned int k = 0; k < b; ++k)
              sum -= l[a][k] * l[b][k];
            if (a == b)
              {
                Assert(sum > 0,
                       ExcMessage("The reference tensor is not positive "
                                  "definite."));
                l[a][a] = std::sqrt(sum);
              }
            else
              l[a][b] = sum / l[b][b];
          }
      for (unsigned int col = 0; col < n; ++col)
        for (unsigned int a = col; a < n; ++a)
          {
            double sum = (a == col ? 1. : 0.);
            for (unsigned int k = col; k < a; ++k)
              sum -= l[a][k] * inverse_factor[k][col];
            inverse_factor[a][col] = sum / l[a][a];
          }
    }



    VoigtMatrix
    EnergyRatio::transformed(const VoigtMatrix &c) const
    {
      // M = L^-1 K L^-T, with L^-1 lower triangular.
      VoigtMatrix k{}, t{}, m{};
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b < n; ++b)
          k[a][b] = c[rows[a]][rows[b]] * kelvin_weight(rows[a]) *
                    kelvin_weight(rows[b]);
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b < n; ++b)
          {
            double sum = 0;
            for (unsigned int q = 0; q <= a; ++q)
              sum += inverse_factor[a][q] * k[q][b];
            t[a][b] = sum;
          }
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b <= a; ++b)
          {
            double sum = 0;
            for (unsigned int q = 0; q <= b; ++q)
              sum += t[a][q] * inverse_factor[b][q];
            m[a][b] = m[b][a] = sum;
          }
      return m;
    }



    double
    EnergyRatio::operator()(const VoigtMatrix &c) const
    {
      VoigtMatrix m = transformed(c);
      return largest_symmetric_eigenvalue(m, n);
    }



    bool
    EnergyRatio::certainly_below(const VoigtMatrix &c, const double t) const
    {
      // Cholesky of A = t I - M, in place; a pivot that is not positive
      // (or not a number) leaves the question open.
      VoigtMatrix a = transformed(c);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          a[i][j] = (i == j ? t : 0.) - a[i][j];
      for (unsigned int j = 0; j < n; ++j)
        {
          double pivot = a[j][j];
          for (unsigned int k = 0; k < j; ++k)
            pivot -= a[j][k] * a[j][k];
          if (!(pivot > 0))
            return false;
          a[j][j] = std::sqrt(pivot);
          for (unsigned int i = j + 1; i < n; ++i)
            {
              double sum = a[i][j];
              for (unsigned int k = 0; k < j; ++k)
                sum -= a[i][k] * a[j][k];
              a[i][j] = sum / a[j][j];
            }
        }
      return true;
    }



    LargestRatio::LargestRatio(const EnergyRatio &ratio)
      : ratio(&ratio)
    {}



    double
    LargestRatio::add(const VoigtMatrix &c, const double w)
    {
      if (!(has_last && c == last))
        {
          if (largest_value > 0 &&
              ratio->certainly_below(c, largest_value / w * (1 - 1e-10)))
            return -1;
          last       = c;
          last_ratio = (*ratio)(c);
          ++solves;
          has_last = true;
        }
      largest_value = std::max(largest_value, last_ratio * w);
      return last_ratio;
    }



    SymmetricTensor<2, 3>
    christoffel_matrix(const VoigtMatrix &c, const Tensor<1, 3> &n)
    {
      SymmetricTensor<2, 3> g;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int k = i; k < 3; ++k)
          {
            double sum = 0;
            for (unsigned int j = 0; j < 3; ++j)
              for (unsigned int l = 0; l < 3; ++l)
                sum += component(c, i, j, k, l) * n[j] * n[l];
            g[i][k] = sum;
          }
      return g;
    }



    std::array<double, 3>
    phase_speeds(const VoigtMatrix  &c,
                 const double        density,
                 const Tensor<1, 3> &n)
    {
      const auto e = eigenvalues_ascending(christoffel_matrix(c, n));
      return {
        {speed(e[2], density), speed(e[1], density), speed(e[0], density)}};
    }



    std::array<double, 2>
    in_plane_phase_speeds(const VoigtMatrix  &c,
                          const double        density,
                          const Tensor<1, 3> &n)
    {
      const SymmetricTensor<2, 3> g    = christoffel_matrix(c, n);
      const double                mean = 0.5 * (g[0][0] + g[1][1]);
      const double half = std::hypot(0.5 * (g[0][0] - g[1][1]), g[0][1]);
      return {{speed(mean + half, density), speed(mean - half, density)}};
    }



    bool
    model_plane_is_mirror_plane(const VoigtMatrix &c)
    {
      double largest = 0;
      for (const auto &row : c)
        for (const double x : row)
          largest = std::max(largest, std::abs(x));
      for (const unsigned int I : {0u, 1u, 5u})
        for (const unsigned int J : {3u, 4u})
          if (std::abs(c[I][J]) > 1e-9 * largest)
            return false;
      return true;
    }



    template <int dim>
    SymmetricTensor<4, dim>
    stiffness_tensor(const VoigtMatrix &c)
    {
      SymmetricTensor<4, dim> a;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = k; l < dim; ++l)
              a[i][j][k][l] = component(c, i, j, k, l);
      return a;
    }



    template <int dim>
    SpeedRange
    speed_range(const VoigtMatrix &c, const double density)
    {
      // In 2-D only the in-plane block of Gamma (polarisations in the
      // model plane) carries waves.
      const auto slow =
        extremes_over_directions<dim>([&](const Tensor<1, 3> &n) {
          return dim == 3 ? phase_speeds(c, density, n)[2] :
                            in_plane_phase_speeds(c, density, n)[1];
        });
      const auto fast =
        extremes_over_directions<dim>([&](const Tensor<1, 3> &n) {
          return dim == 3 ? phase_speeds(c, density, n)[0] :
                            in_plane_phase_speeds(c, density, n)[0];
        });
      return {slow.first, fast.second};
    }



    template SymmetricTensor<4, 2>
    stiffness_tensor<2>(const VoigtMatrix &);
    template SymmetricTensor<4, 3>
    stiffness_tensor<3>(const VoigtMatrix &);
    template SpeedRange
    speed_range<2>(const VoigtMatrix &, const double);
    template SpeedRange
    speed_range<3>(const VoigtMatrix &, const double);
  } // namespace Material
} // namespace rupture
