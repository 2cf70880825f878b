#ifndef rupture_adaptivity_gather_h
#define rupture_adaptivity_gather_h

#include <deal.II/base/config.h>
#include <deal.II/base/point.h>

#include <mpi.h>

#include <utility>
#include <vector>

namespace rupture
{
  namespace Adaptivity
  {
    /**
     * The points that every process holds, on every process (a mesh
     * criterion decides both cells of a fault face alike from them).
     * Collective.
     */
    template <int dim>
    std::vector<dealii::Point<dim>>
    all_gather(const std::vector<dealii::Point<dim>> &mine,
               const MPI_Comm                         communicator);

    /**
     * The same for points with a value each.
     */
    template <int dim>
    std::vector<std::pair<dealii::Point<dim>, double>>
    all_gather(const std::vector<std::pair<dealii::Point<dim>, double>> &mine,
               const MPI_Comm communicator);
  } // namespace Adaptivity
} // namespace rupture

#endif
