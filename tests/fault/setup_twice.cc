// The fault's set-up can be repeated, and a node pair's state belongs to
// its location (Fault::setup(), LocationIndex), in 2-D and 3-D, on one
// process and on two. A box split by the plane y = 500 m, penalty contact
// with the aging law of rate-and-state friction; the plus side is moved
// along x by a slip that grows over the steps and with x.
// - Set up again on the same mesh after three steps: no pair is new, the
//   saved state (the bytes of Fault::save()) is that before, and a fourth
//   step gives the same state and contact force, to the last bit, as a
//   fault that took four steps with one set-up.
// - Set up again after a global refinement (the DoFs are numbered anew):
//   the pairs at the old nodes keep their state (compared value by value
//   with the records of the coarse mesh) and only the new nodes between
//   them start from the initial state.

#include <rupture/fault/fault.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/numerics/vector_tools.h>

#include <cstdio>
#include <map>
#include <sstream>

using namespace dealii;
using rupture::Fault::Fault;
using VectorType = TrilinosWrappers::MPI::Vector;

namespace
{
  /// The displacement of step @p step: zero on the minus side, a slip
  /// along x on the plus side.
  template <int dim>
  class Displacement : public Function<dim>
  {
  public:
    explicit Displacement(const unsigned int step)
      : Function<dim>(2 * dim)
      , step(step)
    {}

    double
    value(const Point<dim> &p, const unsigned int component) const override
    {
      return component == dim ? 2e-6 * step * (1 + p[0] / 1000) : 0.;
    }

  private:
    unsigned int step;
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
      fault->setup(dof_handler,
                   owned,
                   relevant,
                   constraints,
                   std::vector<double>(1, 3e10),
                   MPI_COMM_WORLD);
      constraints.close();
    }

    /// Step @p step (time step 0.01 s): the slip of that step, the
    /// contact forces, and the commit. Returns the contact force.
    VectorType
    step(const unsigned int step)
    {
      const double dt = 0.01, t = step * dt;
      VectorType   u(owned, MPI_COMM_WORLD);
      VectorTools::interpolate(dof_handler, Displacement<dim>(step), u);
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



  bool
  on_all(const bool b)
  {
    return Utilities::MPI::min(b ? 1 : 0, MPI_COMM_WORLD) == 1;
  }

  const char *
  yes(const bool b)
  {
    return b ? "yes" : "no";
  }



  template <int dim>
  void
  check()
  {
    ParameterHandler prm;
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

    Model<dim> once(prm), twice(prm);
    for (unsigned int s = 1; s <= 3; ++s)
      {
        once.step(s);
        twice.step(s);
      }
    const std::string before = twice.saved();
    twice.setup();
    const bool same_state = on_all(twice.saved() == before);
    const auto f_once     = once.step(4);
    const auto f_twice    = twice.step(4);
    bool       same_force = true;
    for (const auto i : once.owned)
      same_force = same_force && f_once(i) == f_twice(i);
    same_force                     = on_all(same_force);
    const bool         same_fourth = on_all(once.saved() == twice.saved());
    const auto         statistics  = twice.fault->statistics();
    const auto         records     = twice.fault->gather();
    const unsigned int n_old       = twice.fault->n_split_nodes();
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("%d-D: %u pairs; set up again: new pairs %u, saved state "
                  "unchanged %s; after a fourth step: state identical %s, "
                  "contact force identical %s, %u slipping, max slip "
                  "%.6e m, max slip rate %.6e m/s\n",
                  dim,
                  n_old,
                  twice.fault->n_new_pairs(),
                  yes(same_state),
                  yes(same_fourth),
                  yes(same_force),
                  statistics.n_slipping,
                  statistics.max_slip,
                  statistics.max_slip_rate);

    // A global refinement: new DoF numbers, new nodes between the old.
    twice.triangulation.refine_global(1);
    twice.setup();
    const unsigned int n_new = twice.fault->n_new_pairs();
    const auto         fine  = twice.fault->gather();
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::map<std::vector<double>, const typename Fault<dim>::NodeRecord *>
          at;
        for (const auto &r : fine)
          at[std::vector<double>(r.location.begin_raw(),
                                 r.location.end_raw())] = &r;
        unsigned int n_found = 0, n_equal = 0;
        for (const auto &r : records)
          {
            const auto f = at.find(std::vector<double>(r.location.begin_raw(),
                                                       r.location.end_raw()));
            if (f == at.end())
              continue;
            ++n_found;
            const auto &g = *f->second;
            n_equal +=
              (g.slip == r.slip && g.slip_velocity == r.slip_velocity &&
               g.traction == r.traction && g.slip_path == r.slip_path &&
               g.rupture_time == r.rupture_time &&
               g.state_values == r.state_values);
          }
        std::printf("%d-D refined: %u pairs, %u new (fine minus coarse "
                    "pairs: %u); coarse nodes found %u of %zu, their state "
                    "kept %u\n",
                    dim,
                    twice.fault->n_split_nodes(),
                    n_new,
                    twice.fault->n_split_nodes() - n_old,
                    n_found,
                    records.size(),
                    n_equal);
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
