#ifndef rupture_output_volume_output_h
#define rupture_output_volume_output_h

#include <rupture/material/elastic_material.h>
#include <rupture/output/directory.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
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
     * Fields (any of available_fields()): displacement and velocity at the
     * points, the stress tensor (Pa) at the centre of each cell, the
     * material id and the MPI rank of each cell. A point is written once
     * for all cells of a piece that share it (once per side of a split
     * fault); Q2 elements are written by their vertex values.
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
       * What is compressed (zlib's fastest level): nothing; the mesh
       * (points, cells) and the integer cell fields only; or also the
       * floating-point fields, which shrink by only 20-30 % at several times
       * the cost of the rest.
       */
      enum class Compression
      {
        none,
        mesh,
        all
      };

      /**
       * Each rank writes its cells in pieces of at most
       * @p cells_per_piece cells (one .vtu file each, all listed in the
       * step's .pvtu), so that the memory of a snapshot stays bounded.
       */
      VolumeOutput(Directory                        &directory,
                   const Material::ElasticMaterials &materials,
                   const std::vector<std::string>   &fields,
                   const Compression                 compression,
                   const unsigned int                cells_per_piece,
                   const MPI_Comm                    communicator);

      /**
       * The names of the fields that can be written.
       */
      static const std::vector<std::string> &
      available_fields();

      /**
       * Write a snapshot. The vectors must hold the locally relevant
       * (ghosted) values.
       */
      void
      write(const DoFHandler<dim>               &dof_handler,
            const TrilinosWrappers::MPI::Vector &displacement,
            const TrilinosWrappers::MPI::Vector &velocity,
            const double                         time,
            const unsigned int                   step);

    private:
      Directory                                  &directory;
      const Material::ElasticMaterials           &materials;
      const Compression                           compression;
      const unsigned int                          cells_per_piece;
      const MPI_Comm                              communicator;
      std::vector<std::pair<double, std::string>> records;
      /// Whether each of available_fields() is written.
      std::array<bool, 5> write_field{};
    };
  } // namespace Output
} // namespace rupture

#endif
