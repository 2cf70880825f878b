#include <rupture/base/binary_io.h>
#include <rupture/base/utilities.h>
#include <rupture/output/statistics.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace rupture
{
  namespace Output
  {
    namespace
    {
      /// A row as the table writes it.
      void
      write_row(std::ostream &out, const std::vector<double> &row)
      {
        for (unsigned int c = 0; c < row.size(); ++c)
          out << (c ? " " : "") << row[c];
        out << "\n";
      }
    } // namespace



    void
    Statistics::keep_in_files(const std::string &table,
                              const std::string &row_file)
    {
      table_file = table;
      rows.keep_in_file(row_file);
      table_current = false;
      unwritten.clear();
    }



    void
    Statistics::keep_no_rows()
    {
      rows.keep_rows(false);
    }



    void
    Statistics::set_columns(const std::vector<std::string> &names)
    {
      columns = names;
      rows.clear();
      table_current = false;
      unwritten.clear();
    }



    void
    Statistics::add_row(const std::vector<double> &values)
    {
      Assert(values.size() == columns.size(),
             dealii::ExcDimensionMismatch(values.size(), columns.size()));
      rows.append(values);
      if (table_current)
        {
          std::ostringstream out;
          out << std::setprecision(14);
          write_row(out, values);
          unwritten += out.str();
        }
    }



    const std::vector<double> &
    Statistics::last_row() const
    {
      Assert(!rows.empty(), dealii::ExcInternalError());
      return rows.last();
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
    Statistics::write()
    {
      AssertThrow(!table_file.empty(), dealii::ExcInternalError());
      if (table_current)
        {
          // The new rows, appended (a run of a million steps does not
          // rewrite its table every minute).
          std::ofstream out(table_file, std::ios::app);
          out << unwritten;
          out.close();
          AssertThrow(out,
                      dealii::ExcMessage("The statistics <" + table_file +
                                         "> cannot be written: is the disk "
                                         "full?"));
          unwritten.clear();
          return;
        }
      // The whole table, through a temporary name.
      std::ostringstream out;
      for (unsigned int c = 0; c < columns.size(); ++c)
        out << "# " << c + 1 << ": " << columns[c] << "\n";
      out << std::setprecision(14);
      rows.for_each(
        [&](const std::vector<double> &row) { write_row(out, row); });
      Utilities::write_file_atomically(table_file, out.str());
      table_current = true;
      unwritten.clear();
    }
    void
    Statistics::save(std::ostream &out) const
    {
      BinaryIO::write(out, static_cast<std::uint64_t>(columns.size()));
      for (const auto &c : columns)
        BinaryIO::write(out, c);
      rows.save(out);
    }



    void
    Statistics::load(std::istream &in)
    {
      columns.resize(BinaryIO::read_size(in));
      for (auto &c : columns)
        BinaryIO::read(in, c);
      rows.load(in);
      table_current = false;
      unwritten.clear();
    }



  } // namespace Output
} // namespace rupture
