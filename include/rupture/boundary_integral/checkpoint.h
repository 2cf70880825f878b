#ifndef rupture_boundary_integral_checkpoint_h
#define rupture_boundary_integral_checkpoint_h

#include <deal.II/base/mpi.h>

#include <iosfwd>
#include <string>

namespace rupture
{
  namespace Output
  {
    class Directory;
  }

  namespace BoundaryIntegral
  {
    /**
     * The time loop's own state: the time, the step proposed next and the
     * last one taken, the extremes, the counts.
     */
    struct Clock
    {
      double        t = 0, dt = 0, last_dt = 0;
      double        dt_min = 1e300, dt_max = 0;
      unsigned long steps = 0, n_events = 0;
    };

    /**
     * The checkpoint file of a boundary-integral run,
     * <output>/checkpoint/boundary_integral.bin, and the one before it
     * (boundary_integral.previous.bin). Its first records are a tag and the
     * Clock with the number of elements; what follows is written by the
     * components (the integrator, the fault, the catalogue, the output).
     */
    class Checkpoint
    {
    public:
      Checkpoint(const std::string &directory_name,
                 const MPI_Comm     communicator);

      /**
       * --resume: rank 0 reads the newest checkpoint (or, if a run was
       * killed between writing one and renaming it, the one before) and
       * sends it to the others; the tag and the number of elements
       * (@p n_elements) are checked and @p clock is read. Returns the
       * bytes after the clock. Collective.
       */
      std::string
      read(Clock &clock, const unsigned int n_elements);

      /// The path read() read (for messages).
      const std::string &
      path() const
      {
        return read_path;
      }

      /// The first records of a checkpoint: the tag and @p clock.
      static void
      write_clock(std::ostream      &out,
                  const Clock       &clock,
                  const unsigned int n_elements);

      /**
       * Write @p bytes as the newest checkpoint in @p directory (rank 0
       * only): written whole under a name of its own, then the newest
       * becomes the one before and the new one the newest.
       */
      static void
      store(Output::Directory &directory, const std::string &bytes);

    private:
      const std::string directory_name;
      const MPI_Comm    communicator;
      std::string       read_path;
    };
  } // namespace BoundaryIntegral
} // namespace rupture

#endif
