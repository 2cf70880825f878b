#ifndef rupture_output_statistics_h
#define rupture_output_statistics_h

#include <rupture/output/series.h>

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace rupture
{
  namespace Output
  {
    /**
     * The table <output>/statistics: one row per time step, with a header
     * that documents each column ("# 3: Kinetic energy (J)"). The process
     * that writes it keeps the rows in a file of their own (Output::Series)
     * and appends the new rows to the table at each write(); the others
     * keep only the last row.
     */
    class Statistics
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
       * Write the table to @p table, with its rows kept in the scratch file
       * @p rows (on the process that writes it).
       */
      void
      keep_in_files(const std::string &table, const std::string &rows);
      /// Keep no rows (the processes that do not write the table).
      void
      keep_no_rows();
      /**
       * Set the column names (with units). Must be called before add_row().
       */
      void
      set_columns(const std::vector<std::string> &names);

      void
      add_row(const std::vector<double> &values);

      /**
       * Bring the table up to date: append the rows added since the last
       * write (the header and every row at the first write, and after
       * set_columns() or load()).
       */
      void
      write();

      const std::vector<double> &
      last_row() const;
      /**
       * The position of the column @p name among set_columns()'s names;
       * throws if there is none of that name.
       */
      unsigned int
      index(const std::string &name) const;
      /// Whether a column of that name exists.
      bool
      has_column(const std::string &name) const;
      /// The value of column @p name in the last row.
      double
      last(const std::string &name) const;

      std::size_t
      n_rows() const
      {
        return rows.size();
      }

    private:
      std::vector<std::string> columns;
      Series                   rows;
      /// The table's file, and its rows not written yet as text.
      std::string table_file;
      std::string unwritten;
      /// Whether the table file holds the header and every row but those
      /// in @p unwritten.
      bool table_current = false;
    };
  } // namespace Output
} // namespace rupture

#endif
