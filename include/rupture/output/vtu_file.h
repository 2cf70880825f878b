#ifndef rupture_output_vtu_file_h
#define rupture_output_vtu_file_h

#include <cstdint>
#include <string>
#include <vector>

namespace rupture
{
  namespace Output
  {
    /**
     * One piece of an unstructured grid in VTK's XML format (.vtu), as
     * ParaView and VTK read it. Each data array is appended in raw binary
     * after the XML header, with 64-bit headers, and optionally compressed
     * with zlib (its fastest level) as soon as it is added; only the bytes
     * to write are kept.
     *
     * Every piece of one output time has the same arrays in the same order,
     * so that pvtu_record() can describe them all from one piece.
     */
    class VtuFile
    {
    public:
      /**
       * Where an array belongs: the point coordinates, the cell topology
       * (connectivity, offsets, types), or data at points or on cells.
       */
      enum class Section
      {
        points,
        cells,
        point_data,
        cell_data
      };

      /**
       * An array as it is written: its name and type and its bytes, with
       * the header and the (compressed) data.
       */
      struct Array
      {
        Section           section;
        std::string       name;
        std::string       type;
        unsigned int      n_components;
        bool              compressed;
        std::vector<char> bytes;
      };

      /**
       * A piece with @p n_points points and @p n_cells cells, at simulated
       * time @p time and output number @p cycle (ParaView's TIME and CYCLE
       * field data), compressed or not.
       */
      VtuFile(const std::uint64_t n_points,
              const std::uint64_t n_cells,
              const double        time,
              const unsigned int  cycle,
              const bool          compress);

      /**
       * Add an array of @p n_components values per point or cell (one value
       * per connectivity entry, offset or type for the cell topology). In a
       * compressed file, @p deflate = false stores the array in zlib's
       * format without compressing it: worth it for the floating-point
       * fields of a solution, which zlib shrinks by only 20-30 % at several
       * times the cost of the rest of the file. Returns the array as it
       * will be written, which a later file with the same mesh may add()
       * again without encoding it anew.
       */
      const Array &
      add(const Section             section,
          const std::string        &name,
          const unsigned int        n_components,
          const std::vector<float> &values,
          const bool                deflate = true);
      const Array &
      add(const Section                    section,
          const std::string               &name,
          const unsigned int               n_components,
          const std::vector<std::int32_t> &values,
          const bool                       deflate = true);
      const Array &
      add(const Section                    section,
          const std::string               &name,
          const unsigned int               n_components,
          const std::vector<std::uint8_t> &values,
          const bool                       deflate = true);

      /**
       * Add an array encoded for an earlier file (of the same compression).
       */
      void
      add(const Array &array);

      /**
       * The whole file.
       */
      std::string
      str() const;

      /**
       * The .pvtu record that lists the pieces @p piece_names (relative to
       * the record), whose arrays are those of this piece.
       */
      std::string
      pvtu_record(const std::vector<std::string> &piece_names) const;

    private:
      const Array &
      add_bytes(const Section      section,
                const std::string &name,
                const std::string &type,
                const unsigned int n_components,
                const void        *data,
                const std::size_t  n_bytes,
                const bool         deflate);

      const std::uint64_t n_points;
      const std::uint64_t n_cells;
      const double        time;
      const unsigned int  cycle;
      const bool          compress;
      std::vector<Array>  arrays;
    };
  } // namespace Output
} // namespace rupture

#endif
