// A new mesh during the run: refine and coarsen as flagged, both sides of
// the fault alike, and carry fields to the new DoFs (deal.II's
// SolutionTransfer).

#include <rupture/discretization/discretization.h>

#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <algorithm>
#include <memory>

namespace rupture
{
  namespace Discretization
  {
    template <int dim>
    void
    Discretization<dim>::refine(std::vector<VectorType>     &fields,
                                const unsigned int           max_alike_rounds,
                                const std::function<bool()> &reflag,
                                const std::function<void()> &setup,
                                TimerOutput                 &timer)
    {
      // The transfer reads and writes every DoF of every cell: through
      // deal.II's own vectors (direct indexing), not Trilinos' (a map
      // lookup per entry), several times faster.
      timer.enter_subsection("Refinement: attach");
      using Distributed = LinearAlgebra::distributed::Vector<double>;
      std::vector<Distributed>         values(fields.size());
      std::vector<const Distributed *> in;
      for (unsigned int k = 0; k < fields.size(); ++k)
        {
          values[k].reinit(owned, relevant, mpi_communicator);
          std::copy(fields[k].begin(), fields[k].end(), values[k].begin());
          values[k].update_ghost_values();
          in.push_back(&values[k]);
        }
      using Transfer =
        parallel::distributed::SolutionTransfer<dim, Distributed>;
      auto transfer = std::make_unique<Transfer>(dofs);
      transfer->prepare_for_coarsening_and_refinement(in);
      timer.leave_subsection();
      timer.enter_subsection("Refinement: new mesh");
      mesh.execute_coarsening_and_refinement();
      // The fields go on through every mesh that is not yet the final one,
      // on its DoFs alone (its fault and operators are not set up):
      // - the mesh's balance (p4est's, which sees all processes) may have
      //   refined or coarsened a cell on one side of the fault only, and
      //   the fault's node pairs need both sides alike: the cells that lack
      //   a level are refined;
      // - @p reflag flags the next level of this adaptation;
      // - with <Fault cell weight>, the final mesh is partitioned once more
      //   with every cell's own weight if its partition leaves the largest
      //   rank's weight more than 5 % above the mean (p4est weighs the
      //   children of a cell it refines alike, so the partition it made
      //   with the refinement balances the fault's cells only in part; a
      //   round costs as much as a level of refinement).
      const auto go_on = [&](const bool repartition) {
        distribute_dofs();
        std::vector<Distributed *> here;
        for (auto &v : values)
          {
            v.reinit(owned, relevant, mpi_communicator);
            here.push_back(&v);
          }
        transfer->interpolate(here);
        // As before the first transfer: hanging DoFs follow their
        // constraints, or a DoF that a cell coarsened next to a finer one
        // made hanging gets two values where it stops hanging.
        AffineConstraints<double> constraints(relevant);
        DoFTools::make_hanging_node_constraints(dofs, constraints);
        constraints.close();
        for (auto &v : values)
          {
            constraints.distribute(v);
            v.update_ghost_values();
          }
        transfer = std::make_unique<Transfer>(dofs);
        transfer->prepare_for_coarsening_and_refinement(in);
        if (repartition)
          mesh.repartition();
        else
          mesh.execute_coarsening_and_refinement();
      };
      unsigned int alike_rounds = 0;
      while (true)
        {
          if (fault && alike_rounds < max_alike_rounds && flag_fault_alike())
            ++alike_rounds;
          else if (reflag && reflag())
            alike_rounds = 0;
          else
            break;
          go_on(false);
        }
      if (weighted() && weighted_balance(partition(), fault_cell_weight) > 1.05)
        go_on(true);
      timer.leave_subsection();

      setup();
      TimerOutput::Scope         t(timer, "Refinement: interpolate");
      std::vector<Distributed *> out;
      for (auto &v : values)
        {
          v.reinit(owned, relevant, mpi_communicator);
          out.push_back(&v);
        }
      transfer->interpolate(out);
      for (unsigned int k = 0; k < fields.size(); ++k)
        {
          fields[k].reinit(owned, mpi_communicator);
          std::copy(values[k].begin(), values[k].end(), fields[k].begin());
        }
    }



    template class Discretization<2>;
    template class Discretization<3>;
  } // namespace Discretization
} // namespace rupture
