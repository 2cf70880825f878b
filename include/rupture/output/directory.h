#ifndef rupture_output_directory_h
#define rupture_output_directory_h

#include <deal.II/base/mpi.h>

#include <fstream>
#include <set>
#include <string>

namespace rupture
{
  namespace Output
  {
    /**
     * The output directory of a run, and the rules that keep the results of
     * runs apart and safe (doc/manual.md, "What the program guarantees"):
     *
     * - The name must be a directory other than the root of the file
     *   system; check_name() refuses the rest before anything is touched.
     * - open() takes a lock, the file <tt>.rupture.lock</tt> with an
     *   exclusive flock() held for the whole run: a second run into the same
     *   directory is refused with the process that holds it. A lock left by
     *   a process that died is free, because the kernel releases flock()s
     *   with the process, and is taken over.
     * - Every file the run writes is named in a manifest before it is
     *   written, one per rank (<tt>.rupture-manifest.N</tt>, for the pieces
     *   that rank N writes). open() first removes the files that the
     *   manifests of the earlier run name, and nothing else: results of a
     *   longer earlier run (later snapshots, pieces of more ranks) cannot
     *   mix with the new run's, and files a user put there stay.
     * - write() writes a file under a temporary name and renames it, so no
     *   reader ever sees half a file; a temporary file left by a killed run
     *   is removed with the file it belonged to.
     *
     * Restart (issue 16) builds on the manifest: a continued run keeps the
     * files its checkpoint still describes.
     */
    class Directory
    {
    public:
      /**
       * Refuse names that cannot be an output directory: empty, the root of
       * the file system, or an existing file that is not a directory. The
       * message names the entry @p entry_name.
       */
      static void
      check_name(const std::string &name, const std::string &entry_name);

      Directory(const std::string &name, const MPI_Comm communicator);

      /**
       * Releases the lock (removing the lock file) and closes the manifest.
       */
      ~Directory();

      Directory(const Directory &) = delete;
      Directory &
      operator=(const Directory &) = delete;

      /**
       * Create the directory, take its lock and remove the files of the
       * earlier run. Collective: if rank 0 cannot do any of that, every rank
       * throws the same message. Called once every check of the input has
       * passed. A run that continues from a checkpoint
       * (@p continue_earlier_run) keeps the earlier run's files and adds to
       * its manifests instead.
       */
      void
      open(const bool continue_earlier_run = false);

      /**
       * The name as the user gave it, and as an absolute path.
       */
      const std::string &
      name() const;
      /// Whether open() has succeeded (only then may results be written).
      bool
      is_open() const
      {
        return opened;
      }
      std::string
      absolute_name() const;

      /**
       * Record @p relative (a path inside the directory, e.g.
       * "solution/solution_00010.0.vtu") in this rank's manifest, if it is
       * not there yet, and return its full path. Subdirectories are created
       * on the way.
       */
      std::string
      record(const std::string &relative);

      /**
       * Record @p relative and write @p contents to it atomically.
       */
      void
      write(const std::string &relative, const std::string &contents);

      /**
       * The name of the lock file and of rank @p rank's manifest, relative
       * to the directory.
       */
      static const char *const lock_name;
      static std::string
      manifest_name(const unsigned int rank);

    private:
      /// Rank 0's part of open(); returns an error message or "".
      std::string
      open_on_root();

      /// Remove what the manifests of an earlier run name. Rank 0.
      void
      remove_earlier_run();

      const std::string     directory;
      const MPI_Comm        communicator;
      bool                  opened     = false;
      bool                  continuing = false;
      int                   lock_fd    = -1;
      std::ofstream         manifest;
      std::set<std::string> recorded;
    };
  } // namespace Output
} // namespace rupture

#endif
