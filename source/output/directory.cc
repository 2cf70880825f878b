#include <rupture/base/utilities.h>
#include <rupture/output/directory.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <sstream>
#include <vector>

namespace rupture
{
  namespace Output
  {
    using dealii::ExcMessage;
    namespace fs = std::filesystem;

    const char *const Directory::lock_name = ".rupture.lock";



    std::string
    Directory::manifest_name(const unsigned int rank)
    {
      return ".rupture-manifest." + std::to_string(rank);
    }



    namespace
    {
      /**
       * Whether @p relative is a path strictly inside a directory: not
       * empty, not absolute, without "." or ".." components. Manifests are
       * read back from disk, so an entry that a user edited must not reach
       * outside the output directory.
       */
      bool
      is_inside(const std::string &relative)
      {
        if (relative.empty() || relative[0] == '/')
          return false;
        for (const auto &part : fs::path(relative))
          if (part == ".." || part == ".")
            return false;
        return true;
      }



      /**
       * The host name, for the lock's note of who holds it.
       */
      std::string
      host_name()
      {
        char name[256] = {};
        if (gethostname(name, sizeof(name) - 1) != 0)
          return "unknown host";
        return name;
      }
    } // namespace



    void
    Directory::check_name(const std::string &name,
                          const std::string &entry_name)
    {
      const std::string allowed =
        " Allowed is the name of a directory, relative to where the program "
        "runs (e.g. 'output') or absolute, other than the root of the file "
        "system.";
      AssertThrow(!name.empty(),
                  ExcMessage("<" + entry_name + "> is empty." + allowed));
      std::error_code error;
      const fs::path absolute = fs::weakly_canonical(fs::absolute(name), error);
      AssertThrow(error || absolute != absolute.root_path(),
                  ExcMessage("<" + entry_name + "> = '" + name +
                             "' is the root of the file system: every output "
                             "file would go there." +
                             allowed));
      AssertThrow(!fs::exists(name, error) || fs::is_directory(name, error),
                  ExcMessage("<" + entry_name + "> = '" + name +
                             "' exists and is not a directory." + allowed));
    }



    Directory::Directory(const std::string &name, const MPI_Comm communicator)
      : directory(name)
      , communicator(communicator)
    {}



    Directory::~Directory()
    {
      if (manifest.is_open())
        manifest.close();
      if (lock_fd >= 0)
        {
          // Unlink first: a run waiting for the lock checks that the file it
          // locked is still the one under the name.
          ::unlink((directory + "/" + lock_name).c_str());
          ::close(lock_fd);
        }
    }



    const std::string &
    Directory::name() const
    {
      return directory;
    }



    std::string
    Directory::absolute_name() const
    {
      std::error_code error;
      const fs::path  path =
        fs::weakly_canonical(fs::absolute(directory), error);
      return error ? fs::absolute(directory).string() : path.string();
    }



    void
    Directory::open(const bool continue_earlier_run)
    {
      continuing = continue_earlier_run;
      const bool root =
        dealii::Utilities::MPI::this_mpi_process(communicator) == 0;
      std::string error = root ? open_on_root() : std::string();
      error = dealii::Utilities::MPI::broadcast(communicator, error);
      AssertThrow(error.empty(), ExcMessage(error));
      opened = true;
    }



    std::string
    Directory::open_on_root()
    {
      std::error_code error;
      fs::create_directories(directory, error);
      if (error)
        return "The output directory <" + directory +
               "> cannot be created: " + error.message() + ".";

      // The lock. flock() locks belong to the open file, so the kernel
      // drops them with a dead process: a lock file left behind is free.
      const std::string lock_path = directory + "/" + lock_name;
      for (unsigned int attempt = 0; attempt < 100 && lock_fd < 0; ++attempt)
        {
          const int fd =
            ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
          if (fd < 0)
            return "The lock file <" + lock_path + "> cannot be created (" +
                   std::strerror(errno) +
                   "): is the output directory writable?";
          if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
            {
              const int   code = errno;
              std::string holder(512, '\0');
              const auto  n = ::read(fd, holder.data(), holder.size() - 1);
              holder.resize(std::max<ssize_t>(0, n));
              while (!holder.empty() && holder.back() == '\n')
                holder.pop_back();
              ::close(fd);
              if (code == EWOULDBLOCK)
                return "Another run is writing into the output directory <" +
                       directory + "> (" +
                       (holder.empty() ? std::string("its lock is held") :
                                         holder) +
                       "). Two runs in one directory would mix their "
                       "results: wait for it to end, or give this run "
                       "another <Output directory>.";
              return "The lock file <" + lock_path + "> cannot be locked (" +
                     std::strerror(code) + ").";
            }
          // The run that held the lock may have removed the file between
          // our open() and flock(); then we locked a file nobody sees.
          struct stat mine, named;
          if (::fstat(fd, &mine) == 0 &&
              ::stat(lock_path.c_str(), &named) == 0 &&
              mine.st_ino == named.st_ino && mine.st_dev == named.st_dev)
            lock_fd = fd;
          else
            ::close(fd);
        }
      if (lock_fd < 0)
        return "The lock file <" + lock_path +
               "> keeps changing; is another "
               "program removing it?";
      std::ostringstream note;
      const std::time_t  now = std::time(nullptr);
      char               date[64];
      std::strftime(date,
                    sizeof(date),
                    "%Y-%m-%d %H:%M:%S UTC",
                    std::gmtime(&now));
      note << "process " << ::getpid() << " on " << host_name() << ", started "
           << date << "\n";
      const std::string text = note.str();
      if (::ftruncate(lock_fd, 0) != 0 ||
          ::pwrite(lock_fd, text.data(), text.size(), 0) !=
            static_cast<ssize_t>(text.size()))
        return "The lock file <" + lock_path + "> cannot be written (" +
               std::strerror(errno) + ").";

      if (!continuing)
        remove_earlier_run();

      manifest.open(directory + "/" + manifest_name(0),
                    continuing ? std::ios::app : std::ios::trunc);
      if (!manifest)
        return "The manifest <" + directory + "/" + manifest_name(0) +
               "> cannot be written: is the output directory writable?";
      manifest << "# Files written by rupture into this directory (rank 0 "
                  "and the run's own files); the next run removes them.\n"
               << std::flush;
      return "";
    }



