// Discretization::CellWiseFields: fields carried through several meshes as
// each cell's values, without DoFs on the meshes between. A cube of
// [-1, 1]^dim, twice refined, split at x = 0 into two sides with the
// elements of a fault (degree 2 on one side, FE_Nothing on the other, as
// Discretization makes them); three fields: two polynomials of degree 2
// per component (the elements hold them exactly) and one zero field (left
// out of every cell's values). The mesh is then
// - refined where y < -1/2 and coarsened where y > 0 (one mesh),
// - refined again where y < -3/4 (a second mesh),
// - partitioned again with its cells weighed by their level (a third),
// and only then are DoFs distributed and the fields written: each must be
// its polynomial on the final mesh (the values of deal.II's interpolation,
// to round-off), the zero field zero, and the hanging constraints must
// hold without being distributed. In 2-D and 3-D.

#include <rupture/discretization/cell_wise_fields.h>

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/numerics/vector_tools.h>

#include <cstdio>
#include <vector>

using namespace dealii;
using Field = LinearAlgebra::distributed::Vector<double>;

namespace
{
  /// Component c of side s: a polynomial of degree 2 in every coordinate
  /// (times @p scale; zero on the other side's components).
  template <int dim>
  class Polynomial : public Function<dim>
  {
  public:
    explicit Polynomial(const double scale)
      : Function<dim>(2 * dim)
      , scale(scale)
    {}

    double
    value(const Point<dim> &p, const unsigned int component) const override
    {
      const unsigned int c = component % dim;
      const double       s = component < dim ? 1. : -2.;
      double             v = s * (1 + c) * (p[0] * p[1] + 0.5 * p[0] * p[0]);
      if (dim == 3)
        v += p[2] * p[2] * p[1] - 0.25 * c * p[2];
      return scale * v;
    }

  private:
    const double scale;
  };



  template <int dim>
  void
  flag(parallel::distributed::Triangulation<dim> &mesh,
       const double                               refine_below,
       const double                               coarsen_above)
  {
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (cell->center()[1] < refine_below)
            cell->set_refine_flag();
          else if (cell->center()[1] > coarsen_above)
            cell->set_coarsen_flag();
        }
  }



  template <int dim>
  void
  check()
  {
    const MPI_Comm                            communicator = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> mesh(
      communicator, Triangulation<dim>::limit_level_difference_at_vertices);
    GridGenerator::hyper_cube(mesh, -1, 1);
    mesh.refine_global(2);
    hp::FECollection<dim> elements;
    elements.push_back(
      FESystem<dim>(FE_Q<dim>(2), dim, FE_Nothing<dim>(), dim));
    elements.push_back(
      FESystem<dim>(FE_Nothing<dim>(), dim, FE_Q<dim>(2), dim));
    DoFHandler<dim> dofs(mesh);
    const auto      distribute = [&]() {
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          cell->set_active_fe_index(cell->center()[0] > 0 ? 1 : 0);
      dofs.distribute_dofs(elements);
    };
    distribute();
    const auto make_fields = [&](std::vector<Field> &fields) {
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dofs, relevant);
      for (unsigned int k = 0; k < fields.size(); ++k)
        {
          fields[k].reinit(dofs.locally_owned_dofs(), relevant, communicator);
          VectorTools::interpolate(dofs,
                                   Polynomial<dim>(k == 0 ? 1. :
                                                   k == 1 ? 3. :
                                                            0.),
                                   fields[k]);
          fields[k].update_ghost_values();
        }
    };
    std::vector<Field> fields(3);
    make_fields(fields);
    std::vector<Field *> pointers;
    for (auto &f : fields)
      pointers.push_back(&f);
    const unsigned int cells_before = mesh.n_global_active_cells();

    rupture::Discretization::CellWiseFields<dim> carried(dofs,
                                                         elements,
                                                         pointers,
                                                         mesh);
    flag(mesh, -0.5, 0.);
    carried.attach();
    mesh.execute_coarsening_and_refinement();
    carried.unpack();
    const unsigned int cells_first = mesh.n_global_active_cells();
    flag(mesh, -0.75, 2.);
    carried.attach();
    mesh.execute_coarsening_and_refinement();
    carried.unpack();
    const unsigned int cells_second = mesh.n_global_active_cells();
    const auto         weigh        = mesh.signals.weight.connect(
      [](const typename Triangulation<dim>::cell_iterator &cell,
         const typename Triangulation<dim>::CellStatus) -> unsigned int {
        return 1 + 10 * cell->level();
      });
    carried.attach();
    mesh.repartition();
    carried.unpack();
    weigh.disconnect();

    distribute();
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    std::vector<Field> written(3);
    for (auto &w : written)
      w.reinit(dofs.locally_owned_dofs(), relevant, communicator);
    std::vector<Field *> out;
    for (auto &w : written)
      out.push_back(&w);
    carried.write(dofs, out);
    std::vector<Field> exact(3);
    make_fields(exact);

    AffineConstraints<double> hanging(relevant);
    DoFTools::make_hanging_node_constraints(dofs, hanging);
    hanging.close();
    double largest = 0, differences[3] = {0, 0, 0}, constraint_error = 0;
    for (unsigned int k = 0; k < 3; ++k)
      {
        largest = std::max(largest, exact[k].linfty_norm());
        Field d(exact[k]);
        d -= written[k];
        differences[k] = d.linfty_norm();
        // A hanging DoF of the written field against its constraint.
        written[k].update_ghost_values();
        for (const auto i : dofs.locally_owned_dofs())
          if (hanging.is_constrained(i))
            {
              double v = hanging.get_inhomogeneity(i);
              for (const auto &[j, w] : *hanging.get_constraint_entries(i))
                v += w * written[k](j);
              constraint_error =
                std::max(constraint_error, std::abs(v - written[k](i)));
            }
      }
    largest          = Utilities::MPI::max(largest, communicator);
    constraint_error = Utilities::MPI::max(constraint_error, communicator);
    for (auto &d : differences)
      d = Utilities::MPI::max(d, communicator);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::printf("%d-D: cells %u -> %u -> %u (partitioned again: %u)\n",
                    dim,
                    cells_before,
                    cells_first,
                    cells_second,
                    mesh.n_global_active_cells());
        std::printf("  largest value %.4g; written against the polynomials: "
                    "first field %s, second %s, zero field exactly zero: %s\n",
                    largest,
                    differences[0] < 1e-13 * largest ? "equal" : "DIFFERENT",
                    differences[1] < 1e-13 * largest ? "equal" : "DIFFERENT",
                    differences[2] == 0 ? "yes" : "no");
        std::printf("  hanging DoFs follow their constraints: %s\n",
                    constraint_error < 1e-13 * largest ? "yes" : "no");
      }
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>();
  check<3>();
  return 0;
}
