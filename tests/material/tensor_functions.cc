// Anisotropic constants given as functions of position, each on its own
// (<Material/Stiffness> = "C11 = 6e10 + 6e7*x, ..."), so that the shape of
// the tensor, not only its size, varies in space:
// 1. The same constants written as functions that are constant give the
//    results of the numbers: a 3-D explicit split-node rupture in an
//    oblique transversely isotropic medium with absorbing boundaries (the
//    matrix-free operator's tensor per quadrature point, the lumped mass,
//    the stable step's bound, the dashpots, the fault pairs' shear
//    stiffness), and a transversely isotropic layer over an isotropic one
//    under gravity, quasi-static (assembled matrix) and explicit.
// 2. The explicit stable step bounds each cell by the largest energy ratio
//    of its tensors to a reference tensor times its shape's eigenvalue
//    with that reference. The reference is the cell's own tensor at its
//    centre, rounded (to 1 % of its largest diagonal entry), so that it
//    follows the tensor's shape; the material's reference (its tensor at
//    the origin, or the Kelvin identity where the constants are not
//    allowed there) only where the rounded tensor is not positive definite
//    enough. In a box whose C11 doubles along x the step is within 0.5 %
//    below that of the box made of the stiffest rock; where C11 grows and
//    C66 falls to a third along x (the tensor's shape changes: with the
//    material's reference alone the step was 1/sqrt(3) of what the stiffer
//    end rock needs) it is within 6 % below (the tensor's change across a
//    cell and the rounding).

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace
{

  /// Runs @p prm with @p settings plus @p numbers in <name>-numbers and
  /// plus @p functions in <name>-functions; says whether the statistics
  /// (and the files @p also) agree to @p tolerance.
  void
  compare(const std::string              &title,
          const std::string              &name,
          const std::string              &prm,
          const std::vector<std::string> &settings,
          const std::string              &numbers,
          const std::string              &functions,
          const std::vector<std::string> &also,
          const double                    tolerance)
  {
    std::vector<std::string> a = settings, b = settings;
    a.push_back("Material/Stiffness=" + numbers);
    b.push_back("Material/Stiffness=" + functions);
    tests::run_in(name + "-numbers", {prm}, a);
    tests::run_in(name + "-functions", {prm}, b);
    std::vector<std::string> files = {"statistics"};
    files.insert(files.end(), also.begin(), also.end());
    for (const std::string &file : files)
      {
        const auto x = tests::read_statistics(name + "-numbers/" + file);
        const auto y = tests::read_statistics(name + "-functions/" + file);
        if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          std::printf("%s: %s, %zu rows, the same to %g: %s\n",
                      title.c_str(),
                      file.c_str(),
                      x.size(),
                      tolerance,
                      tests::relative_difference(x, y) < tolerance ? "yes" :
                                                                     "no");
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string source = std::string(SOURCE_DIR) + "/../";

  // 1. Constant functions = numbers.
  compare("3-D split nodes, oblique transversely isotropic",
          "split-3d",
          source + "fault/split_node_3d.prm",
          {"Time integration/End time=0.6",
           "Material/Symmetry=transversely isotropic",
           "Material/Material axes=1, 2, 3"},
          "C11 = 6.0e10, C33 = 4.0e10, C13 = 1.5e10, C44 = 1.2e10, "
          "C66 = 2.0e10",
          "C11 = 6.0e10 + 0*x, C33 = 4.0e10 + 0*y*z, C13 = 1.5e10, "
          "C44 = if(x < 1e9, 1.2e10, 0), C66 = 2.0e10 + 0*z",
          {"center.dat"},
          1e-10);
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
    compare("transversely isotropic layer over an isotropic one, " + scheme,
            "layers-" + scheme,
            "layers.prm",
            scheme == "explicit" ?
              std::vector<std::string>{"Time integration/Scheme=explicit "
                                       "central difference",
                                       "Time integration/Time step=0",
                                       "Time integration/End time=0.05"} :
              std::vector<std::string>{},
            "C11 = 6.2e10, C33 = 4.8e10, C13 = 1.9e10, C44 = 1.6e10, C66 = "
            "2.1e10;",
            "C11 = 6.2e10 + 0*x, C33 = 4.8e10, C13 = 1.9e10 + 0*y, C44 = "
            "1.6e10, C66 = 2.1e10;",
            {},
            1e-10);

  // 2. The stable step.
  std::ofstream("box.prm") << R"(set Dimension = 2
set Test mode = true
subsection Scene
  set Model = box
  subsection Box
    set Lower corner = 1000, 0
    set Upper corner = 2000, 500
    set Number of cells = 8, 4
  end
end
subsection Material
  set Density = 2700
  set Symmetry = orthotropic
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
)" << std::flush;
  const auto step = [](const std::string &dir) {
    return tests::find_number(dir + "/log.txt", "Stable explicit time step:");
  };
  const auto constants = [](const std::string &c11, const std::string &c66) {
    return "Material/Stiffness=C11 = " + c11 +
           ", C22 = 5e10, C33 = 5e10, C12 = 1.5e10, C13 = 1.5e10, C23 = "
           "1.5e10, C44 = 2e10, C55 = 2e10, C66 = " +
           c66;
  };
  // C11 from 6e10 at x = 1000 to 12e10 at x = 2000: linear (zero at the
  // origin, where the reference is then the Kelvin identity) and
  // quadratic (12e10 at the origin, the stiffest rock's tensor there).
  tests::run_in("stiffest", {"box.prm"}, {constants("12e10", "2e10")});
  tests::run_in("graded", {"box.prm"}, {constants("6e7*x", "2e10")});
  tests::run_in("graded-origin",
                {"box.prm"},
                {constants("6e10 + 6e4*(x - 1000)^2", "2e10")});
  // C11 growing, C66 falling: the rocks at the ends, and the gradient.
  tests::run_in("end-1000", {"box.prm"}, {constants("6e10", "3e10")});
  tests::run_in("end-2000", {"box.prm"}, {constants("12e10", "1e10")});
  tests::run_in("shape",
                {"box.prm"},
                {constants("6e10 + 6e4*(x - 1000)^2",
                           "3e10 - 2e4*(x - 1000)^2")});
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    return 0;
  std::printf("stable step: C11 doubling along x / stiffest rock = %.3f "
              "(reference at the origin not allowed, the Kelvin identity), "
              "%.3f (reference at the origin allowed)\n",
              step("graded") / step("stiffest"),
              step("graded-origin") / step("stiffest"));
  std::printf("stable step: C11 growing and C66 falling along x / the "
              "smaller of the two end rocks = %.3f (end rocks %.3g and %.3g "
              "s)\n",
              step("shape") / std::min(step("end-1000"), step("end-2000")),
              step("end-1000"),
              step("end-2000"));
}