    void
    Directory::remove_earlier_run()
    {
      std::vector<fs::path> manifests;
      std::error_code       error;
      for (const auto &entry : fs::directory_iterator(directory, error))
        if (entry.path().filename().string().rfind(".rupture-manifest.", 0) ==
            0)
          manifests.push_back(entry.path());

      std::vector<std::string> subdirectories;
      for (const auto &path : manifests)
        {
          std::ifstream in(path);
          std::string   line;
          while (std::getline(in, line))
            {
              if (line.empty() || line[0] == '#')
                continue;
              if (line.back() == '/')
                {
                  line.pop_back();
                  if (is_inside(line))
                    subdirectories.push_back(line);
                  continue;
                }
              if (!is_inside(line) || line == lock_name)
                continue;
              for (const std::string &name : {line, line + ".tmp"})
                {
                  const fs::path file = fs::path(directory) / name;
                  if (fs::is_regular_file(fs::symlink_status(file, error)) ||
                      fs::is_symlink(fs::symlink_status(file, error)))
                    fs::remove(file, error);
                }
            }
          fs::remove(path, error);
        }
      // Deepest first; a directory that still holds files (a user's) stays.
      std::sort(subdirectories.begin(),
                subdirectories.end(),
                [](const std::string &a, const std::string &b) {
                  return a.size() > b.size();
                });
      for (const auto &d : subdirectories)
        if (fs::is_directory(
              fs::symlink_status(fs::path(directory) / d, error)) &&
            fs::is_empty(fs::path(directory) / d, error))
          fs::remove(fs::path(directory) / d, error);
    }



    std::string
    Directory::record(const std::string &relative)
    {
      Assert(opened, dealii::ExcInternalError());
      Assert(is_inside(relative), dealii::ExcInternalError());
      if (recorded.insert(relative).second)
        {
          if (!manifest.is_open())
            {
              // Ranks other than 0 start their manifest with their first
              // file; rank 0 removed the earlier run's before they could.
              const unsigned int rank =
                dealii::Utilities::MPI::this_mpi_process(communicator);
              manifest.open(directory + "/" + manifest_name(rank),
                            continuing ? std::ios::app : std::ios::trunc);
              AssertThrow(manifest,
                          ExcMessage("The manifest <" + directory + "/" +
                                     manifest_name(rank) +
                                     "> cannot be written."));
              manifest << "# Files written by rupture into this directory "
                          "(rank "
                       << rank << "); the next run removes them.\n";
            }
          // Parent directories first, so that the next run can remove them
          // once they are empty.
          const fs::path parent = fs::path(relative).parent_path();
          if (!parent.empty() && recorded.insert(parent.string() + "/").second)
            {
              manifest << parent.string() << "/\n";
              std::error_code error;
              fs::create_directories(fs::path(directory) / parent, error);
              AssertThrow(!error,
                          ExcMessage(
                            "The directory <" +
                            (fs::path(directory) / parent).string() +
                            "> cannot be created: " + error.message()));
            }
          // Named before it exists: a run killed while writing it leaves
          // nothing that the next run does not know of.
          manifest << relative << std::endl;
        }
      return directory + "/" + relative;
    }



    void
    Directory::write(const std::string &relative, const std::string &contents)
    {
      Utilities::write_file_atomically(record(relative), contents);
    }
  } // namespace Output
} // namespace rupture
