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

#include <deal.II/base/mpi.h>

#include "fault_model.h"

#include <cstdio>
#include <map>

namespace
{
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
    tests::parse_fault_parameters<dim>(prm);

    tests::Model<dim> once(prm), twice(prm);
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
