#ifndef rupture_output_log_h
#define rupture_output_log_h

#include <fstream>
#include <memory>
#include <ostream>
#include <sstream>
#include <streambuf>
#include <string>

namespace rupture
{
  namespace Output
  {
    /**
     * The screen stream of rank 0, mirrored into <output>/log.txt. Until the
     * output directory is known to be safe to write (the input has been
     * checked), lines are kept in memory; attach_file() writes them out and
     * mirrors everything after. Both the screen and the file are flushed
     * at the end of every line.
     */
    class Log
    {
    public:
      Log();
      ~Log();

      std::ostream &
      stream();

      /**
       * Start mirroring into @p filename (truncating it), beginning with
       * everything written so far.
       */
      void
      attach_file(const std::string &filename, const bool append = false);

    private:
      class TeeBuffer : public std::streambuf
      {
      public:
        std::streambuf    *screen = nullptr;
        std::ostringstream pending;
        std::ofstream      file;

      protected:
        int
        overflow(int c) override;
        std::streamsize
        xsputn(const char *s, std::streamsize n) override;
        int
        sync() override;
      };

      TeeBuffer                     buffer;
      std::unique_ptr<std::ostream> out;
    };
  } // namespace Output
} // namespace rupture

#endif
