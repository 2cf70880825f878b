// A box built as blocks refined <Tree levels> times gives every cell, the
// parents too, the material of its layer: p4est refines a coarse cell again
// wherever cells move to another process or a checkpoint is loaded, and the
// children take the parent's material. Before, the parents kept the ids that
// deal.II's colouring gives by octant (0 to 7), and a three-level adaptive
// TPV3 on 2 ranks met a cell of material 6 where one material exists. Each
// mesh here is coarsened to its coarse cells and refined again, as a process
// does that gets cells back, and the materials are counted against the
// layers. A layered box whose layers do not fill whole blocks takes fewer
// levels, so that no block straddles an interface. The vertices come back
// where they were: the box describes its blocks by a manifold, so that a
// graded block refined again has its graded vertices (before, they came
// back at the blocks' midpoints, up to 2.5 m off in the graded box here).


#include <rupture/scene/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>

#include <cstdio>
#include <string>
#include <vector>

using namespace dealii;

namespace
{
  template <int dim>
  void
  check(const std::string &name,
        const std::string &lower,
        const std::string &upper,
        const std::string &cells,
        const std::string &interfaces,
        const std::string &growth,
        const std::string &core_lower,
        const std::string &core_upper)
  {
    ParameterHandler prm;
    rupture::Scene::declare_parameters(prm);
    prm.enter_subsection("Scene");
    prm.set("Model", "box");
    prm.enter_subsection("Box");
    prm.set("Lower corner", lower);
    prm.set("Upper corner", upper);
    prm.set("Number of cells", cells);
    prm.set("Tree levels", "2");
    prm.set("Layer interfaces", interfaces);
    prm.enter_subsection("Grading");
    prm.set("Growth factor", growth);
    if (!core_lower.empty())
      {
        prm.set("Core lower corner", core_lower);
        prm.set("Core upper corner", core_upper);
      }
    prm.leave_subsection();
    prm.leave_subsection();
    prm.leave_subsection();
    const auto                scene = rupture::Scene::create<dim>(prm);
    const std::vector<double> z =
      Utilities::string_to_double(Utilities::split_string_list(interfaces));
    const auto layer = [&](const Point<dim> &p) {
      types::material_id id = 0;
      for (const double interface : z)
        id += (p[dim - 1] < interface);
      return id;
    };

    parallel::distributed::Triangulation<dim> mesh(MPI_COMM_WORLD);
    scene->create_coarse_mesh(mesh);
    const unsigned int levels = mesh.n_global_levels() - 1;
    unsigned int       wrong  = 0;
    for (const auto &cell : mesh.cell_iterators())
      wrong += (cell->material_id() != layer(cell->center()));
    std::printf("%s: %u coarse cells, %u tree levels, %u cells\n",
                name.c_str(),
                mesh.n_cells(0),
                levels,
                mesh.n_global_active_cells());
    std::printf("  cells (all levels) off their layer's material: %u\n", wrong);

    std::vector<Point<dim>> before;
    for (const auto &cell : mesh.active_cell_iterators())
      for (const auto v : cell->vertex_indices())
        before.push_back(cell->vertex(v));
    for (unsigned int k = 0; k < levels; ++k)
      {
        for (const auto &cell : mesh.active_cell_iterators())
          cell->set_coarsen_flag();
        mesh.execute_coarsening_and_refinement();
      }
    const unsigned int coarse = mesh.n_global_active_cells();
    mesh.refine_global(levels);
    wrong = 0;
    for (const auto &cell : mesh.active_cell_iterators())
      wrong += (cell->material_id() != layer(cell->center()));
    std::vector<Point<dim>> after;
    for (const auto &cell : mesh.active_cell_iterators())
      for (const auto v : cell->vertex_indices())
        after.push_back(cell->vertex(v));
    double moved = (before.size() == after.size() ? 0 : 1e300);
    for (unsigned int i = 0; i < std::min(before.size(), after.size()); ++i)
      moved = std::max(moved, before[i].distance(after[i]));
    std::printf("  coarsened to %u cells and refined again: cells off their "
                "layer's material: %u; vertices where they were: %s\n",
                coarse,
                wrong,
                moved == 0 ? "yes" : "no");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // A uniform box and a graded one (colouring numbered their parents by
  // octant), two layers in blocks of 4 cells, and three layers of 6, 4 and
  // 6 cells (blocks of 2 cells: one level instead of two).
  check<2>("2-D uniform", "0, 0", "8, 8", "8, 8", "", "1", "", "");
  check<2>(
    "2-D graded", "-60, -40", "60, 40", "16, 8", "", "1.2", "-16, -8", "16, 8");
  check<2>("2-D two layers", "0, -16", "8, 0", "8, 16", "-8", "1", "", "");
  check<2>(
    "2-D three layers", "0, -16", "8, 0", "8, 16", "-6, -10", "1", "", "");
  check<3>("3-D uniform", "0, 0, 0", "8, 8, 8", "8, 8, 8", "", "1", "", "");
  check<3>(
    "3-D two layers", "0, 0, -16", "4, 4, 0", "4, 4, 16", "-8", "1", "", "");
  return 0;
}
