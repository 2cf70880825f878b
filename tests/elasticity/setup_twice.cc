// The elastic system can be set up and assembled again
// (Elasticity::System): a box split by a penalty fault at y = 500 m, Q2 in
// 2-D and Q1 in 3-D, one global refinement and one more level where
// x < 300 m, held at its bottom, with absorbing east and west sides,
// gravity and a traction on its top, Rayleigh damping and a damped fault
// zone, on one process and on two, with the stiffness matrix-free (the
// effective stiffness then keeps its diagonal) and stored (the effective
// stiffness is then a stored matrix with its algebraic preconditioner).
// - Set up and assembled again on the same mesh (after the DoFs were set
//   up again): K x, M x, the damping force, the dashpots' force, the
//   effective stiffness (its diagonal, or its product) and the load are
//   the same to the last bit.
// - The stored and the matrix-free stiffness and mass agree (K x and M x
//   at the DoFs that are not tied, to the digits printed).

#include <rupture/discretization/discretization.h>
#include <rupture/elasticity/system.h>
#include <rupture/fault/fault.h>
#include <rupture/material/elastic_material.h>
#include <rupture/scene/boundary_conditions.h>
#include <rupture/scene/scene.h>
#include <rupture/simulator/simulator.h>
#include <rupture/solver/linear_solver.h>
#include <rupture/time_integration/time_state.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/vector_tools.h>

#include "discretization/setup_dofs.h"

#include <cstdio>
#include <string>
#include <vector>

using namespace dealii;
using VectorType = TrilinosWrappers::MPI::Vector;

namespace
{
  /// A smooth field with a jump across the fault (both sides' components).
  template <int dim>
  class Field : public Function<dim>
  {
  public:
    Field()
      : Function<dim>(2 * dim)
    {}
    double
    value(const Point<dim> &p, const unsigned int c) const override
    {
      return 1e-3 * std::sin(0.002 * p[0] + c) * std::cos(0.003 * p[1]) +
             (c >= dim ? 1e-4 : 0.);
    }
  };

  const char *
  yes(const bool b)
  {
    return Utilities::MPI::min(b ? 1 : 0, MPI_COMM_WORLD) == 1 ? "yes" : "no";
  }



