// Absorbing boundaries in anisotropic rock whose axes are oblique to the
// boundary: a plane quasi-P pulse travels down to an absorbing bottom in
// transversely isotropic rock with its axis 35 degrees from the vertical,
// in the model plane. Its polarization (from the Christoffel matrix of the
// vertical, computed here) is 14 degrees off the vertical, so the
// dashpots' impedance sqrt(rho Gamma(n)) is a full matrix. A receiver 600
// m above the bottom records the incident pulse and whatever comes back
// (the box is wide enough that nothing from its free sides reaches it in
// time). An impedance that is not the rock's converts part of the pulse
// into a reflected quasi-S wave, polarized across the incident one: with
// the matrix's diagonal alone (rupture before 2026-12-07) 6.1 % of the
// incident peak velocity, in both schemes; with the full matrix none. (The
// reflection along the polarization is the discretization's, as in
// isotropic rock: printed, not checked.) Explicit central differences
// (each boundary node solves its block), implicit Newmark with the
// assembled matrix and matrix-free (the same series), in 2-D, and the
// explicit scheme in a 3-D slab one cell thick (rollers on its faces, the
// model plane turned to x-z), which must give the 2-D series.

#include <rupture/material/elastic_material.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  const std::string stiffness =
    "C11 = 6e10, C33 = 3e10, C13 = 1.2e10, C44 = 1.0e10, C66 = 2.0e10";
  constexpr double density = 2500, angle = 35 * M_PI / 180;

  // The pulse 0.01 g(s + c t) along the unit vector s toward the bottom,
  // with g a Gaussian of half-width 300 m around 2000 m from the bottom.
  std::string
  pulse(const std::string &height, const double c, const double p)
  {
    std::ostringstream o;
    o.precision(17);
    const std::string g = "0.01*exp(-((" + height + "-2000)/300)^2)";
    o << p << "*" << g << "#" << p * c << "*" << g << "*(-2*(" << height
      << "-2000)/300^2)";
    return o.str();
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  // The quasi-P wave along the vertical of the 2-D model.
  const std::string axes_2d = std::to_string(std::sin(angle)) + ", " +
                              std::to_string(std::cos(angle)) + ", 0";
  dealii::ParameterHandler prm;
  rupture::Material::ElasticMaterials::declare_parameters(prm);
  prm.parse_input_from_string(
    "subsection Material\n  set Density = " + std::to_string(density) +
    "\n  set Symmetry = transversely isotropic\n"
    "  set Stiffness = " +
    stiffness + "\n  set Material axes = " + axes_2d + "\nend\n");
  rupture::Material::ElasticMaterials materials;
  materials.parse_parameters(prm, 3);
  dealii::Tensor<1, 3> vertical;
  vertical[1]      = 1;
  const auto pairs = dealii::eigenvectors(
    rupture::Material::christoffel_matrix(materials.get(0).voigt, vertical));
  const double c  = std::sqrt(pairs[0].first / density);
  double       px = pairs[0].second[0], py = pairs[0].second[1];
  if (py < 0)
    px = -px, py = -py;
  if (root)
    std::printf("quasi-P along the vertical: %.1f m/s, polarization %.1f "
                "degrees off the vertical\n",
                c,
                std::atan2(std::abs(px), py) * 180 / M_PI);

  const auto split = [](const std::string &s) {
    const auto hash = s.find('#');
    return std::make_pair(s.substr(0, hash), s.substr(hash + 1));
  };
  const auto [ux, vx]   = split(pulse("y", c, px));
  const auto [uy, vy]   = split(pulse("y", c, py));
  const auto [uz, vz]   = split(pulse("z", c, py));
  const auto [ux3, vx3] = split(pulse("z", c, px));

  struct Case
  {
    std::string              title, directory;
    std::vector<std::string> settings;
  };
  const std::string input =
    std::string(SOURCE_DIR) + "/inputs/absorbing_oblique.prm";
  const std::vector<Case> cases = {
    {"2-D, explicit", "explicit", {}},
    {"2-D, implicit Newmark, lumped mass, AMG",
     "implicit",
     {"--set",
      "Time integration/Scheme=implicit Newmark",
      "--set",
      "Discretization/Mass matrix=lumped"}},
    {"2-D, implicit Newmark, lumped mass, matrix-free",
     "matrix-free",
     {"--set",
      "Time integration/Scheme=implicit Newmark",
      "--set",
      "Discretization/Mass matrix=lumped",
      "--set",
      "Solver/Preconditioner=block Jacobi"}},
    {"3-D slab, explicit",
     "slab",
     {"--set",
      "Dimension=3",
      "--set",
      "Scene/Box/Upper corner=11000, 100, 3000",
      "--set",
      "Scene/Box/Number of cells=110, 1, 30",
      "--set",
      "Boundary conditions/Roller=south: y, north: y",
      "--set",
      "Material/Material axes=" + std::to_string(std::sin(angle)) + ", 0, " +
        std::to_string(std::cos(angle)),
      "--set",
      "Initial conditions/Displacement=" + ux3 + "; 0; " + uz,
      "--set",
      "Initial conditions/Velocity=" + vx3 + "; 0; " + vz,
      "--set",
      "Output/Receivers=centre: 5500, 50, 600"}}};

  std::vector<std::vector<double>> explicit_rows, implicit_rows;
  for (const Case &k : cases)
    {
      std::vector<std::string> args = {input,
                                       "--set",
                                       "Output directory=" + k.directory,
                                       "--set",
                                       "Material/Stiffness=" + stiffness,
                                       "--set",
                                       "Material/Material axes=" + axes_2d,
                                       "--set",
                                       "Initial conditions/Displacement=" + ux +
                                         "; " + uy,
                                       "--set",
                                       "Initial conditions/Velocity=" + vx +
                                         "; " + vy};
      args.insert(args.end(), k.settings.begin(), k.settings.end());
      const int code = tests::run(args);
      if (!root)
        continue;
      // t, then displacement and velocity per component.
      const auto rows = tests::read_statistics(k.directory + "/centre.dat");
      const bool slab = (k.directory == "slab");
      // The pulse has passed the receiver 1400 m below its start by
      // (1400 + 2.5 x 300 m) / c. After that: the quasi-P reflection, along
      // the polarization (some of which the discretization reflects in any
      // rock), and the converted quasi-S wave across it, which only an
      // impedance that is not that of the rock makes.
      const double passed   = 2150 / c;
      double       incident = 0, along = 0, across = 0;
      for (const auto &row : rows)
        {
          const double vx = row[2], vy = slab ? row[6] : row[4];
          if (row[0] < passed)
            incident = std::max(incident, std::hypot(vx, vy));
          else
            {
              along  = std::max(along, std::abs(vx * px + vy * py));
              across = std::max(across, std::abs(vx * py - vy * px));
            }
        }
      std::printf("%s: exit code %d, %zu rows; incident peak %.3f m/s; "
                  "after it, along its polarization %.1f %% of it, across "
                  "it %.3f %% (below 0.01 %%: %s)\n",
                  k.title.c_str(),
                  code,
                  rows.size(),
                  incident,
                  100 * along / incident,
                  100 * across / incident,
                  across < 1e-4 * incident ? "yes" : "NO");
      // The series against those of another case: columns (here, there).
      const auto compare =
        [&](const std::vector<std::vector<double>>           &other,
            const std::vector<std::pair<unsigned, unsigned>> &columns) {
          if (rows.size() != other.size())
            return 1e300;
          double largest = 0, diff = 0;
          for (unsigned int i = 0; i < rows.size(); ++i)
            for (const auto &[a, b] : columns)
              {
                largest = std::max(largest, std::abs(other[i][b]));
                diff    = std::max(diff, std::abs(rows[i][a] - other[i][b]));
              }
          return diff / largest;
        };
      if (k.directory == "explicit")
        explicit_rows = rows;
      if (k.directory == "implicit")
        implicit_rows = rows;
      if (k.directory == "matrix-free")
        std::printf("  the series equal those with the assembled matrix "
                    "within 1e-6: %s\n",
                    compare(implicit_rows, {{1, 1}, {2, 2}, {3, 3}, {4, 4}}) <
                        1e-6 ?
                      "yes" :
                      "NO");
      if (slab)
        std::printf("  the slab's x and z series equal the 2-D x and y ones "
                    "within 1e-9: %s\n",
                    compare(explicit_rows, {{1, 1}, {2, 2}, {5, 3}, {6, 4}}) <=
                        1e-9 ?
                      "yes" :
                      "NO");
    }
}
