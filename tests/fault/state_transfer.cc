// The fault's state carried to a globally refined copy of the mesh and
// back (Fault::state_fields(), deal.II's SolutionTransfer,
// Fault::interpolate_new_pairs()), in 2-D and 3-D, on one process and on
// two. The model of fault_model.h takes three steps in the dynamic phase
// with a slip of 2e-5 m * step * x / 1000 m: the pairs with x > 500 m
// slip faster than 1 mm/s and rupture. Checked on the refined mesh:
// - the old nodes keep their state value by value;
// - a new node's slip is the slip of the old nodes interpolated along the
//   fault faces: the slip, linear in x, is that of its location, and its
//   log10(theta) is the mean of those of the old nodes nearest to it (2
//   at the middle of an edge, 4 at the centre of a face);
// - rupture time: an old node keeps its own; a new node next to a
//   ruptured old one has an unknown rupture time (-2), the others have
//   not ruptured (-1).
// Coarsened back to the first mesh, the saved state (the bytes of
// Fault::save()) is that before the refinement.

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>

#include "fault_model.h"

#include <cstdio>
#include <map>

namespace
{

  /// Carry the fault's state of @p model across the mesh change
  /// @p change (refinement or coarsening) and set up again.
  template <int dim, typename Change>
  unsigned int
  change_mesh(tests::Model<dim> &model, const Change &change)
  {
    const auto              fields = model.fault->state_fields(model.owned);
    std::vector<VectorType> ghosted;
    for (const auto &f : fields)
      {
        ghosted.emplace_back(model.owned, model.relevant, MPI_COMM_WORLD);
        ghosted.back() = f;
      }
    std::vector<const VectorType *> in;
    for (const auto &g : ghosted)
      in.push_back(&g);
    parallel::distributed::SolutionTransfer<dim, VectorType> transfer(
      model.dof_handler);
    transfer.prepare_for_coarsening_and_refinement(in);
    change(model.triangulation);
    model.setup();
    std::vector<VectorType>   moved(fields.size());
    std::vector<VectorType *> out;
    for (auto &m : moved)
      {
        m.reinit(model.owned, MPI_COMM_WORLD);
        out.push_back(&m);
      }
    transfer.interpolate(out);
    return model.fault->interpolate_new_pairs(moved);
  }



  template <int dim>
  void
  check()
  {
    ParameterHandler prm;
    tests::parse_fault_parameters<dim>(prm);
    tests::Model<dim> model(prm);
    model.fault->start_dynamic_phase(0);
    for (unsigned int s = 1; s <= 3; ++s)
      model.step(s, 2e-5, 0);
    const std::string saved  = model.saved();
    const auto        coarse = model.fault->gather();

    const unsigned int n_without =
      change_mesh(model, [](auto &tria) { tria.refine_global(1); });
    const auto fine = model.fault->gather();
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        using R = typename Fault<dim>::NodeRecord;
        std::map<std::vector<double>, const R *> old;
        for (const auto &r : coarse)
          old[std::vector<double>(r.location.begin_raw(),
                                  r.location.end_raw())] = &r;
        unsigned int n_old = 0, n_kept = 0, n_new = 0, n_slip = 0, n_theta = 0,
                     n_unknown = 0, n_not = 0, n_time = 0;
        double max_slip_error = 0, max_theta_error = 0;
        for (const auto &r : fine)
          {
            const auto at = old.find(std::vector<double>(r.location.begin_raw(),
                                                         r.location.end_raw()));
            if (at != old.end())
              {
                const R &o = *at->second;
                ++n_old;
                n_kept +=
                  (o.slip == r.slip && o.slip_velocity == r.slip_velocity &&
                   o.traction == r.traction && o.slip_path == r.slip_path &&
                   o.rupture_time == r.rupture_time &&
                   o.state_values == r.state_values);
                continue;
              }
            ++n_new;
            const double slip       = 2e-5 * 3 * r.location[0] / 1000;
            const double slip_error = std::abs(r.slip[0] - slip);
            max_slip_error          = std::max(max_slip_error, slip_error);
            n_slip += slip_error <= 1e-12 * 6e-5;
            // The old nodes nearest to this one.
            double nearest = 1e300;
            for (const auto &o : coarse)
              nearest = std::min(nearest, o.location.distance(r.location));
            double       mean     = 0;
            unsigned int n        = 0;
            bool         ruptured = false;
            for (const auto &o : coarse)
              if (o.location.distance(r.location) < nearest * (1 + 1e-9))
                {
                  mean += o.state_values[0];
                  ++n;
                  ruptured = ruptured || o.rupture_time >= 0;
                }
            mean /= n;
            const double theta_error = std::abs(r.state_values[0] - mean);
            max_theta_error          = std::max(max_theta_error, theta_error);
            n_theta += theta_error <= 1e-12 * std::abs(mean);
            const double expected = ruptured ? -2 : -1;
            n_time += (r.rupture_time == expected);
            n_unknown += (r.rupture_time == -2);
            n_not += (r.rupture_time == -1);
          }
        std::printf("%d-D: %zu coarse pairs, %zu fine pairs, %u without an "
                    "old pair near\n",
                    dim,
                    coarse.size(),
                    fine.size(),
                    n_without);
        std::printf("  old nodes: %u, state kept %u\n", n_old, n_kept);
        std::printf("  new nodes: %u; slip = that of the location %u "
                    "(largest error %.1e m); log10(theta) = mean of the "
                    "nearest old nodes %u (largest error %.1e); rupture "
                    "time as expected %u (unknown %u, not ruptured %u)\n",
                    n_new,
                    n_slip,
                    max_slip_error,
                    n_theta,
                    max_theta_error,
                    n_time,
                    n_unknown,
                    n_not);
      }

    // And back to the first mesh.
    const unsigned int n_without_back = change_mesh(model, [](auto &tria) {
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          cell->set_coarsen_flag();
      tria.execute_coarsening_and_refinement();
    });
    const bool         same =
      Utilities::MPI::min(model.saved() == saved ? 1 : 0, MPI_COMM_WORLD) == 1;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::printf("  coarsened back: %u new pairs, %u without an old pair "
                  "near, saved state as before the refinement: %s\n",
                  model.fault->n_new_pairs(),
                  n_without_back,
                  same ? "yes" : "no");
  }
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>();
  check<3>();
}
