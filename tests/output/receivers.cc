// Off-fault stations (<Output/Receivers>): a block under uniaxial plane-strain
// compression (E = 2.5e10, nu = 0.25, 10 MPa on top, rollers west and
// bottom) has the linear displacement u = (1.25e-4 x, -3.75e-4 y), which
// trilinear elements reproduce exactly, so the receiver values at points
// inside cells, on a node and on the corner must match it to round-off,
// serial and on 2 ranks (where a receiver sits on the boundary between the
// ranks' cells). Also: the file layout, and a receiver outside the mesh is
// refused with a message.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <fstream>

namespace
{
  const std::string input = R"(set Dimension = 2
set Test mode = true
set Output directory = results
subsection Scene
  subsection Box
    set Number of cells = 4
  end
end
subsection Material
  set Parametrization = Young's modulus and Poisson's ratio
  set Young's modulus = 2.5e10
  set Poisson's ratio = 0.25
end
subsection Boundary conditions
  set Roller = west: x, bottom: y
  set Traction = top: 0; -10e6
end
subsection Time integration
  set Scheme = quasi-static
  set Time step = 1
  set End time = 2
end
subsection Output
  set Output interval = -1
  set Receivers = inside: 310, 770; node: 500, 500; corner: 1000, 1000; edge: 0, 333
end
)";
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  if (!root)
    std::freopen("/dev/null", "w", stdout);
  if (root)
    std::ofstream("run.prm") << input;
  MPI_Barrier(MPI_COMM_WORLD);

  std::printf("exit code: %d\n", tests::run({"run.prm"}));
  if (root)
    {
      std::printf("header of inside.dat:\n");
      std::istringstream lines(tests::read_file("results/inside.dat"));
      std::string        line;
      while (std::getline(lines, line) && line.rfind("# Column", 0) != 0)
        ;
      do
        std::printf("  %s\n", line.c_str());
      while (std::getline(lines, line) && line[0] != '0');
      for (const std::string name : {"inside", "node", "corner", "edge"})
        {
          const auto rows = tests::read_statistics("results/" + name + ".dat");
          // read_statistics skips '#' lines; the field-name line is not a
          // number row, so the rows are t = 0, 1, 2.
          std::printf("%s: %zu rows\n", name.c_str(), rows.size());
          if (rows.empty())
            continue;
          const auto  &last = rows.back();
          const double x    = name == "inside" ? 310 :
                              name == "node"   ? 500 :
                              name == "corner" ? 1000 :
                                                 0;
          const double y    = name == "inside" ? 770 :
                              name == "node"   ? 500 :
                              name == "corner" ? 1000 :
                                                 333;
          const double ux = 1.25e-4 * x, uy = -3.75e-4 * y;
          std::printf("  t = %g: u = (%.6e, %.6e), exact (%.6e, %.6e), "
                      "error below 1e-12 m: %s, velocity below 1e-12 "
                      "m/s: %s\n",
                      last[0],
                      last[1],
                      last[3],
                      ux,
                      uy,
                      (std::abs(last[1] - ux) < 1e-12 &&
                       std::abs(last[3] - uy) < 1e-12) ?
                        "yes" :
                        "no",
                      (std::abs(last[2]) < 1e-12 && std::abs(last[4]) < 1e-12) ?
                        "yes" :
                        "no");
        }
    }

  // A receiver outside the mesh.
  if (root)
    {
      std::string text = input;
      text.replace(text.find("edge: 0, 333"), 12, "away: 2000, 10");
      std::ofstream("outside.prm") << text;
    }
  MPI_Barrier(MPI_COMM_WORLD);
  std::string errors;
  const int   code = tests::run_capture({"outside.prm"}, errors);
  while (!errors.empty() && errors[0] == '\n')
    errors.erase(0, 1);
  std::printf("receiver outside the mesh: exit code %d\n  %s",
              code,
              errors.c_str());
}
