#include <rupture/base/binary_io.h>
#include <rupture/output/series.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace rupture
{
  namespace Output
  {
    namespace
    {
      /// Rows are appended to the file once this many numbers wait.
      constexpr std::size_t batch = 1 << 16;
    } // namespace



    Series::~Series()
    {
      if (!file.empty())
        std::remove(file.c_str());
    }



    Series::Series(Series &&other) noexcept
    {
      *this = std::move(other);
    }



    Series &
    Series::operator=(Series &&other) noexcept
    {
      if (this != &other)
        {
          if (!file.empty())
            std::remove(file.c_str());
          file     = std::move(other.file);
          keep     = other.keep;
          width    = other.width;
          n_rows   = other.n_rows;
          last_row = std::move(other.last_row);
          pending  = std::move(other.pending);
          other.file.clear();
          other.n_rows = 0;
          other.width  = 0;
        }
      return *this;
    }



    void
    Series::keep_in_file(const std::string &path)
    {
      AssertThrow(keep && file.empty(),
                  dealii::ExcMessage("A series gets its file once, and only "
                                     "if it keeps its rows."));
      file = path;
      std::ofstream out(file, std::ios::binary | std::ios::trunc);
      AssertThrow(out,
                  dealii::ExcMessage("The file <" + file +
                                     "> (the rows of a time series) cannot be "
                                     "written."));
      out.close();
      // The rows so far (in memory until now) go to it.
      flush();
    }



    void
    Series::keep_rows(const bool keep_them)
    {
      keep = keep_them;
      if (!keep)
        pending.clear();
    }



    void
    Series::append(const std::vector<double> &row)
    {
      if (n_rows == 0)
        width = row.size();
      Assert(row.size() == width,
             dealii::ExcDimensionMismatch(row.size(), width));
      ++n_rows;
      last_row = row;
      if (!keep)
        return;
      pending.insert(pending.end(), row.begin(), row.end());
      if (!file.empty() && pending.size() >= batch)
        flush();
    }



    void
    Series::clear()
    {
      n_rows = 0;
      width  = 0;
      last_row.clear();
      pending.clear();
      if (!file.empty())
        {
          std::ofstream out(file, std::ios::binary | std::ios::trunc);
          AssertThrow(out,
                      dealii::ExcMessage("The file <" + file +
                                         "> (the rows of a time series) "
                                         "cannot be written."));
        }
    }



    const std::vector<double> &
    Series::last() const
    {
      Assert(n_rows > 0, dealii::ExcInternalError());
      return last_row;
    }



    void
    Series::flush() const
    {
      if (file.empty() || pending.empty())
        return;
      std::ofstream out(file, std::ios::binary | std::ios::app);
      out.write(reinterpret_cast<const char *>(pending.data()),
                pending.size() * sizeof(double));
      out.close();
      AssertThrow(out,
                  dealii::ExcMessage("The file <" + file +
                                     "> (the rows of a time series) cannot be "
                                     "written: is the disk full?"));
      pending.clear();
    }



    void
    Series::for_each(
      const std::function<void(const std::vector<double> &)> &action) const
    {
      AssertThrow(keep || n_rows == 0, dealii::ExcInternalError());
      std::vector<double> row(width);
      if (file.empty())
        {
          for (std::uint64_t i = 0; i < n_rows; ++i)
            {
              std::copy(pending.begin() + i * width,
                        pending.begin() + (i + 1) * width,
                        row.begin());
              action(row);
            }
          return;
        }
      flush();
      std::ifstream       in(file, std::ios::binary);
      std::vector<double> chunk;
      std::uint64_t       done = 0;
      while (done < n_rows)
        {
          const std::uint64_t n = std::min<std::uint64_t>(
            n_rows - done,
            std::max<std::size_t>(batch / std::max<std::size_t>(width, 1), 1));
          chunk.resize(n * width);
          in.read(reinterpret_cast<char *>(chunk.data()),
                  chunk.size() * sizeof(double));
          AssertThrow(in,
                      dealii::ExcMessage(
                        "The file <" + file +
                        "> (the rows of a time series) is shorter than the "
                        "rows written to it: was it changed or removed "
                        "during the run?"));
          for (std::uint64_t i = 0; i < n; ++i)
            {
              std::copy(chunk.begin() + i * width,
                        chunk.begin() + (i + 1) * width,
                        row.begin());
              action(row);
            }
          done += n;
        }
    }



    void
    Series::save(std::ostream &out) const
    {
      BinaryIO::write(out, n_rows);
      for_each(
        [&](const std::vector<double> &row) { BinaryIO::write(out, row); });
    }



    void
    Series::load(std::istream &in)
    {
      clear();
      const std::uint64_t n = BinaryIO::read_size(in);
      std::vector<double> row;
      for (std::uint64_t i = 0; i < n; ++i)
        {
          BinaryIO::read(in, row);
          AssertThrow(i == 0 || row.size() == width,
                      dealii::ExcMessage("A row of a time series in the "
                                         "checkpoint has the wrong length."));
          append(row);
        }
      flush();
    }
  } // namespace Output
} // namespace rupture
