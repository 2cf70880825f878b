#ifndef rupture_output_volume_output_h
#define rupture_output_volume_output_h

#include <rupture/material/elastic_material.h>
#include <rupture/output/directory.h>
#include <rupture/output/vtu_file.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <boost/signals2/connection.hpp>

#include <array>
#include <functional>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace rupture
{
  namespace Output
  {
    /**
     * Writes the volume fields for ParaView: one .pvtu/.vtu set per output
     * time in <output>/solution/, and the time series <output>/solution.pvd
     * (start_series() starts another one, for a loading phase).
     * Fields (any of available_fields()): displacement and velocity at the
     * points, the stress tensor (Pa) at the centre of each cell, the
     * material id and the MPI rank of each cell. A point is written once
     * for all cells of a piece that share it (once per side of a split
     * fault); Q2 elements are written by their vertex values.
     *
     * The DoFHandler may carry the displacement on one or two sides (a split
     * fault): components i and i + dim are then the same physical component
     * on either side, and only one of them is nonzero on any cell.
     *
     * What does not change from one snapshot to the next is built at the
     * first one and kept: each piece's cells, points and the local indices
     * of their DoFs, and the encoded mesh and integer cell fields. It is
     * built anew when the triangulation changes or the DoFs or the ghosted
     * vectors' layout differ.
     */
    template <int dim>
    class VolumeOutput
    {
    public:
      /**
       * Write what a checkpoint keeps of this object to @p out, and read it
       * back (doc/manual.md, "Checkpoints and restart").
       */
      void
      save(std::ostream &out) const;
      void
      load(std::istream &in);
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

      /// What the snapshots hold and how they are written (<Output>).
      struct Settings
      {
        /// The fields written (names of available_fields()).
        std::vector<std::string> fields;
        Compression              compression = Compression::mesh;
        /// Each rank writes its cells in pieces of at most this many cells
        /// (one .vtu file each, all listed in the step's .pvtu), so that
        /// the memory of a snapshot stays bounded.
        unsigned int cells_per_piece = 0;

        /// Read <Volume fields>, <Compression> and <Cells per output
        /// piece> (the caller has entered <Output>).
        void
        parse_parameters(ParameterHandler &prm);
      };

      /// The field names of @p settings are checked here.
      VolumeOutput(Directory                        &directory,
                   const Material::ElasticMaterials &materials,
                   const Settings                   &settings,
                   const MPI_Comm                    communicator);

      ~VolumeOutput();

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

      /**
       * Start a new time series: later snapshots are written as
       * solution/<file_prefix>_NNNNN.* (NNNNN the step) and listed, with
       * their times, in <output>/<pvd_name>. The first series is
       * "solution" in solution.pvd.
       */
      void
      start_series(const std::string &file_prefix, const std::string &pvd_name);

    private:
      /**
       * What a piece keeps between snapshots.
       */
      struct Piece
      {
        /// The mesh cell of each VTK cell: a cell of degree p is written
        /// as p^dim sub-cells between its nodes.
        std::vector<typename DoFHandler<dim>::active_cell_iterator> cells;
        /// Which sub-cell of its mesh cell each VTK cell is
        /// (lexicographic).
        std::vector<unsigned int> sub_cell;
        /// Each cell's points, in VTK's vertex order.
        std::vector<std::int32_t> connectivity;
        /// The local (ghosted) index of each point's dim components.
        std::vector<std::array<int, dim>> point_dofs;
        /// Points, connectivity, offsets and types, encoded.
        std::vector<VtuFile::Array> mesh;
        /// The material ids, MPI ranks and levels (as chosen), encoded.
        std::vector<VtuFile::Array> cell_fields;
      };

      /// Build the pieces for @p dof_handler; @p local gives the local
      /// (ghosted) index of a DoF, of which there are @p n_local.
      void
      build_pieces(const DoFHandler<dim> &dof_handler,
                   const std::function<int(types::global_dof_index)> &local,
                   const int                                          n_local);

      Directory                                  &directory;
      const Material::ElasticMaterials           &materials;
      const Compression                           compression;
      const unsigned int                          cells_per_piece;
      const MPI_Comm                              communicator;
      std::vector<std::pair<double, std::string>> records;
      std::string file_prefix = "solution", pvd_name = "solution.pvd";
      /// Whether each of available_fields() is written.
      std::array<bool, 6> write_field{};

      std::vector<Piece>      pieces;
      const DoFHandler<dim>  *pieces_dof_handler = nullptr;
      types::global_dof_index pieces_n_dofs      = 0;
      int                     pieces_n_local     = 0;
      /// Clears the pieces when the triangulation changes.
      boost::signals2::connection tria_listener;
    };
  } // namespace Output
} // namespace rupture

#endif
