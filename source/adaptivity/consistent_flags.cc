// The mesh's level balance decided alike on any partition (see the
// header).

#include <rupture/adaptivity/consistent_flags.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <vector>

namespace rupture
{
  namespace Adaptivity
  {
    namespace
    {
      /// Whether @p cell belongs to a family that its flags coarsen: every
      /// sibling active, locally owned and flagged.
      template <typename Iterator>
      bool
      family_coarsens(const Iterator &cell)
      {
        if (!cell->coarsen_flag_set() || cell->level() == 0)
          return false;
        for (const auto &sibling : cell->parent()->child_iterators())
          if (!sibling->is_active() || !sibling->is_locally_owned() ||
              !sibling->coarsen_flag_set())
            return false;
        return true;
      }
    } // namespace



    template <int dim>
    void
    make_flags_consistent(
      dealii::parallel::distributed::Triangulation<dim> &triangulation)
    {
      using namespace dealii;
      using Iterator = typename Triangulation<dim>::active_cell_iterator;
      const MPI_Comm communicator = triangulation.get_communicator();
      // The finest level at each vertex after the adaptation. (On a mesh
      // whose neighbours differ by at most one level, every cell that
      // touches a cell has one of its vertices, hanging ones apart.)
      std::vector<int> at_vertex(triangulation.n_vertices());
      // The level each cell will have after the adaptation; -1 where this
      // process does not know (artificial cells).
      std::vector<int> future(triangulation.n_active_cells(), -1);
      // A neighbour counts at its level, one more if it is refined: not
      // one less if its family coarsens, which its owner knows but a
      // process that sees only some of the family's cells does not (deal.II
      // judges such a family by what it sees, so whether the cells next to
      // it may coarsen would depend on the partition).
      const auto level_after = [](const Iterator &cell) {
        return cell->level() + (cell->refine_flag_set() ? 1 : 0);
      };
      // Coarsening flags of families that cannot coarsen go first (their
      // cells would be judged as coarsening).
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && cell->coarsen_flag_set() &&
            !family_coarsens(cell))
          cell->clear_coarsen_flag();
      // A cell may not become both; refinement wins.
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && cell->refine_flag_set())
          cell->clear_coarsen_flag();

      for (unsigned int round = 0; round < 100; ++round)
        {
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned())
              future[cell->active_cell_index()] = level_after(cell);
          GridTools::exchange_cell_data_to_ghosts<int, Triangulation<dim>>(
            triangulation,
            [&](const Iterator &cell) {
              return future[cell->active_cell_index()];
            },
            [&](const Iterator &cell, const int &level) {
              future[cell->active_cell_index()] = level;
            });
          std::fill(at_vertex.begin(), at_vertex.end(), -1);
          for (const auto &cell : triangulation.active_cell_iterators())
            if (!cell->is_artificial())
              for (const unsigned int v : cell->vertex_indices())
                at_vertex[cell->vertex_index(v)] =
                  std::max(at_vertex[cell->vertex_index(v)],
                           future[cell->active_cell_index()]);
          // From this round's levels alone: the cells to refine and the
          // families that stay. (The cell's own family counts at the
          // family's level, which neither decision looks at.)
          std::vector<Iterator> refine, keep;
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned())
              {
                int finest = -1;
                for (const unsigned int v : cell->vertex_indices())
                  finest = std::max(finest, at_vertex[cell->vertex_index(v)]);
                const int level = cell->level();
                if (family_coarsens(cell) && finest > level)
                  keep.push_back(cell);
                else if (!cell->refine_flag_set() && finest > level + 1)
                  refine.push_back(cell);
              }
          bool changed = false;
          for (const auto &cell : keep)
            for (const auto &sibling : cell->parent()->child_iterators())
              if (sibling->coarsen_flag_set())
                {
                  sibling->clear_coarsen_flag();
                  changed = true;
                }
          for (const auto &cell : refine)
            {
              cell->clear_coarsen_flag();
              cell->set_refine_flag();
              changed = true;
            }
          // A family one of whose cells is now refined does not coarsen.
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned() && cell->coarsen_flag_set() &&
                !family_coarsens(cell))
              {
                cell->clear_coarsen_flag();
                changed = true;
              }
          if (Utilities::MPI::max(changed ? 1 : 0, communicator) == 0)
            return;
        }
      // Each round settles at least one more level: far fewer rounds than
      // this suffice.
      AssertThrow(false,
                  ExcMessage("Internal error: the mesh's level balance did "
                             "not settle in 100 rounds."));
    }



    template void
    make_flags_consistent(dealii::parallel::distributed::Triangulation<2> &);
    template void
    make_flags_consistent(dealii::parallel::distributed::Triangulation<3> &);
  } // namespace Adaptivity
} // namespace rupture
