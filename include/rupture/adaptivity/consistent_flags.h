#ifndef rupture_adaptivity_consistent_flags_h
#define rupture_adaptivity_consistent_flags_h

#include <deal.II/distributed/tria.h>

namespace rupture
{
  namespace Adaptivity
  {
    /**
     * Make the refinement and coarsening flags of the locally owned cells
     * obey the mesh's level balance (neighbours, also across a vertex,
     * differ by at most one level after the adaptation) the same way on
     * any number of processes: a family coarsens only if every neighbour
     * of its cells stays at most one level finer than the parent will be,
     * and a cell is refined where a neighbour would otherwise be two
     * levels finer. Every process decides for its own cells from the
     * levels that the others' flags give their cells, exchanged to the
     * ghost cells, and all decide again from the new levels until no flag
     * changes anywhere (each round from the previous round's levels alone,
     * so the result does not depend on where the processes' borders lie).
     *
     * deal.II's own Triangulation::prepare_coarsening_and_refinement()
     * sees the flags of the ghost cells, but not those of the cells beyond
     * them, so it decides a family next to a border from less than the
     * family's owner on another partition knows: the mesh depended on the
     * number of processes. After this it finds nothing to change.
     * Collective; only flags of locally owned cells change.
     */
    template <int dim>
    void
    make_flags_consistent(
      dealii::parallel::distributed::Triangulation<dim> &triangulation);
  } // namespace Adaptivity
} // namespace rupture

#endif
