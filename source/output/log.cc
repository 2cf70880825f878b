#include <rupture/output/log.h>

#include <iostream>

namespace rupture
{
  namespace Output
  {
    Log::Log()
    {
      buffer.screen = std::cout.rdbuf();
      out           = std::make_unique<std::ostream>(&buffer);
    }



    Log::~Log()
    {
      out->flush();
    }



    std::ostream &
    Log::stream()
    {
      return *out;
    }



    void
    Log::attach_file(const std::string &filename, const bool append)
    {
      out->flush();
      buffer.file.open(filename, append ? std::ios::app : std::ios::out);
      if (buffer.file)
        {
          buffer.file << buffer.pending.str();
          buffer.pending.str("");
        }
    }



    int
    Log::TeeBuffer::overflow(int c)
    {
      if (c == EOF)
        return !EOF;
      const char ch = static_cast<char>(c);
      screen->sputc(ch);
      if (file.is_open())
        file.put(ch);
      else
        pending.put(ch);
      if (ch == '\n')
        sync();
      return c;
    }



    std::streamsize
    Log::TeeBuffer::xsputn(const char *s, std::streamsize n)
    {
      screen->sputn(s, n);
      if (file.is_open())
        file.write(s, n);
      else
        pending.write(s, n);
      // Line by line: a batch job's stdout is a file, block-buffered, and
      // a run killed at its time limit would otherwise leave nothing.
      if (std::char_traits<char>::find(s, n, '\n') != nullptr)
        sync();
      return n;
    }



    int
    Log::TeeBuffer::sync()
    {
      screen->pubsync();
      if (file.is_open())
        file.flush();
      return 0;
    }
  } // namespace Output
} // namespace rupture
