// A box split by the plane y = 500 m with a fault of penalty contact
// and the aging law of rate-and-state friction, its DoFs set up as the
// program does (one displacement field per side), for the tests of the
// fault's set-up and state transfer.
#ifndef rupture_tests_fault_fault_model_h
#define rupture_tests_fault_fault_model_h

#include <rupture/fault/fault.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/numerics/vector_tools.h>

#include <sstream>
#include <string>

using namespace dealii;
using rupture::Fault::Fault;
using VectorType = TrilinosWrappers::MPI::Vector;

namespace tests
{
  /// The displacement of step @p step: zero on the minus side, a slip
  /// along x of @p rate * step * (@p offset + x / 1000 m) on the plus
  /// side.
  template <int dim>
  class Displacement : public Function<dim>
  {
  public:
    Displacement(const unsigned int step,
                 const double       rate,
                 const double       offset)
      : Function<dim>(2 * dim)
      , step(step)
      , rate(rate)
      , offset(offset)
    {}

    double
    value(const Point<dim> &p, const unsigned int component) const override
    {
      return component == dim ? rate * step * (offset + p[0] / 1000) : 0.;
    }

  private:
    unsigned int step;
    double       rate, offset;
  };



  /// A mesh, its DoFs and the fault on it.
  template <int dim>
  struct Model
  {
    Model(ParameterHandler &prm)
      : triangulation(MPI_COMM_WORLD)
      , dof_handler(triangulation)
      , fault(Fault<dim>::create(prm))
    {
      Point<dim>                p0, p1;
      std::vector<unsigned int> n(dim, 4);
      for (unsigned int d = 0; d < dim; ++d)
        p1[d] = 1000;
      GridGenerator::subdivided_hyper_rectangle(triangulation, n, p0, p1);
      fe.push_back(FESystem<dim>(FE_Q<dim>(1), dim, FE_Nothing<dim>(), dim));
      fe.push_back(FESystem<dim>(FE_Nothing<dim>(), dim, FE_Q<dim>(1), dim));
      setup();
    }

    void
    setup()
    {
      dof_handler.reinit(triangulation);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          cell->set_active_fe_index(fault->side(cell));
      dof_handler.distribute_dofs(fe);
      owned = dof_handler.locally_owned_dofs();
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      constraints.clear();
      constraints.reinit(relevant);
      DoFTools::make_hanging_node_constraints(dof_handler, constraints);
      fault->setup(
        dof_handler,
        owned,
        relevant,
        constraints,
        [](const types::material_id,
           const Tensor<1, dim> &,
           const Point<dim> &) {
          return std::array<double, 2>{{3e10, 2670.}};
        },
        MPI_COMM_WORLD);
      constraints.close();
    }

    /// Step @p step (time step 0.01 s): the slip of that step
    /// (Displacement), the contact forces, and the commit. Returns the
    /// contact force.
    VectorType
    step(const unsigned int step,
         const double       rate   = 2e-6,
         const double       offset = 1)
    {
      const double dt = 0.01, t = step * dt;
      VectorType   u(owned, MPI_COMM_WORLD);
      VectorTools::interpolate(dof_handler,
                               Displacement<dim>(step, rate, offset),
                               u);
      VectorType ghosted(owned, relevant, MPI_COMM_WORLD);
      ghosted = u;
      VectorType force(owned, MPI_COMM_WORLD);
      fault->set_time(t);
      fault->assemble(ghosted, dt, constraints, force, constraints, nullptr);
      force.compress(VectorOperation::add);
      fault->commit(dt, t);
      return force;
    }

    std::string
    saved() const
    {
      std::ostringstream out;
      fault->save(out);
      return out.str();
    }

    parallel::distributed::Triangulation<dim> triangulation;
    DoFHandler<dim>                           dof_handler;
    hp::FECollection<dim>                     fe;
    IndexSet                                  owned, relevant;
    AffineConstraints<double>                 constraints;
    std::unique_ptr<Fault<dim>>               fault;
  };



  /// The "Fault" section of the model.
  template <int dim>
  void
  parse_fault_parameters(ParameterHandler &prm)
  {
    Fault<dim>::declare_parameters(prm);
    prm.parse_input_from_string(std::string("subsection Fault\n"
                                            "  set Model = penalty contact\n") +
                                (dim == 2 ?
                                   "  set Plane point = 0, 500\n"
                                   "  set Plane normal = 0, 1\n"
                                   "  set Initial traction = 5e6; -10e6\n" :
                                   "  set Plane point = 0, 500, 0\n"
                                   "  set Plane normal = 0, 1, 0\n"
                                   "  set Initial traction = 5e6; -10e6; 0\n") +
                                "  set Friction law = rate and state\n"
                                "  subsection Rate and state\n"
                                "    set Formulation = regularized\n"
                                "    set Evolution law = aging\n"
                                "    set Initial state = 2e4\n"
                                "  end\n"
                                "end\n");
  }
} // namespace tests

#endif
