#include <rupture/base/binary_io.h>
#include <rupture/base/utilities.h>
#include <rupture/output/statistics.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace rupture
{
  namespace Output
  {
    void
    Statistics::set_columns(const std::vector<std::string> &names)
    {
      columns = names;
      rows.clear();
    }



    void
    Statistics::add_row(const std::vector<double> &values)
    {
      Assert(values.size() == columns.size(),
             dealii::ExcDimensionMismatch(values.size(), columns.size()));
      rows.push_back(values);
    }



    const std::vector<double> &
    Statistics::last_row() const
    {
      Assert(!rows.empty(), dealii::ExcInternalError());
      return rows.back();
    }



    unsigned int
    Statistics::index(const std::string &name) const
    {
      const auto c = std::find(columns.begin(), columns.end(), name);
      AssertThrow(c != columns.end(),
                  dealii::ExcMessage("The statistics have no column <" + name +
                                     ">."));
      return c - columns.begin();
    }



    bool
    Statistics::has_column(const std::string &name) const
    {
      return std::find(columns.begin(), columns.end(), name) != columns.end();
    }



    double
    Statistics::last(const std::string &name) const
    {
      return last_row()[index(name)];
    }



    void
    Statistics::write(const std::string &filename) const
    {
      std::ostringstream out;
      for (unsigned int c = 0; c < columns.size(); ++c)
        out << "# " << c + 1 << ": " << columns[c] << "\n";
      out << std::setprecision(14);
      for (const auto &row : rows)
        {
          for (unsigned int c = 0; c < row.size(); ++c)
            out << (c ? " " : "") << row[c];
          out << "\n";
        }
      Utilities::write_file_atomically(filename, out.str());
    }
    void
    Statistics::save(std::ostream &out) const
    {
      BinaryIO::write(out, static_cast<std::uint64_t>(columns.size()));
      for (const auto &c : columns)
        BinaryIO::write(out, c);
      BinaryIO::write(out, rows);
    }



    void
    Statistics::load(std::istream &in)
    {
      columns.resize(BinaryIO::read_size(in));
      for (auto &c : columns)
        BinaryIO::read(in, c);
      BinaryIO::read(in, rows);
    }



  } // namespace Output
} // namespace rupture
