// Vectors on the DoFs: ghosted copies and where a vector is largest.

#include <rupture/discretization/discretization.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>

#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace rupture
{
  namespace Discretization
  {
    template <int dim>
    const typename Discretization<dim>::VectorType &
    Discretization<dim>::ghosted_copy(const unsigned int slot,
                                      const VectorType  &v) const
    {
      if (!ghosts)
        ghosts = std::make_unique<GhostedVectors>(owned,
                                                  relevant,
                                                  mpi_communicator,
                                                  2);
      return ghosts->copy(slot, v);
    }



    template <int dim>
    std::string
    Discretization<dim>::locate_largest(const VectorType &v) const
    {
      // The support point of the entry that is not finite, or of the
      // largest one; over all ranks.
      Point<dim>   where;
      unsigned int where_component = 0;
      double       worst           = -1;
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto                          &fe = cell->get_fe();
            std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
            cell->get_dof_indices(indices);
            for (unsigned int i = 0; i < indices.size(); ++i)
              if (owned.is_element(indices[i]))
                {
                  const double value = v(indices[i]);
                  const double size  = std::isfinite(value) ?
                                         std::abs(value) :
                                         std::numeric_limits<double>::max();
                  if (size > worst)
                    {
                      worst = size;
                      where = MappingQ1<dim>().transform_unit_to_real_cell(
                        cell, fe.unit_support_point(i));
                      where_component =
                        fe.system_to_component_index(i).first % dim;
                    }
                }
          }
      const auto global_worst =
        dealii::Utilities::MPI::max(worst, mpi_communicator);
      const unsigned int rank =
        dealii::Utilities::MPI::this_mpi_process(mpi_communicator);
      const unsigned int owner =
        dealii::Utilities::MPI::min(worst == global_worst ?
                                      rank :
                                      dealii::numbers::invalid_unsigned_int,
                                    mpi_communicator);
      std::array<double, dim + 1> data;
      for (unsigned int d = 0; d < dim; ++d)
        data[d] = where[d];
      data[dim] = where_component;
      MPI_Bcast(data.data(), dim + 1, MPI_DOUBLE, owner, mpi_communicator);

      std::ostringstream text;
      text << "largest in component " << static_cast<int>(data[dim]) << " at (";
      for (unsigned int d = 0; d < dim; ++d)
        text << (d > 0 ? ", " : "") << data[d];
      text << ") m";
      return text.str();
    }



    template class Discretization<2>;
    template class Discretization<3>;
  } // namespace Discretization
} // namespace rupture
