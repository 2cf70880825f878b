#ifndef rupture_output_volume_output_h
#define rupture_output_volume_output_h

#include <rupture/material/elastic_material.h>
#include <rupture/output/directory.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <utility>
#include <vector>

namespace rupture
{
  namespace Output
  {
    /**
     * Writes the volume fields for ParaView: one .pvtu/.vtu set per output
     * time in <output>/solution/, and the time series <output>/solution.pvd.
     * Fields: displacement, velocity, stress (tensor, Pa), material id and
     * MPI rank.
     *
     * The DoFHandler may carry the displacement on one or two sides (a split
     * fault): components i and i + dim are then the same physical component
     * on either side, and only one of them is nonzero on any cell.
     */
    template <int dim>
    class VolumeOutput
    {
    public:
      /**
       * Each rank writes its cells in pieces of at most
       * @p cells_per_piece cells (one .vtu file each, all listed in the
       * step's .pvtu), so that the memory of a snapshot stays bounded.
       */
      VolumeOutput(Directory                        &directory,
                   const Material::ElasticMaterials &materials,
                   const unsigned int                cells_per_piece,
                   const MPI_Comm                    communicator);

      void
      write(const DoFHandler<dim>               &dof_handler,
            const TrilinosWrappers::MPI::Vector &displacement,
            const TrilinosWrappers::MPI::Vector &velocity,
            const double                         time,
            const unsigned int                   step);

    private:
      Directory                                  &directory;
      const Material::ElasticMaterials           &materials;
      const unsigned int                          cells_per_piece;
      const MPI_Comm                              communicator;
      std::vector<std::pair<double, std::string>> records;
    };
  } // namespace Output
} // namespace rupture

#endif
