// The discretization can be set up again (Discretization::Discretization):
// a box split by a fault at y = 500 m, Q2, one global refinement and one
// more level where x < 300 m (so the fault has hanging nodes), held at
// its bottom and rolled at its west side, in 2-D and 3-D, on one process
// and on two.
// - Every active cell of the mesh just made is at its base level (the
//   level that the adaptation never coarsens below).
// - distribute_dofs() and make_constraints() again on the same mesh give
//   the same DoFs and, line by line and entry by entry, the same hanging,
//   welded and kinematic constraints, and the same prescribed motion.
// - After a global refinement the DoFs are set up anew for the finer mesh
//   and every cell is one level above its base level.
// - Two more levels in the second row of cells above the fault (x > 750 m)
//   make the mesh's level balance refine the first row, on the plus side
//   only: flag_fault_alike() finds the cells across from it, and after
//   their refinement both sides of every fault face are alike again and
//   the fault can be set up.

#include <rupture/discretization/discretization.h>
#include <rupture/fault/fault.h>
#include <rupture/material/elastic_material.h>
#include <rupture/scene/boundary_conditions.h>
#include <rupture/scene/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include "discretization/setup_dofs.h"

#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

using namespace dealii;
using rupture::Discretization::Discretization;

namespace
{
  using Line =
    std::tuple<types::global_dof_index,
               std::vector<std::pair<types::global_dof_index, double>>,
               double>;

  /// The lines of @p constraints at the DoFs this process owns.
  std::vector<Line>
  lines(const AffineConstraints<double> &constraints, const IndexSet &owned)
  {
    std::vector<Line> result;
    for (const auto i : owned)
      if (constraints.is_constrained(i))
        {
          const auto *entries = constraints.get_constraint_entries(i);
          result.emplace_back(
            i,
            entries ? *entries :
                      std::vector<std::pair<types::global_dof_index, double>>(),
            constraints.get_inhomogeneity(i));
        }
    return result;
  }

  unsigned int
  sum(const std::size_t n)
  {
    return Utilities::MPI::sum(static_cast<unsigned int>(n), MPI_COMM_WORLD);
  }

  const char *
  yes(const bool b)
  {
    return Utilities::MPI::min(b ? 1 : 0, MPI_COMM_WORLD) == 1 ? "yes" : "no";
  }



  template <int dim>
  struct Setup
  {
    types::global_dof_index n_dofs;
    std::vector<Line>       hanging, increments;
    std::vector<double>     motion;
    unsigned int            n_welded, n_split;
  };



