// The 2-D antiplane (mode III) problem in a 3-D slab one cell thick
// (inputs/antiplane_slab.prm): a vertical strike-slip fault in a
// half-space slips by a forced 1 mm between the depths 2 and 6 km. The
// slab's rollers leave only the out-of-plane displacement u_y, whose exact
// solution (two screw dislocations and their images in the free surface)
// holds the sides and the bottom. Checked at 16 and 32 cells across (1000
// and 500 m): the in-plane displacements are zero, the surface profile is
// antisymmetric, and the surface u_y at five nodes converges to
// (s/pi) [atan(x/D) - atan(x/D2)] at second order in h (the nodal slip
// tapers over one cell, centred on the ends of the slipping band). This is
// how rupture runs the SEAS benchmarks' antiplane problems (BP1, BP2) until
// it has a 2-D antiplane model of its own (doc/design-cycles-plan.md).
//
// The same slab in orthotropic rock (issue 39: the antiplane model takes
// the material's antiplane shear moduli): with u_y(x, z) alone the only
// stresses that work are sigma_xy = C66 u_y,x and sigma_yz = C44 u_y,z, so
// x stretched by k = sqrt(C44 / C66) turns the body into the isotropic
// one, and the exact field is the isotropic one at (k x, z). C55 (the
// in-plane shear) is eight times C44 and must not enter. At degree 2 the
// slab's middle nodes are free in x and z: the model plane being a mirror
// plane of the material, they stay at rest.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
  // The exact field on the sides and the bottom, for x stretched by k (the
  // prm's expression with x replaced by k x).
  std::string
  exact_velocity(const double k)
  {
    const std::string x = "(" + std::to_string(k) + "*x)";
    std::string       g;
    for (const char *d : {"2000", "6000"})
      {
        const std::string D(d);
        g += std::string(g.empty() ? "" : " - ") + "(atan(" + x + "/(" + D +
             "+z+1e-9)) + (((" + D + "+z+1e-9) < 0) ? pi*((" + x +
             " > 0) ? 1 : -1) : 0) + atan(" + x + "/(" + D + "-z)))";
      }
    const std::string u = "0; 1e-3/(2*pi)*(" + g + "); 0";
    return "west: " + u + ", east: " + u + ", bottom: " + u;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const std::string prm =
    std::string(SOURCE_DIR) + "/inputs/antiplane_slab.prm";
  const double              s = 1e-3, D = 2000, D2 = 6000;
  const std::vector<double> xs = {1000, 2000, 3000, 4000, -2000};
  const char *names[]          = {"x1000", "x2000", "x3000", "x4000", "xm2000"};

  // mu of the isotropic run; the orthotropic rock's antiplane moduli
  // C66 = mu and C44 = mu / 4 (k = 1/2), C55 = 2 mu.
  const double      mu = 2670. * 3464. * 3464.;
  const std::string orthotropic =
    "C11 = " + std::to_string(3 * mu) + ", C22 = " + std::to_string(2.5 * mu) +
    ", C33 = " + std::to_string(3.5 * mu) + ", C12 = " + std::to_string(mu) +
    ", C13 = " + std::to_string(0.8 * mu) +
    ", C23 = " + std::to_string(1.2 * mu) +
    ", C44 = " + std::to_string(mu / 4) + ", C55 = " + std::to_string(2 * mu) +
    ", C66 = " + std::to_string(mu);

  struct Case
  {
    std::string               title;
    double                    k;
    std::vector<unsigned int> cells;
    unsigned int              degree;
  };
  const std::vector<Case> cases = {
    {"isotropic", 1, {16, 32}, 1},
    {"orthotropic, C66 = mu, C44 = mu/4, C55 = 2 mu", 0.5, {16, 32}, 1},
    {"the same at degree 2", 0.5, {16}, 2}};

  for (const Case &c : cases)
    {
      if (root && c.k != 1)
        std::printf("%s (u_y(x, z) = the isotropic field at (%g x, z)):\n",
                    c.title.c_str(),
                    c.k);
      std::vector<double> worst;
      for (const unsigned int n : c.cells)
        {
          std::vector<std::string> args = {prm,
                                           "--set",
                                           "Scene/Box/Number of cells=" +
                                             std::to_string(n) + ", 1, " +
                                             std::to_string(n)};
          if (c.k != 1)
            args.insert(
              args.end(),
              {"--set",
               "Material/Symmetry=orthotropic",
               "--set",
               "Material/Stiffness=" + orthotropic,
               "--set",
               "Boundary conditions/Prescribed velocity=" + exact_velocity(c.k),
               "--set",
               "Discretization/Polynomial degree=" + std::to_string(c.degree)});
          const int code = tests::run(args);
          if (!root)
            continue;
          double              in_plane = 0, largest = 0;
          std::vector<double> uy;
          for (unsigned int k = 0; k < xs.size(); ++k)
            {
              const auto rows = tests::read_statistics(
                std::string("output-antiplane-slab/") + names[k] + ".dat");
              const auto &last = rows.back();
              // t, then displacement and velocity per component.
              in_plane =
                std::max({in_plane, std::abs(last[1]), std::abs(last[5])});
              uy.push_back(last[3]);
              largest = std::max(largest, std::abs(last[3]));
            }
          double error = 0;
          std::printf("%u cells across (h = %g m), exit code %d:\n",
                      n,
                      16000. / n,
                      code);
          for (unsigned int k = 0; k < xs.size(); ++k)
            {
              const double exact =
                s / M_PI *
                (std::atan(c.k * xs[k] / D) - std::atan(c.k * xs[k] / D2));
              const double e = std::abs(uy[k] - exact) / std::abs(exact);
              error          = std::max(error, e);
              std::printf(
                "  x = %6.0f m: u_y %.4e m, exact %.4e m, error %.1f %%\n",
                xs[k],
                uy[k],
                exact,
                100 * e);
            }
          worst.push_back(error);
          std::printf("  in-plane displacement zero: %s; antisymmetric (x = "
                      "+-2000 m): %s\n",
                      in_plane <= 1e-12 * largest ? "yes" : "no",
                      std::abs(uy[1] + uy[4]) <= 1e-9 * largest ? "yes" : "no");
        }
      if (root && worst.size() == 2)
        std::printf("largest error halving h: %.1f %% -> %.1f %%, ratio %s "
                    "(second order: about 4)\n",
                    100 * worst[0],
                    100 * worst[1],
                    (worst[0] / worst[1] > 3 && worst[0] / worst[1] < 5) ?
                      "between 3 and 5" :
                      "outside 3 to 5");
    }
}
