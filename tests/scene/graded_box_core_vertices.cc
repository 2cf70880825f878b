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

namespace
{
  // Whether @p s holds @p x to 1e-6 m (the outer cells' round-off).
  bool
  contains(const std::set<double> &s, const double x)
  {
    const auto it = s.lower_bound(x - 1e-6);
    return it != s.end() && *it <= x + 1e-6;
  }

  // The distinct x and y of the vertices of a graded box built with
  // <Tree levels> = levels, after printing what the test checks.
  std::pair<std::set<double>, std::set<double>>
  check(const std::string &levels)
  {
    ParameterHandler prm;
    rupture::Scene::declare_parameters(prm);
    prm.enter_subsection("Scene");
    prm.set("Model", "box");
    prm.enter_subsection("Box");
    prm.set("Lower corner", "-60000, -45000");
    prm.set("Upper corner", "60000, 45000");
    prm.set("Number of cells", "144, 12");
    prm.set("Tree levels", levels);
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

    // Every distinct x of a vertex inside the core, and how many of them
    // are not exactly -18000 + i 250.
    std::set<double> xs, all_x, all_y;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto v : cell->vertex_indices())
        {
          const Point<2> &p = cell->vertex(v);
          all_x.insert(p[0]);
          all_y.insert(p[1]);
          if (p[0] >= -18000.5 && p[0] <= 18000.5)
            xs.insert(p[0]);
        }
    unsigned int off_grid = 0, in_patch = 0;
    for (const double x : xs)
      {
        const double i = std::round((x + 18000) / 250);
        if (x != -18000 + i * 250)
          ++off_grid;
        if (std::abs(x) <= 1500)
          ++in_patch;
      }
    std::printf("Tree levels %s: cells %u, coarse cells %u, vertex columns in "
                "the core %zu (expected 145)\n",
                levels.c_str(),
                triangulation.n_active_cells(),
                triangulation.n_cells(0),
                xs.size());
    std::printf("  columns not exactly on the core grid: %u\n", off_grid);
    std::printf("  columns with abs(x) <= 1500: %u (expected 13)\n", in_patch);
    std::printf("  y = 0 is a vertex row: %s\n",
                all_y.count(0.) ? "yes" : "no");
    return {all_x, all_y};
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // One coarse cell per cell, then blocks of 4 x 4 and 8 x 8 cells refined
  // 2 and 3 times: the same vertices, except that the largest outer cells
  // are halved where the numbers of cells are not divisible.
  const auto reference = check("0");
  for (const std::string levels : {"2", "3"})
    {
      const auto   mesh  = check(levels);
      unsigned int extra = 0, missing = 0, extra_in_core = 0;
      for (unsigned int d = 0; d < 2; ++d)
        {
          const auto &a = (d == 0 ? reference.first : reference.second);
          const auto &b = (d == 0 ? mesh.first : mesh.second);
          for (const double x : a)
            missing += !contains(b, x);
          for (const double x : b)
            if (!contains(a, x))
              {
                ++extra;
                const double core = (d == 0 ? 18000 : 1500);
                extra_in_core += (std::abs(x) <= core);
              }
        }
      std::printf("  vertex coordinates of Tree levels 0 missing: %u; added "
                  "(halved outer cells): %u, of which in the core: %u\n",
                  missing,
                  extra,
                  extra_in_core);
    }
  return 0;
}
