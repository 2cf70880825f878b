// A graded box puts the vertices of its uniform core exactly on the core's
// grid (core lower corner + i h), whatever the round-off of the growing
// outer cells, so that regions given by exact bounds contain the vertices
// on their edges. This is TPV3's x direction at 250 m (144 cells across the
// core [-18000, 18000] in a box [-60000, 60000], growth 1.2): before the
// vertices were snapped, the nucleation patch "abs(x) <= 1500" lost the
// vertices on its edge.

#include <rupture/scene/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>

#include <cstdio>
#include <set>

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  ParameterHandler prm;
  rupture::Scene::declare_parameters(prm);
  prm.enter_subsection("Scene");
  prm.set("Model", "box");
  prm.enter_subsection("Box");
  prm.set("Lower corner", "-60000, -45000");
  prm.set("Upper corner", "60000, 45000");
  prm.set("Number of cells", "144, 12");
  prm.enter_subsection("Grading");
  prm.set("Growth factor", "1.2");
  prm.set("Core lower corner", "-18000, -1500");
  prm.set("Core upper corner", "18000, 1500");
  prm.leave_subsection();
  prm.leave_subsection();
  prm.leave_subsection();
  const auto scene = rupture::Scene::create<2>(prm);

  parallel::distributed::Triangulation<2> triangulation(MPI_COMM_WORLD);
  scene->create_coarse_mesh(triangulation);

  // Every distinct x of a vertex inside the core, and how many of them are
  // not exactly -18000 + i 250.
  std::set<double> xs;
  for (const auto &p : triangulation.get_vertices())
    if (p[0] >= -18000.5 && p[0] <= 18000.5)
      xs.insert(p[0]);
  unsigned int off_grid = 0, in_patch = 0;
  for (const double x : xs)
    {
      const double i = std::round((x + 18000) / 250);
      if (x != -18000 + i * 250)
        ++off_grid;
      if (std::abs(x) <= 1500)
        ++in_patch;
    }
  std::printf("cells %u, vertex columns in the core %zu (expected 145)\n",
              triangulation.n_active_cells(),
              xs.size());
  std::printf("columns not exactly on the core grid: %u\n", off_grid);
  std::printf("columns with abs(x) <= 1500: %u (expected 13)\n", in_patch);
  std::printf("y = 0 is a vertex row: %s\n",
              std::any_of(triangulation.get_vertices().begin(),
                          triangulation.get_vertices().end(),
                          [](const Point<2> &p) { return p[1] == 0.; }) ?
                "yes" :
                "no");
  return 0;
}
