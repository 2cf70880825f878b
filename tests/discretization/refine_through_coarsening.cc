// Discretization::refine() through a mesh that coarsened cells next to
// finer ones, then refines them again in a later pass of the same
// adaptation. A 2-D box of 16 x 4 cells of 250 m (no fault, degree 1),
// refined once where x < 2000 m, carries f = sin(x / 700) cos(y / 500).
// One adaptation then coarsens the cells where x < 1000 m back to 250 m
// (pass one) and refines them again (pass two, by the reflag callback):
// - where x < 1000 m the field must be the bilinear interpolant of f on
//   the 250 m cells (what the coarsened cells held);
// - on the line x = 1000 m, whose nodes hung on the coarse cells after
//   pass one and stop hanging in pass two, it must be that interpolant
//   too: the fields follow the coarsened mesh's hanging constraints before
//   the next pass (without that a node there would get the fine cells' own
//   value or the coarse cells', whichever cell wrote it last);
// - where x > 1000 m it must be f (on the line x = 2000 m, where the
//   fine cells meet the coarse ones, the coarse cells' interpolant).
// On one and two ranks.

#include <rupture/discretization/discretization.h>
#include <rupture/material/elastic_material.h>
#include <rupture/scene/scene.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

using namespace dealii;
using rupture::Discretization::Discretization;

namespace
{
  double
  f(const Point<2> &p)
  {
    return std::sin(p[0] / 700) * std::cos(p[1] / 500);
  }

  /// f in both components.
  class Field : public Function<2>
  {
  public:
    Field()
      : Function<2>(2)
    {}
    double
    value(const Point<2> &p, const unsigned int) const override
    {
      return f(p);
    }
  };

  /// The bilinear interpolant of f on the cells of 250 m.
  double
  interpolant(const Point<2> &p)
  {
    const double h  = 250;
    const double x0 = std::floor(p[0] / h) * h, y0 = std::floor(p[1] / h) * h;
    const double s = (p[0] - x0) / h, t = (p[1] - y0) / h;
    return (1 - s) * (1 - t) * f(Point<2>(x0, y0)) +
           s * (1 - t) * f(Point<2>(x0 + h, y0)) +
           (1 - s) * t * f(Point<2>(x0, y0 + h)) +
           s * t * f(Point<2>(x0 + h, y0 + h));
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ParameterHandler                 prm;
  rupture::Scene::declare_parameters(prm);
  rupture::Material::ElasticMaterials::declare_parameters(prm);
  prm.enter_subsection("Discretization");
  Discretization<2>::declare_parameters(prm);
  prm.leave_subsection();
  prm.parse_input_from_string("subsection Scene\n"
                              "  set Model = box\n"
                              "  subsection Box\n"
                              "    set Lower corner = 0, 0\n"
                              "    set Upper corner = 4000, 1000\n"
                              "    set Number of cells = 16, 4\n"
                              "  end\n"
                              "end\n");
  const auto                          scene = rupture::Scene::create<2>(prm);
  rupture::Material::ElasticMaterials materials;
  materials.parse_parameters(prm);
  Discretization<2> discretization(MPI_COMM_WORLD);
  prm.enter_subsection("Discretization");
  discretization.parse_parameters(prm);
  prm.leave_subsection();
  ConditionalOStream silent(std::cout, false);
  discretization.make_mesh(*scene, materials, "", silent);
  discretization.distribute_dofs();
  TimerOutput timer(MPI_COMM_SELF,
                    silent,
                    TimerOutput::never,
                    TimerOutput::wall_times);
  auto       &mesh = discretization.triangulation();
  const int   base =
    Utilities::MPI::min(mesh.begin_active()->level(), MPI_COMM_WORLD);
  const auto setup = [&]() { discretization.distribute_dofs(); };
  const auto flag  = [&](const double below, const bool refine) {
    bool any = false;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[0] < below)
        {
          if (refine && cell->level() == base)
            cell->set_refine_flag(), any = true;
          if (!refine && cell->level() == base + 1)
            cell->set_coarsen_flag(), any = true;
        }
    mesh.prepare_coarsening_and_refinement();
    return Utilities::MPI::max(any ? 1 : 0, MPI_COMM_WORLD) == 1;
  };

  std::vector<Discretization<2>::VectorType> fields(1);
  fields[0].reinit(discretization.locally_owned_dofs(), MPI_COMM_WORLD);
  flag(2000, true);
  discretization.refine(fields, 0, {}, setup, timer);
  fields[0].reinit(discretization.locally_owned_dofs(), MPI_COMM_WORLD);
  VectorTools::interpolate(discretization.dof_handler(), Field(), fields[0]);
  {
    // As refine() takes fields: their hanging DoFs (on x = 2000 m)
    // following their constraints.
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(discretization.dof_handler(),
                                            relevant);
    AffineConstraints<double> hanging(relevant);
    DoFTools::make_hanging_node_constraints(discretization.dof_handler(),
                                            hanging);
    hanging.close();
    hanging.distribute(fields[0]);
  }
  const unsigned int cells_refined = mesh.n_global_active_cells();

  flag(1000, false);
  unsigned int passes = 0;
  discretization.refine(
    fields,
    0,
    [&]() { return passes++ == 0 && flag(1000, true); },
    setup,
    timer);

  std::map<types::global_dof_index, Point<2>> points;
  DoFTools::map_dofs_to_support_points(MappingQ1<2>(),
                                       discretization.dof_handler(),
                                       points);
  double       error_left = 0, error_line = 0, error_right = 0;
  unsigned int n_line = 0;
  for (const auto i : discretization.locally_owned_dofs())
    {
      const Point<2> &p = points.at(i);
      const double    v = fields[0][i];
      if (std::abs(p[0] - 1000) < 1e-6)
        {
          error_line = std::max(error_line, std::abs(v - interpolant(p)));
          ++n_line;
        }
      else if (p[0] < 1000)
        error_left = std::max(error_left, std::abs(v - interpolant(p)));
      else
        error_right =
          std::max(error_right,
                   std::abs(v - (std::abs(p[0] - 2000) < 1e-6 ? interpolant(p) :
                                                                f(p))));
    }
  const MPI_Comm c = MPI_COMM_WORLD;
  error_left       = Utilities::MPI::max(error_left, c);
  error_line       = Utilities::MPI::max(error_line, c);
  error_right      = Utilities::MPI::max(error_right, c);
  n_line           = Utilities::MPI::sum(n_line, c);
  if (Utilities::MPI::this_mpi_process(c) == 0)
    {
      std::printf("cells: %u refined where x < 2000, %u after coarsening "
                  "and refining again where x < 1000\n",
                  cells_refined,
                  mesh.n_global_active_cells());
      std::printf("x < 1000: the coarse cells' interpolant: %s\n",
                  error_left < 1e-12 ? "yes" : "no");
      std::printf("x = 1000 (%u DoFs, two components): the interpolant, as "
                  "the coarsened mesh's constraints set it: %s\n",
                  n_line,
                  error_line < 1e-12 ? "yes" : "no");
      std::printf("x > 1000: f itself: %s\n",
                  error_right < 1e-12 ? "yes" : "no");
    }
  return 0;
}