  template <int dim>
  void
  check(const std::string &stiffness_operator)
  {
    ParameterHandler prm;
    rupture::Simulator<dim>::declare_parameters(prm);
    const std::string d2 = dim == 2 ? "" : ", 0";
    prm.parse_input_from_string(
      "subsection Scene\n"
      "  set Model = box\n"
      "  subsection Box\n"
      "    set Lower corner = 0, 0" +
      d2 + "\n    set Upper corner = 1000, 1000" +
      std::string(dim == 2 ? "" : ", 250") +
      "\n    set Number of cells = 4, 4" + std::string(dim == 2 ? "" : ", 1") +
      "\n  end\nend\n"
      "subsection Fault\n"
      "  set Model = penalty contact\n"
      "  set Plane point = 0, 500" +
      d2 + "\n  set Plane normal = 0, 1" + d2 +
      "\n  set Initial traction = 5e6; -10e6" +
      std::string(dim == 2 ? "" : "; 0") +
      "\nend\n"
      "subsection Boundary conditions\n"
      "  set Fixed = bottom\n"
      "  set Absorbing = east, west\n"
      "  set Traction = top: 0; -1e6" +
      std::string(dim == 2 ? "" : "; 0") +
      "\nend\n"
      "subsection Discretization\n"
      "  set Initial global refinement = 1\n"
      "  set Refinement region = x < 300 ? 1 : 0\n"
      "  set Refinement region levels = 1\n"
      "  set Polynomial degree = " +
      std::string(dim == 2 ? "2" : "1") +
      "\n"
      "  set Stiffness operator = " +
      stiffness_operator +
      "\nend\n"
      "subsection Damping\n"
      "  set Rayleigh alpha = 0.5\n"
      "  set Rayleigh beta = 1e-3\n"
      "  set Fault zone damping = 0.2\n"
      "end\n"
      "subsection Loads\n"
      "  set Gravity = 9.81\n"
      "end\n"
      "subsection Time integration\n"
      "  set Scheme = implicit Newmark\n"
      "end\n"
      "subsection Solver\n"
      "  set Preconditioner = " +
      std::string(stiffness_operator == "matrix" ? "AMG" : "block Jacobi") +
      "\nend\n");
    const auto scene = rupture::Scene::create<dim>(prm);
    rupture::Material::ElasticMaterials materials;
    materials.parse_parameters(prm);
    const auto fault = rupture::Fault::Fault<dim>::create(prm);
    rupture::Scene::BoundaryConditions<dim> boundary_conditions;
    boundary_conditions.parse_parameters(prm, scene->get_boundary_names());
    rupture::TimeIntegration::Parameters time_parameters;
    time_parameters.parse_parameters(prm);
    rupture::Solver::LinearSolver linear_solver;
    linear_solver.parse_parameters(prm);
    rupture::TimeIntegration::TimeState state;
    state.time_step = 0.01;

    rupture::Discretization::Discretization<dim> discretization(MPI_COMM_WORLD);
    prm.enter_subsection("Discretization");
    discretization.parse_parameters(prm);
    prm.leave_subsection();
    discretization.set_fault(fault.get());
    ConditionalOStream silent(std::cout, false);
    TimerOutput        timer(MPI_COMM_SELF,
                      silent,
                      TimerOutput::never,
                      TimerOutput::wall_times);
    discretization.make_mesh(*scene, materials, "", silent);

    rupture::Elasticity::System<dim> system(discretization,
                                            materials,
                                            boundary_conditions,
                                            time_parameters,
                                            state,
                                            linear_solver,
                                            timer,
                                            silent,
                                            MPI_COMM_WORLD);
    system.parse_parameters(prm, true);
    system.set_fault(fault.get());
    system.set_scheme(rupture::TimeIntegration::Scheme::implicit_newmark);

    // The products of a set-up, as vectors of this process's entries.
    const auto products = [&]() {
      tests::setup_dofs(discretization,
                        *fault,
                        boundary_conditions,
                        materials.get(0).mu);
      system.setup();
      system.assemble();
      const double dt = state.time_step;
      system.set_effective_stiffness(1 + 1e-3 / dt,
                                     4 / (dt * dt) + 0.5 * 2 / dt,
                                     2 / dt);
      const IndexSet &owned = discretization.locally_owned_dofs();
      VectorType      x(owned, MPI_COMM_WORLD), y(x);
      VectorTools::interpolate(discretization.dof_handler(), Field<dim>(), x);
      discretization.distribute_hanging(x);
      std::vector<std::vector<double>> result;
      const auto                       keep = [&](const VectorType &v) {
        result.emplace_back(v.begin(), v.end());
      };
      // At tied DoFs the stored matrices have placeholder rows: compared
      // at the others.
      const auto &tied = discretization.hanging_constraints();
      system.apply_stiffness(x, y);
      tied.set_zero(y);
      keep(y);
      system.apply_mass(x, y);
      tied.set_zero(y);
      keep(y);
      system.damping_force(x, y);
      keep(y);
      system.absorbing_force(x, y);
      keep(y);
      if (stiffness_operator == "matrix")
        system.effective_matrix().vmult(y, x);
      else
        y = system.effective_diagonal();
      keep(y);
      keep(system.load(0));
      return result;
    };
    const auto          first  = products();
    const auto          second = products();
    const char         *same   = yes(first == second);
    std::vector<double> norms;
    for (const auto &v : first)
      {
        double s = 0;
        for (const double a : v)
          s += a * a;
        norms.push_back(std::sqrt(Utilities::MPI::sum(s, MPI_COMM_WORLD)));
      }
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("%d-D, stiffness %s: %u DoFs; set up and assembled again: "
                  "identical %s; |K x| %.5e, |M x| %.5e, |C x| %.6e, "
                  "|C_abs x| %.6e, |A x| or |diag A| %.6e, |f| %.6e\n",
                  dim,
                  stiffness_operator.c_str(),
                  static_cast<unsigned int>(
                    discretization.dof_handler().n_dofs()),
                  same,
                  norms[0],
                  norms[1],
                  norms[2],
                  norms[3],
                  norms[4],
                  norms[5]);
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const std::string op : {"matrix free", "matrix"})
    {
      check<2>(op);
      check<3>(op);
    }
}
