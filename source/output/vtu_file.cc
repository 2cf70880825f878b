#include <rupture/base/utilities.h>
#include <rupture/output/vtu_file.h>

#include <zlib.h>

#include <array>
#include <cstring>
#include <iomanip>
#include <sstream>

namespace rupture
{
  namespace Output
  {
    namespace
    {
      const char *
      section_tag(const VtuFile::Section section)
      {
        switch (section)
          {
            case VtuFile::Section::points:
              return "Points";
            case VtuFile::Section::cells:
              return "Cells";
            case VtuFile::Section::point_data:
              return "PointData";
            default:
              return "CellData";
          }
      }
    } // namespace



    VtuFile::VtuFile(const std::uint64_t n_points,
                     const std::uint64_t n_cells,
                     const double        time,
                     const unsigned int  cycle,
                     const bool          compress)
      : n_points(n_points)
      , n_cells(n_cells)
      , time(time)
      , cycle(cycle)
      , compress(compress)
    {}



    const VtuFile::Array &
    VtuFile::add(const Section             section,
                 const std::string        &name,
                 const unsigned int        n_components,
                 const std::vector<float> &values,
                 const bool                deflate)
    {
      return add_bytes(section,
                       name,
                       "Float32",
                       n_components,
                       values.data(),
                       values.size() * sizeof(float),
                       deflate);
    }



    const VtuFile::Array &
    VtuFile::add(const Section                    section,
                 const std::string               &name,
                 const unsigned int               n_components,
                 const std::vector<std::int32_t> &values,
                 const bool                       deflate)
    {
      return add_bytes(section,
                       name,
                       "Int32",
                       n_components,
                       values.data(),
                       values.size() * sizeof(std::int32_t),
                       deflate);
    }



    const VtuFile::Array &
    VtuFile::add(const Section                    section,
                 const std::string               &name,
                 const unsigned int               n_components,
                 const std::vector<std::uint8_t> &values,
                 const bool                       deflate)
    {
      return add_bytes(section,
                       name,
                       "UInt8",
                       n_components,
                       values.data(),
                       values.size(),
                       deflate);
    }



    const VtuFile::Array &
    VtuFile::add_bytes(const Section      section,
                       const std::string &name,
                       const std::string &type,
                       const unsigned int n_components,
                       const void        *data,
                       const std::size_t  n_bytes,
                       const bool         deflate)
    {
      Array array{section, name, type, n_components, compress, {}};
      if (!compress)
        {
          // The size in bytes, then the bytes.
          const std::uint64_t size = n_bytes;
          array.bytes.resize(sizeof(size) + n_bytes);
          std::memcpy(array.bytes.data(), &size, sizeof(size));
          if (n_bytes > 0)
            std::memcpy(array.bytes.data() + sizeof(size), data, n_bytes);
          arrays.push_back(std::move(array));
          return arrays.back();
        }
      // VTK's compressed layout: a header of 64-bit words (the number of
      // blocks, the uncompressed size of a block and of the last block, the
      // compressed size of each block), then the blocks. One block holds
      // the whole array; an empty array has no block.
      std::array<std::uint64_t, 4> header{{0, 32768, 0, 0}};
      unsigned int                 n_words = 3;
      std::vector<char>            body;
      if (n_bytes > 0)
        {
          uLongf size = compressBound(n_bytes);
          body.resize(size);
          const int code = compress2(reinterpret_cast<Bytef *>(body.data()),
                                     &size,
                                     static_cast<const Bytef *>(data),
                                     n_bytes,
                                     deflate ? Z_BEST_SPEED : Z_NO_COMPRESSION);
          AssertThrow(code == Z_OK,
                      ExcMessage("zlib could not compress the array '" + name +
                                 "' of a volume output file (" + "zlib error " +
                                 std::to_string(code) + ")."));
          body.resize(size);
          header  = {{1, n_bytes, n_bytes, size}};
          n_words = 4;
        }
      array.bytes.resize(n_words * sizeof(std::uint64_t) + body.size());
      std::memcpy(array.bytes.data(),
                  header.data(),
                  n_words * sizeof(std::uint64_t));
      if (!body.empty())
        std::memcpy(array.bytes.data() + n_words * sizeof(std::uint64_t),
                    body.data(),
                    body.size());
      arrays.push_back(std::move(array));
      return arrays.back();
    }



    void
    VtuFile::add(const Array &array)
    {
      AssertThrow(array.compressed == compress, ExcInternalError());
      arrays.push_back(array);
    }



    std::string
    VtuFile::str() const
    {
      std::ostringstream out;
      out << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
             "byte_order=\"LittleEndian\" header_type=\"UInt64\""
          << (compress ? " compressor=\"vtkZLibDataCompressor\"" : "")
          << ">\n<UnstructuredGrid>\n"
          << "<FieldData>\n"
          << "<DataArray type=\"Float64\" Name=\"TIME\" NumberOfTuples=\"1\" "
             "format=\"ascii\">"
          << std::setprecision(17) << time << "</DataArray>\n"
          << "<DataArray type=\"Int32\" Name=\"CYCLE\" NumberOfTuples=\"1\" "
             "format=\"ascii\">"
          << cycle << "</DataArray>\n"
          << "</FieldData>\n"
          << "<Piece NumberOfPoints=\"" << n_points << "\" NumberOfCells=\""
          << n_cells << "\">\n";
      std::uint64_t offset = 0;
      for (const Section section : {Section::points,
                                    Section::cells,
                                    Section::point_data,
                                    Section::cell_data})
        {
          out << '<' << section_tag(section) << ">\n";
          for (const auto &a : arrays)
            if (a.section == section)
              {
                out << "<DataArray type=\"" << a.type << "\" Name=\"" << a.name
                    << "\" NumberOfComponents=\"" << a.n_components
                    << "\" format=\"appended\" offset=\"" << offset << "\"/>\n";
                offset += a.bytes.size();
              }
          out << "</" << section_tag(section) << ">\n";
        }
      out
        << "</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_";
      // The arrays in the order of their offsets.
      for (const Section section : {Section::points,
                                    Section::cells,
                                    Section::point_data,
                                    Section::cell_data})
        for (const auto &a : arrays)
          if (a.section == section)
            out.write(a.bytes.data(), a.bytes.size());
      out << "\n</AppendedData>\n</VTKFile>\n";
      return out.str();
    }



    std::string
    VtuFile::pvtu_record(const std::vector<std::string> &piece_names) const
    {
      std::ostringstream out;
      out << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" "
             "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
          << "<PUnstructuredGrid GhostLevel=\"0\">\n";
      for (const Section section :
           {Section::points, Section::point_data, Section::cell_data})
        {
          out << "<P" << section_tag(section) << ">\n";
          for (const auto &a : arrays)
            if (a.section == section)
              out << "<PDataArray type=\"" << a.type << "\" Name=\"" << a.name
                  << "\" NumberOfComponents=\"" << a.n_components << "\"/>\n";
          out << "</P" << section_tag(section) << ">\n";
        }
      for (const auto &name : piece_names)
        out << "<Piece Source=\"" << name << "\"/>\n";
      out << "</PUnstructuredGrid>\n</VTKFile>\n";
      return out.str();
    }
  } // namespace Output
} // namespace rupture
