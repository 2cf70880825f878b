#ifndef rupture_output_statistics_h
#define rupture_output_statistics_h

#include <iosfwd>
#include <string>
#include <vector>

namespace rupture
{
  namespace Output
  {
    /**
     * The table <output>/statistics: one row per time step, with a header
     * that documents each column ("# 3: Kinetic energy (J)"). The file is
     * rewritten through a temporary name so it is never half written.
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
       * Set the column names (with units). Must be called before add_row().
       */
      void
      set_columns(const std::vector<std::string> &names);

      void
      add_row(const std::vector<double> &values);

      /**
       * Write the whole table to @p filename.
       */
      void
      write(const std::string &filename) const;

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
      std::vector<std::string>         columns;
      std::vector<std::vector<double>> rows;
    };
  } // namespace Output
} // namespace rupture

#endif