  template <int dim>
  void
  check()
  {
    ParameterHandler prm;
    rupture::Scene::declare_parameters(prm);
    rupture::Material::ElasticMaterials::declare_parameters(prm);
    rupture::Fault::Fault<dim>::declare_parameters(prm);
    rupture::Scene::BoundaryConditions<dim>::declare_parameters(prm);
    prm.enter_subsection("Discretization");
    Discretization<dim>::declare_parameters(prm);
    prm.leave_subsection();
    const std::string zeros = dim == 2 ? "0, 0" : "0, 0, 0";
    prm.parse_input_from_string(
      "subsection Scene\n"
      "  set Model = box\n"
      "  subsection Box\n"
      "    set Lower corner = " +
      zeros +
      "\n"
      "    set Upper corner = " +
      std::string(dim == 2 ? "1000, 1000" : "1000, 1000, 1000") +
      "\n"
      "    set Number of cells = " +
      std::string(dim == 2 ? "4, 4" : "4, 4, 1") +
      "\n"
      "  end\n"
      "end\n"
      "subsection Fault\n"
      "  set Model = traction at split nodes\n"
      "  set Plane point = " +
      std::string(dim == 2 ? "0, 500" : "0, 500, 0") +
      "\n"
      "  set Plane normal = " +
      std::string(dim == 2 ? "0, 1" : "0, 1, 0") +
      "\n"
      "  set Initial traction = " +
      std::string(dim == 2 ? "5e6; -10e6" : "5e6; -10e6; 0") +
      "\n"
      "end\n"
      "subsection Boundary conditions\n"
      "  set Fixed = bottom\n"
      "  set Roller = west: x\n"
      "  set Prescribed velocity = east: 1e-9 * y; 0" +
      std::string(dim == 2 ? "" : "; 0") +
      "\n"
      "end\n"
      "subsection Discretization\n"
      "  set Initial global refinement = 1\n"
      "  set Refinement region = x < 300 ? 1 : 0\n"
      "  set Refinement region levels = 1\n"
      "  set Polynomial degree = 2\n"
      "end\n");
    const auto scene = rupture::Scene::create<dim>(prm);
    rupture::Material::ElasticMaterials materials;
    materials.parse_parameters(prm);
    const auto fault = rupture::Fault::Fault<dim>::create(prm);
    rupture::Scene::BoundaryConditions<dim> boundary_conditions;
    boundary_conditions.parse_parameters(prm, scene->get_boundary_names());

    Discretization<dim> discretization(MPI_COMM_WORLD);
    prm.enter_subsection("Discretization");
    discretization.parse_parameters(prm);
    prm.leave_subsection();
    discretization.set_fault(fault.get());
    ConditionalOStream silent(std::cout, false);
    discretization.make_mesh(*scene, materials, "", silent);

    const auto setup = [&]() {
      tests::setup_dofs(discretization, *fault, boundary_conditions, 3e10);
      const IndexSet &owned = discretization.locally_owned_dofs();
      Setup<dim>      s;
      s.n_dofs     = discretization.dof_handler().n_dofs();
      s.hanging    = lines(discretization.hanging_constraints(), owned);
      s.increments = lines(discretization.increment_constraints(), owned);
      TrilinosWrappers::MPI::Vector u(owned, MPI_COMM_WORLD), v(u);
      discretization.set_kinematic_velocity(v, 0.5);
      discretization.impose_kinematic_motion(v, u, 1, 0.25);
      s.motion.assign(u.begin(), u.end());
      s.n_welded = fault->n_welded_nodes();
      s.n_split  = fault->n_split_nodes();
      return s;
    };

    const auto &mesh     = discretization.triangulation();
    const auto  at_level = [&](const int offset) {
      bool all = true;
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->is_locally_owned())
          all = all &&
                cell->level() == int(discretization.base_level(cell)) + offset;
      return yes(all);
    };
    const auto  first  = setup();
    const char *base   = at_level(0);
    const auto  second = setup();
    const auto  held   = discretization.held_components();
    std::string held_text;
    for (unsigned int c = 0; c < dim; ++c)
      held_text +=
        (Utilities::MPI::max(held[c] ? 1 : 0, MPI_COMM_WORLD) ? "xyz"[c] : '-');
    const unsigned int n_cells     = mesh.n_global_active_cells();
    const char        *same_lines  = yes(first.hanging == second.hanging &&
                                 first.increments == second.increments);
    const char        *same_motion = yes(first.motion == second.motion);
    const auto         n_hanging   = sum(first.hanging.size());
    const auto         n_increment = sum(first.increments.size());

    discretization.triangulation().refine_global(1);
    const auto  fine       = setup();
    const char *fine_level = at_level(1);

    // Whether the cells on the two sides of every fault face are alike.
    const auto alike = [&]() {
      bool all = true;
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto f : cell->face_indices())
            if (!cell->at_boundary(f) &&
                fault->side(cell->neighbor(f)) != fault->side(cell))
              all = all && !cell->neighbor(f)->has_children() &&
                    cell->neighbor(f)->level() == cell->level();
      return yes(all);
    };
    // The second row above the fault where x > 750 m (62.5 m cells).
    for (unsigned int k = 0; k < 2; ++k)
      {
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->is_locally_owned() && cell->center()[0] > 750 &&
              cell->center()[1] > 562.5 && cell->center()[1] < 625)
            cell->set_refine_flag();
        discretization.triangulation().execute_coarsening_and_refinement();
      }
    const char  *before_repair = alike();
    unsigned int n_passes      = 0;
    while (discretization.flag_fault_alike())
      {
        discretization.triangulation().execute_coarsening_and_refinement();
        ++n_passes;
      }
    const char *after_repair = alike();
    const auto  repaired     = setup();
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::printf("%d-D: %u cells, every cell at its base level %s; %u "
                    "DoFs, %u split pairs, %u welded nodes; constraint lines "
                    "(owned, summed over processes): hanging and welded "
                    "%u, with the kinematic ones %u; held components %s\n",
                    dim,
                    n_cells,
                    base,
                    static_cast<unsigned int>(first.n_dofs),
                    first.n_split,
                    first.n_welded,
                    n_hanging,
                    n_increment,
                    held_text.c_str());
        std::printf("%d-D set up again: DoFs %u, same constraints %s, same "
                    "prescribed motion %s\n",
                    dim,
                    static_cast<unsigned int>(second.n_dofs),
                    same_lines,
                    same_motion);
        std::printf("%d-D refined globally: %u DoFs, every cell one level "
                    "above its base %s\n",
                    dim,
                    static_cast<unsigned int>(fine.n_dofs),
                    fine_level);
        std::printf("%d-D two levels more in the second row above the "
                    "fault: both sides alike %s; after %u pass(es) of "
                    "flag_fault_alike(): alike %s, %u DoFs, %u split pairs\n",
                    dim,
                    before_repair,
                    n_passes,
                    after_repair,
                    static_cast<unsigned int>(repaired.n_dofs),
                    repaired.n_split);
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>();
  check<3>();
}
