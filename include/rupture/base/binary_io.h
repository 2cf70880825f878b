#ifndef rupture_base_binary_io_h
#define rupture_base_binary_io_h

#include <deal.II/base/exceptions.h>

#include <cstdint>
#include <istream>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace rupture
{
  /**
   * The few types a checkpoint holds, written and read as raw bytes (the
   * machine's own representation: a checkpoint is read back on the machine,
   * or the cluster, that wrote it). Doubles keep every bit, so a restarted
   * run continues with exactly the numbers of the run that stopped.
   */
  namespace BinaryIO
  {
    inline void
    write(std::ostream &out, const double x)
    {
      out.write(reinterpret_cast<const char *>(&x), sizeof(x));
    }

    inline void
    write(std::ostream &out, const std::uint64_t x)
    {
      out.write(reinterpret_cast<const char *>(&x), sizeof(x));
    }

    inline void
    write(std::ostream &out, const std::string &s)
    {
      write(out, static_cast<std::uint64_t>(s.size()));
      out.write(s.data(), s.size());
    }

    inline void
    write(std::ostream &out, const std::vector<double> &v)
    {
      write(out, static_cast<std::uint64_t>(v.size()));
      out.write(reinterpret_cast<const char *>(v.data()),
                v.size() * sizeof(double));
    }

    inline void
    write(std::ostream &out, const std::vector<std::vector<double>> &v)
    {
      write(out, static_cast<std::uint64_t>(v.size()));
      for (const auto &x : v)
        write(out, x);
    }

    inline void
    write(std::ostream                                      &out,
          const std::vector<std::pair<double, std::string>> &v)
    {
      write(out, static_cast<std::uint64_t>(v.size()));
      for (const auto &[t, s] : v)
        {
          write(out, t);
          write(out, s);
        }
    }

    inline void
    write(std::ostream &out, const std::map<std::string, double> &records)
    {
      write(out, static_cast<std::uint64_t>(records.size()));
      for (const auto &[name, value] : records)
        {
          write(out, name);
          write(out, value);
        }
    }

    /**
     * The named scalars of a checkpoint ("time/step", "energy/kinetic",
     * ...): each owner of a part of the state writes and reads its own.
     */
    using Records = std::map<std::string, double>;

    /// The record @p name; a missing one is a damaged checkpoint.
    inline double
    record(const Records &records, const std::string &name)
    {
      const auto r = records.find(name);
      AssertThrow(r != records.end(),
                  dealii::ExcMessage("A checkpoint has no record <" + name +
                                     ">: it is damaged or not a checkpoint of "
                                     "this program."));
      return r->second;
    }

    /// Read raw bytes; a short read is a damaged checkpoint.
    inline void
    read_bytes(std::istream &in, char *data, const std::size_t n)
    {
      in.read(data, n);
      AssertThrow(in.good() || (in.eof() &&
                                in.gcount() == static_cast<std::streamsize>(n)),
                  dealii::ExcMessage("A checkpoint file ends early: it is "
                                     "damaged or not a checkpoint of this "
                                     "program."));
    }

    inline void
    read(std::istream &in, double &x)
    {
      read_bytes(in, reinterpret_cast<char *>(&x), sizeof(x));
    }

    inline void
    read(std::istream &in, std::uint64_t &x)
    {
      read_bytes(in, reinterpret_cast<char *>(&x), sizeof(x));
    }

    /// A length, checked against what a checkpoint can hold.
    inline std::uint64_t
    read_size(std::istream &in)
    {
      std::uint64_t n = 0;
      read(in, n);
      AssertThrow(n < (std::uint64_t(1) << 40),
                  dealii::ExcMessage("A checkpoint file holds a length of " +
                                     std::to_string(n) +
                                     ": it is damaged or not a checkpoint of "
                                     "this program."));
      return n;
    }

    inline void
    read(std::istream &in, std::string &s)
    {
      s.resize(read_size(in));
      read_bytes(in, s.data(), s.size());
    }

    inline void
    read(std::istream &in, std::vector<double> &v)
    {
      v.resize(read_size(in));
      read_bytes(in,
                 reinterpret_cast<char *>(v.data()),
                 v.size() * sizeof(double));
    }

    inline void
    read(std::istream &in, std::vector<std::vector<double>> &v)
    {
      v.resize(read_size(in));
      for (auto &x : v)
        read(in, x);
    }

    inline void
    read(std::istream &in, std::map<std::string, double> &records)
    {
      records.clear();
      const std::uint64_t n = read_size(in);
      for (std::uint64_t k = 0; k < n; ++k)
        {
          std::string name;
          double      value;
          read(in, name);
          read(in, value);
          records[name] = value;
        }
    }

    inline void
    read(std::istream &in, std::vector<std::pair<double, std::string>> &v)
    {
      v.resize(read_size(in));
      for (auto &[t, s] : v)
        {
          read(in, t);
          read(in, s);
        }
    }
  } // namespace BinaryIO
} // namespace rupture

#endif
