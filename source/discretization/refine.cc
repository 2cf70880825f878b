// A new mesh during the run: refine and coarsen as flagged, both sides of
// the fault alike, and carry fields to the new DoFs (each cell's values
// through the meshes between).

#include <rupture/discretization/cell_wise_fields.h>
#include <rupture/discretization/discretization.h>

#include <deal.II/base/mpi.h>
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
      // The fields are read and written at every DoF of every cell through
      // deal.II's own vectors (direct indexing), not Trilinos' (a map
      // lookup per entry), several times faster; between the meshes they
      // go as each cell's values (CellWiseFields), so that only the last
      // mesh gets DoFs.
      timer.enter_subsection("Refinement: attach");
      using Distributed = LinearAlgebra::distributed::Vector<double>;
      std::vector<Distributed>   values(fields.size());
      std::vector<Distributed *> pointers;
      for (unsigned int k = 0; k < fields.size(); ++k)
        {
          values[k].reinit(owned, relevant, mpi_communicator);
          std::copy(fields[k].begin(), fields[k].end(), values[k].begin());
          values[k].update_ghost_values();
          pointers.push_back(&values[k]);
        }
      auto carried =
        std::make_unique<CellWiseFields<dim>>(dofs, elements, pointers, mesh);
      for (auto &v : values)
        v.reinit(0);
      carried->attach();
      // Where a family is coarsened next to finer cells, the values of the
      // finer cells at the new hanging nodes are their own, not the coarse
      // cell's: if a later mesh refined the coarse cell, such a node would
      // stop hanging with two values.
      bool coarsened = false;
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->is_locally_owned() && cell->coarsen_flag_set())
          coarsened = true;
      coarsened = Utilities::MPI::max(coarsened ? 1 : 0, mpi_communicator);
      timer.leave_subsection();
      timer.enter_subsection("Refinement: new mesh");
      mesh.execute_coarsening_and_refinement();
      ++meshes_made;
      carried->unpack();
      // So before a later mesh the fields are made to follow the hanging
      // constraints of the coarsened one, on its DoFs (once).
      const auto conform = [&]() {
        distribute_dofs();
        for (auto &v : values)
          v.reinit(owned, relevant, mpi_communicator);
        carried->write(dofs, pointers);
        AffineConstraints<double> constraints(relevant);
        DoFTools::make_hanging_node_constraints(dofs, constraints);
        constraints.close();
        for (auto &v : values)
          {
            v.update_ghost_values();
            constraints.distribute(v);
            v.update_ghost_values();
          }
        carried =
          std::make_unique<CellWiseFields<dim>>(dofs, elements, pointers, mesh);
        for (auto &v : values)
          v.reinit(0);
        coarsened = false;
      };
      // The fields go on through every mesh that is not yet the final one:
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
        if (coarsened && !repartition)
          conform();
        carried->attach();
        if (repartition)
          mesh.repartition();
        else
          mesh.execute_coarsening_and_refinement();
        ++meshes_made;
        carried->unpack();
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
      TimerOutput::Scope t(timer, "Refinement: interpolate");
      for (auto &v : values)
        v.reinit(owned, relevant, mpi_communicator);
      carried->write(dofs, pointers);
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
