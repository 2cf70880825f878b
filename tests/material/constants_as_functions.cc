// Isotropic constants given as functions of position (<Material/Density>,
// the wave speeds or Young's modulus and Poisson's ratio) reach every part
// of the computation that uses a material's constants:
// 1. The same constants written as functions that are constant (e.g.
//    "6000 + 0*x") give the results of the numbers: the 3-D explicit
//    split-node rupture with absorbing boundaries (lumped mass, stiffness,
//    stable step, dashpots, the fault pairs' shear modulus) and the 2-D
//    Northeast-Japan section with three materials by Young's modulus and
//    Poisson's ratio (implicit Newmark, penalty contact, assembled matrix,
//    loading then rupture).
// 2. The explicit stable step bounds each cell by its largest local
//    constants: in a box whose P-wave speed grows along x (with a fixed
//    S-wave speed, so that Poisson's ratio changes too) the step is within
//    0.5 % below that of the box made of the fastest rock (the reference's
//    lambda / mu is rounded up to a bin of 1 %); where vs grows from 2500 to
//    3500 m/s at a fixed vp (the cells of low vs limit the step: a rock
//    of vs 2500 needs a smaller step than one of 3500) the bound takes
//    each cell's largest lambda and mu, and the step is within 1 % below
//    that of the rock of vs 2500 (on the safe side).
// 3. The volume output's stress uses the local constants (a column under
//    gravity whose Poisson's ratio changes with depth).
// 4. An isotropic material given by functions beside an anisotropic one
//    (the operator's anisotropic kernel, with Lame's constants per
//    quadrature point in the function material's lanes): a two-layer box
//    under gravity, quasi-static and explicit, gives the results of the
//    same constants as numbers.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace
{
  /// The Float32 array @p name of an uncompressed .vtu file with appended
  /// raw data (a 64-bit byte count, then the values).
  std::vector<double>
  raw_array(const std::string &file, const std::string &name)
  {
    const std::string   text = tests::read_file(file);
    const auto          tag  = text.find("Name=\"" + name + "\"");
    const auto          data = text.find("<AppendedData encoding=\"raw\">");
    std::vector<double> values;
    if (tag == std::string::npos || data == std::string::npos)
      return values;
    const auto        key    = text.find("offset=\"", tag) + 8;
    const std::size_t offset = std::stoull(text.substr(key));
    const char       *at     = text.data() + text.find('_', data) + 1 + offset;
    std::uint64_t     bytes;
    std::memcpy(&bytes, at, 8);
    for (std::size_t i = 0; i < bytes / 4; ++i)
      {
        float v;
        std::memcpy(&v, at + 8 + 4 * i, 4);
        values.push_back(v);
      }
    return values;
  }



  /// Runs @p prm with @p settings in <name>-numbers, and with @p functions
  /// added in <name>-functions, and says whether the two statistics files
  /// agree to @p tolerance.
  void
  compare_with_functions(const std::string              &title,
                         const std::string              &name,
                         const std::string              &prm,
                         std::vector<std::string>        settings,
                         const std::vector<std::string> &functions,
                         const double                    tolerance)
  {
    tests::run_in(name + "-numbers", {prm}, settings);
    settings.insert(settings.end(), functions.begin(), functions.end());
    tests::run_in(name + "-functions", {prm}, settings);
    const auto a = tests::read_statistics(name + "-numbers/statistics");
    const auto b = tests::read_statistics(name + "-functions/statistics");
    std::printf("%s: %zu rows, statistics %s to %g\n",
                title.c_str(),
                a.size(),
                tests::relative_difference(a, b) < tolerance ? "the same" :
                                                               "differ",
                tolerance);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string source = std::string(SOURCE_DIR) + "/../";

  // 1. Constant functions = numbers.
  compare_with_functions("3-D split nodes",
                         "split-3d",
                         source + "fault/split_node_3d.prm",
                         {"Time integration/End time=0.6"},
                         {"Material/Density=2670 + 0*x",
                          "Material/P-wave speed=6000 + 0*y",
                          "Material/S-wave speed=3464 + 0*z"},
                         1e-10);
  std::printf("3-D split nodes: centre station %s to 1e-10\n",
              tests::relative_difference(
                tests::read_statistics("split-3d-numbers/center.dat"),
                tests::read_statistics("split-3d-functions/center.dat")) <
                  1e-10 ?
                "the same" :
                "differs");
  compare_with_functions(
    "2-D Northeast Japan",
    "japan-2d",
    source + "scene/northeast_japan_fault_2d.prm",
    {},
    {"Material/Young's modulus=2.69e10 + 0*x; 3.82e10 + 0*y; 12.07e10 + 0*x",
     "Material/Poisson's ratio=0.226 + 0*x; 0.273; 0.258 + 0*y",
     "Material/Density=2700; 3300 + 0*y; 3000"},
    1e-9);

  // 2. The stable step in a box whose P-wave speed grows along x.
  const std::string box = R"(set Dimension = 2
set Test mode = true
subsection Scene
  set Model = box
  subsection Box
    set Upper corner = 1000, 500
    set Number of cells = 8, 4
  end
end
subsection Material
  set Density = 2700
  set S-wave speed = 3000
end
subsection Boundary conditions
  set Fixed = bottom
end
subsection Time integration
  set Scheme = explicit central difference
  set Time step = 0
  set End time = 0.01
end
subsection Output
  set Output interval = -1
end
)";
  std::ofstream("box.prm") << box << std::flush;
  const auto stable_step = [](const std::string &dir) {
    return tests::find_number(dir + "/log.txt", "Stable explicit time step:");
  };
  tests::run_in("fastest", {"box.prm"}, {"Material/P-wave speed=7000"});
  tests::run_in("gradient",
                {"box.prm"},
                {"Material/P-wave speed=5600 + 1.4*x"});
  tests::run_in("vs-gradient",
                {"box.prm"},
                {"Material/P-wave speed=7000",
                 "Material/S-wave speed=2500 + x"});
  tests::run_in("vs-2500",
                {"box.prm"},
                {"Material/P-wave speed=7000", "Material/S-wave speed=2500"});
  tests::run_in("vs-3500",
                {"box.prm"},
                {"Material/P-wave speed=7000", "Material/S-wave speed=3500"});
  std::printf("stable step: vp gradient / fastest rock = %.3f; vs gradient "
              "at fixed vp / rock of vs 2500 = %.3f (of vs 3500: %.3f)\n",
              stable_step("gradient") / stable_step("fastest"),
              stable_step("vs-gradient") / stable_step("vs-2500"),
              stable_step("vs-gradient") / stable_step("vs-3500"));

  // 3. A column under gravity between rollers (x fixed on both sides) has
  // eps_xx = 0, so sigma_xx / sigma_yy = lambda / (lambda + 2 mu) at the
  // point where the output takes the constants (the cells' centres),
  // however accurate the solution: with vp growing upwards from 5500 to
  // 7100 m/s at a fixed vs that ratio runs from 0.40 to 0.64.
  {
    std::ofstream("column.prm") << R"(set Dimension = 2
set Test mode = true
subsection Scene
  set Model = box
  subsection Box
    set Upper corner = 100, 800
    set Number of cells = 1, 16
  end
end
subsection Material
  set Density = 2700
  set P-wave speed = 5500 + 2*y
  set S-wave speed = 3000
end
subsection Boundary conditions
  set Fixed = bottom
  set Roller = west: x, east: x
end
subsection Loads
  set Gravity = 9.81
end
subsection Time integration
  set Scheme = quasi-static
  set Time step = 1
  set End time = 1
end
subsection Output
  set Output interval = 1
  set Volume fields = stress
  set Compression = none
end
)";
  }
  tests::run_in("column", {"column.prm"}, {});
  const auto stress =
    raw_array("column/solution/solution_00001.0.vtu", "stress");
  std::vector<double> measured, expected;
  for (unsigned int c = 0; c + 9 <= stress.size(); c += 9)
    measured.push_back(stress[c + 0] / stress[c + 4]);
  for (unsigned int i = 0; i < 16; ++i)
    {
      const double vp = 5500 + 2 * (25 + 50 * i), vs = 3000;
      expected.push_back(1 - 2 * vs * vs / (vp * vp));
    }
  std::sort(measured.begin(), measured.end());
  double error = (measured.size() == expected.size() ? 0 : 1e300);
  for (unsigned int i = 0; i < std::min(measured.size(), expected.size()); ++i)
    error = std::max(error, std::abs(measured[i] - expected[i]));
  std::printf("column: %zu cells, sigma_xx / sigma_yy from %.4f to %.4f, "
              "lambda / (lambda + 2 mu) at the centres %s to 1e-6\n",
              measured.size(),
              measured.empty() ? 0. : measured.front(),
              measured.empty() ? 0. : measured.back(),
              error < 1e-6 ? "matched" : "not matched");

  // 4. A transversely isotropic layer over an isotropic one whose
  // constants are constant functions.
  {
    std::ofstream("layers.prm")
      << "set Dimension = 2\nset Test mode = true\nsubsection Scene\n  set "
         "Model = gmsh\n  subsection Gmsh\n    set Mesh file = "
      << source << "../meshes/two_layer_box_2d.msh\n  end\nend\n"
      << R"(subsection Material
  set Names = upper, lower
  set Density = 2500, 3000
  set P-wave speed = 5000, 6000
  set S-wave speed = 2887, 3464
  set Symmetry = transversely isotropic, isotropic
  set Stiffness = C11 = 6.2e10, C33 = 4.8e10, C13 = 1.9e10, C44 = 1.6e10, C66 = 2.1e10;
  set Material axes = 1, 1, 0;
end
subsection Boundary conditions
  set Roller = west: x, east: x
  set Fixed = bottom
end
subsection Loads
  set Gravity = 9.81
end
subsection Time integration
  set Scheme = quasi-static
  set Time step = 1
  set End time = 1
end
subsection Output
  set Output interval = -1
end
)";
  }
  for (const std::string scheme : {"quasi-static", "explicit"})
    compare_with_functions(
      "anisotropic layer over a function layer, " + scheme,
      "layers",
      "layers.prm",
      scheme == "explicit" ?
        std::vector<std::string>{"Time integration/Scheme=explicit central "
                                 "difference",
                                 "Time integration/Time step=0",
                                 "Time integration/End time=0.05"} :
        std::vector<std::string>{},
      {"Material/Density=2500; 3000 + 0*x",
       "Material/P-wave speed=5000; 6000 + 0*y",
       "Material/S-wave speed=2887; 3464 + 0*x*y"},
      1e-10);
}
