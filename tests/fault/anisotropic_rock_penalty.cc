// Penalty contact (the paper's fault method) in anisotropic rock, serial
// and on 2 ranks: the implicit 3-D rupture of penalty_rupture_3d.prm and
// the 2-D quasi-static loading then implicit rupture of load_sequence.prm,
// each in transversely isotropic rock whose axis is oblique to the fault
// (3-D: along (1, 2, 3); 2-D: along (1, 2, 0), so that the model plane
// stays a mirror plane). Each run must finish with its energy balance
// closed, and give the same stations as the same tensor written out as a
// general one (all 21 constants in the model's frame, computed here from
// the rotated tensor: the general class takes no rotation), so that the
// classes, the rotation and the penalty bound from the tensor agree.

#include <rupture/material/elastic_material.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  const std::string stiffness =
    "C11 = 1.2e11, C33 = 0.8e11, C13 = 3.2e10, C44 = 2.4e10, C66 = 3.6e10";

  /// The 21 constants of the rotated tensor, as <Material/Stiffness> of
  /// the general class.
  std::string
  general_constants(const std::string &axes, const unsigned int dim)
  {
    dealii::ParameterHandler prm;
    rupture::Material::ElasticMaterials::declare_parameters(prm);
    prm.parse_input_from_string(
      "subsection Material\n  set Density = 2670\n  set Symmetry = "
      "transversely isotropic\n  set Stiffness = " +
      stiffness + "\n  set Material axes = " + axes + "\nend\n");
    rupture::Material::ElasticMaterials materials;
    materials.parse_parameters(prm, dim);
    const auto        &c = materials.get(0).voigt;
    std::ostringstream o;
    o.precision(17);
    for (unsigned int i = 0; i < 6; ++i)
      for (unsigned int j = i; j < 6; ++j)
        o << (i + j > 0 ? ", " : "") << "C" << i + 1 << j + 1 << " = "
          << c[i][j];
    return o.str();
  }

  bool
  balance_closed(const std::string &directory)
  {
    const std::string text = tests::read_file(directory + "/summary.json");
    return text.find("\"within\": true") != std::string::npos &&
           text.find("\"status\": \"finished\"") != std::string::npos;
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  struct Case
  {
    std::string              title, prm, axes;
    unsigned int             dim;
    std::vector<std::string> stations;
  };
  const std::vector<Case> cases = {
    {"3-D implicit rupture",
     "penalty_rupture_3d.prm",
     "1, 2, 3",
     3,
     {"center", "edge"}},
    {"2-D quasi-static loading, then implicit rupture",
     "load_sequence.prm",
     "1, 2, 0",
     2,
     {"centre", "side"}}};
  for (const Case &c : cases)
    {
      const std::string tag = std::to_string(c.dim) + "d-";
      const auto        run = [&](const std::string &directory,
                           const std::string &symmetry,
                           const std::string &constants,
                           const std::string &axes) {
        return tests::run({std::string(SOURCE_DIR) + "/" + c.prm,
                           "--set",
                           "Output directory=" + tag + directory,
                           "--set",
                           "Material/Symmetry=" + symmetry,
                           "--set",
                           "Material/Stiffness=" + constants,
                           "--set",
                           "Material/Material axes=" + axes});
      };
      const int ti = run("ti", "transversely isotropic", stiffness, c.axes);
      const int general =
        run("general", "general", general_constants(c.axes, c.dim), "");
      if (!root)
        continue;
      std::printf("%s in TI rock, axis (%s): exit codes %d %d, energy "
                  "balance closed: %s %s\n",
                  c.title.c_str(),
                  c.axes.c_str(),
                  ti,
                  general,
                  balance_closed(tag + "ti") ? "yes" : "NO",
                  balance_closed(tag + "general") ? "yes" : "NO");
      for (const std::string &s : c.stations)
        {
          const auto a = tests::read_statistics(tag + "ti/" + s + ".dat");
          const auto b = tests::read_statistics(tag + "general/" + s + ".dat");
          double     slip = 0;
          for (const auto &row : a)
            slip = std::max(slip, std::abs(row[1]));
          std::printf("  station %s: largest slip %.3f m; the general "
                      "tensor gives the same series within 1e-6: %s\n",
                      s.c_str(),
                      slip,
                      tests::relative_difference(a, b) < 1e-6 ? "yes" : "NO");
        }
    }
}
