#ifndef rupture_output_receivers_h
#define rupture_output_receivers_h

#include <rupture/output/directory.h>
#include <rupture/output/series.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

namespace rupture
{
  namespace Output
  {
    using namespace dealii;

    /**
     * Receivers: named points in the body (off the fault) whose
     * displacement and velocity are recorded at every step and written as
     * time series, laid out like the SCEC off-fault station files
     * (<output>/<name>.dat, columns t, then displacement and velocity per
     * global component: 't x-disp x-vel y-disp y-vel [z-disp z-vel]').
     * Values are interpolated with the finite element, never snapped to a
     * node; a receiver outside the mesh is an error.
     */
    template <int dim>
    class Receivers
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
       * Parse 'name: x, y[, z]; ...' (<Output/Receivers>). Throws with a
       * message naming the entry on malformed input.
       */
      Receivers(const std::string &specification, const MPI_Comm communicator);

      bool
      empty() const
      {
        return receivers.empty();
      }

      /// The receivers' names (each writes <name>.dat).
      std::vector<std::string>
      names() const
      {
        std::vector<std::string> result;
        for (const auto &r : receivers)
          result.push_back(r.name);
        return result;
      }

      /**
       * Find the cell of each receiver. A receiver on a split fault is
       * taken on the side of the cell found first; receivers are meant to
       * be off the fault.
       */
      void
      setup(const DoFHandler<dim> &dof_handler,
            const IndexSet        &locally_owned_dofs);

      /// Record the values at @p time (one row per call).
      void
      record(const TrilinosWrappers::MPI::Vector &displacement,
             const TrilinosWrappers::MPI::Vector &velocity,
             const double                         time);

      /// Forget the rows so far (the series restarts with the dynamic phase).
      void
      clear()
      {
        for (auto &r : receivers)
          r.rows.clear();
      }

      /// Keep the rows in scratch files of @p directory (on the process
      /// that writes them) instead of in memory.
      void
      keep_series_in(Directory &directory)
      {
        for (auto &r : receivers)
          r.rows.keep_in_file(
            directory.record(".receiver-" + r.name + ".rows"));
      }

      /// Write all rows so far (rank 0), replacing the files.
      void
      write(Directory &directory, const double time_step) const;

    private:
      struct Receiver
      {
        std::string name;
        Point<dim>  location;
        /// On the owning rank: the cell's DoFs and their weights per
        /// component (the shape function values at the point).
        std::vector<types::global_dof_index> dofs;
        std::vector<double>                  weights;
        std::vector<unsigned int>            components;
        bool                                 owned = false;
        /// Rows of (time, u, v) on rank 0.
        Series rows;
      };

      MPI_Comm                      communicator;
      std::vector<Receiver>         receivers;
      TrilinosWrappers::MPI::Vector ghosted;
    };
  } // namespace Output
} // namespace rupture

#endif
