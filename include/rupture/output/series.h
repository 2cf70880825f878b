#ifndef rupture_output_series_h
#define rupture_output_series_h

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace rupture
{
  namespace Output
  {
    /**
     * A time series: rows of numbers of one length, one per recorded step
     * (the statistics, a fault station, a receiver). A run of a million
     * steps must not hold them all in memory, so on the process that writes
     * them the rows go to a file of their own (keep_in_file(): raw doubles,
     * appended in batches) and are read back in order when a table is
     * written or a checkpoint saved. The file is scratch: it is removed when
     * the series goes away, and a checkpoint holds the rows themselves.
     *
     * Three ways to keep the rows: in memory (the default), in a file, or
     * not at all (keep_rows(false): only their number and the last row, on
     * the processes that do not write the series).
     */
    class Series
    {
    public:
      Series() = default;
      /// Removes the file (if any).
      ~Series();
      Series(const Series &) = delete;
      Series &
      operator=(const Series &) = delete;
      Series(Series &&other) noexcept;
      Series &
      operator=(Series &&other) noexcept;

      /**
       * From now on keep the rows in the file @p path: the rows so far are
       * written to it (replacing what it held), later ones appended. Once
       * per series.
       */
      void
      keep_in_file(const std::string &path);
      /// Keep no rows at all (only their number and the last one).
      void
      keep_rows(const bool keep);

      void
      append(const std::vector<double> &row);
      /// Forget every row.
      void
      clear();

      std::uint64_t
      size() const
      {
        return n_rows;
      }
      bool
      empty() const
      {
        return n_rows == 0;
      }
      /// The last row (the series must not be empty).
      const std::vector<double> &
      last() const;

      /// Call @p action with each row, in order. Not with keep_rows(false).
      void
      for_each(
        const std::function<void(const std::vector<double> &)> &action) const;

      /// Write the rows as a checkpoint holds them (BinaryIO's layout of a
      /// list of lists of numbers), and read them back.
      void
      save(std::ostream &out) const;
      void
      load(std::istream &in);

    private:
      /// Append the rows in memory to the file.
      void
      flush() const;

      std::string         file;
      bool                keep   = true;
      std::size_t         width  = 0;
      std::uint64_t       n_rows = 0;
      std::vector<double> last_row;
      /// The rows not yet in the file (all of them without one), one after
      /// the other.
      mutable std::vector<double> pending;
    };
  } // namespace Output
} // namespace rupture

#endif
