// The geometric multigrid preconditioner (Operators::Multigrid) on plain
// elasticity in the unit square and cube, two materials (stiffness ratio
// 4), clamped on one side and loaded by a body force: CG preconditioned by
// one V-cycle (flexible CG) must converge in a number of iterations that stays
// bounded as the mesh is refined (the coarse mesh of 2 cells per direction
// refined 1 to 4 times in 2-D, 1 to 2 times in 3-D), for the quasi-static
// operator K and for the mass-dominated one of an implicit dynamic step, on 1
// and 2 ranks. Block Jacobi alone needs iterations in proportion to the cells
// across the model. The same at degrees 2 to 4 (2-D) and 2 (3-D; degree 3
// on one mesh only, to keep the test short): the levels coarsen in degree
// first, halving it down to 1 on the fine mesh (so Q4 has two levels more
// than Q1 on the same mesh, Q2 and Q3 one), then in h.

#include <rupture/material/elastic_material.h>
#include <rupture/operators/elastic_operator.h>
#include <rupture/operators/multigrid.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <iostream>

using namespace dealii;
using VectorType = LinearAlgebra::distributed::Vector<double>;

namespace
{
  struct Function
  {
    std::function<void(VectorType &, const VectorType &)> f;
    void
    vmult(VectorType &dst, const VectorType &src) const
    {
      f(dst, src);
    }
  };



  template <int dim>
  void
  check(const unsigned int                         refinements,
        const double                               mass_factor,
        const rupture::Material::ElasticMaterials &materials,
        ConditionalOStream                        &out,
        const unsigned int                         degree = 1)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> tria(comm);
    Point<dim>                                upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = 1;
    GridGenerator::subdivided_hyper_rectangle(
      tria, std::vector<unsigned int>(dim, 2), Point<dim>(), upper, true);
    for (auto &cell : tria.active_cell_iterators())
      cell->set_material_id(cell->center()[1] > 0.5 ? 1 : 0);
    tria.refine_global(refinements);

    hp::FECollection<dim> fe(FESystem<dim>(FE_Q<dim>(degree), dim));
    DoFHandler<dim>       dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    AffineConstraints<double> constraints(relevant);
    constraints.close();

    rupture::Operators::ElasticOperator<dim> op;
    op.reinit(MappingQ1<dim>(), dof_handler, constraints, materials, degree);

    typename rupture::Operators::Multigrid<dim>::Description description;
    description.triangulation = &tria;
    description.dof_handler   = &dof_handler;
    description.constraints   = &constraints;
    description.fine_operator = &op;
    description.fe_collection = &fe;
    description.fe_degree     = degree;
    description.materials     = &materials;
    std::array<bool, dim> all;
    all.fill(true);
    description.kinematic_boundaries.emplace_back(0, all);
    rupture::Operators::Multigrid<dim> multigrid;
    multigrid.reinit(description, comm);
    multigrid.set_operator(1., mass_factor, {});

    // Clamped at x = 0 (boundary 0): identity rows there.
    VectorType free, x, b, masked;
    for (VectorType *v : {&free, &x, &b, &masked})
      op.initialize_dof_vector(*v);
    const IndexSet clamped =
      DoFTools::extract_boundary_dofs(dof_handler,
                                      ComponentMask(dim, true),
                                      {0});
    unsigned int i = 0;
    for (const auto dof : dof_handler.locally_owned_dofs())
      {
        free.local_element(i) = clamped.is_element(dof) ? 0. : 1.;
        // A body force, mostly along y.
        b.local_element(i) =
          free.local_element(i) * (dof % dim == 1 ? 1. : 0.1);
        ++i;
      }
    const unsigned int n = free.locally_owned_size();
    const Function     a{[&](VectorType &dst, const VectorType &src) {
      for (unsigned int i = 0; i < n; ++i)
        masked.local_element(i) = src.local_element(i) * free.local_element(i);
      op.vmult(dst, masked, 1., mass_factor);
      for (unsigned int i = 0; i < n; ++i)
        if (free.local_element(i) == 0)
          dst.local_element(i) = src.local_element(i);
    }};
    const Function p{[&](VectorType &dst, const VectorType &src) {
      multigrid.vmult(src.begin(), dst.begin(), free.begin());
    }};
    // The V-cycle's coarse solve is loose: flexible CG.
    SolverControl                control(500, 1e-8 * b.l2_norm());
    SolverFlexibleCG<VectorType> cg(control);
    cg.solve(a, x, b, p);

    // The solution must satisfy the system.
    VectorType r(b), ax(b);
    a.vmult(ax, x);
    r -= ax;
    if (degree > 1)
      out << "Q" << degree << ", ";
    out << dim << "-D, " << refinements << " refinements, "
        << (mass_factor == 0 ? "K" : "K + a0 M") << ": " << dof_handler.n_dofs()
        << " DoFs, " << multigrid.n_levels() << " levels, "
        << control.last_step() << " CG iterations, residual "
        << (r.l2_norm() <= 1e-7 * b.l2_norm() ? "ok" : "too large") << "\n";
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ConditionalOStream               out(std::cout,
                         Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  ParameterHandler                 prm;
  rupture::Material::ElasticMaterials::declare_parameters(prm);
  prm.parse_input_from_string("subsection Material\n"
                              "  set Names = stiff, soft\n"
                              "  set Density = 2670, 2000\n"
                              "  set P-wave speed = 6000, 3000\n"
                              "  set S-wave speed = 3464, 1732\n"
                              "end\n");
  rupture::Material::ElasticMaterials materials;
  materials.parse_parameters(prm);

  // The mass factor a0 = 1 / (beta dt^2) of an average-acceleration
  // Newmark step (beta = 1/4) of dt = 0.05 times the P-wave crossing time
  // of the unit square.
  const double dt = 0.05 / 6000.;
  for (unsigned int r = 1; r <= 4; ++r)
    check<2>(r, 0., materials, out);
  for (unsigned int r = 1; r <= 4; ++r)
    check<2>(r, 4. / (dt * dt), materials, out);
  for (unsigned int r = 1; r <= 2; ++r)
    check<3>(r, 0., materials, out);

  // Degrees 2 to 4: p-coarsening to degree 1, then in h; the iterations
  // must stay bounded as the mesh is refined at each degree.
  for (unsigned int p = 2; p <= 4; ++p)
    {
      for (unsigned int r = 1; r <= 3; ++r)
        check<2>(r, 0., materials, out, p);
      for (unsigned int r = 1; r <= 3; ++r)
        check<2>(r, 4. / (dt * dt), materials, out, p);
    }
  for (unsigned int r = 1; r <= 2; ++r)
    check<3>(r, 0., materials, out, 2);
  check<3>(1, 0., materials, out, 3);
}
