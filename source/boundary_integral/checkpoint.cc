// The boundary-integral run's checkpoint file.

#include <rupture/base/binary_io.h>
#include <rupture/base/on_root.h>
#include <rupture/boundary_integral/checkpoint.h>
#include <rupture/output/directory.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace rupture
{
  namespace BoundaryIntegral
  {
    namespace
    {
      const char *const tag      = "rupture boundary-integral checkpoint 1";
      const char *const newest   = "checkpoint/boundary_integral.bin";
      const char *const previous = "checkpoint/boundary_integral.previous.bin";
      const char *const writing  = "checkpoint/boundary_integral.writing.bin";
    } // namespace



    Checkpoint::Checkpoint(const std::string &directory_name,
                           const MPI_Comm     communicator)
      : directory_name(directory_name)
      , communicator(communicator)
    {}



    std::string
    Checkpoint::read(Clock &clock, const unsigned int n_elements)
    {
      using dealii::ExcMessage;
      std::string bytes;
      Utilities::on_root(communicator, [&]() {
        for (const std::string name : {newest, previous})
          {
            read_path = directory_name + "/" + name;
            std::ifstream file(read_path, std::ios::binary);
            if (file)
              {
                std::ostringstream content;
                content << file.rdbuf();
                bytes = content.str();
                return;
              }
          }
        AssertThrow(false,
                    ExcMessage("--resume: there is no checkpoint <" +
                               directory_name + "/" + newest +
                               "> to continue from. A run writes one "
                               "with <Checkpoint/Interval> or "
                               "<Wall-clock interval>."));
      });
      read_path = dealii::Utilities::MPI::broadcast(communicator, read_path, 0);
      bytes     = dealii::Utilities::MPI::broadcast(communicator, bytes, 0);
      std::istringstream  in(bytes);
      std::string         read_tag;
      std::vector<double> scalars;
      BinaryIO::read(in, read_tag);
      AssertThrow(read_tag == tag,
                  ExcMessage("--resume: <" + read_path +
                             "> is not a checkpoint of the "
                             "boundary-integral method."));
      BinaryIO::read(in, scalars);
      AssertThrow(in.good(),
                  ExcMessage("--resume: the checkpoint <" + read_path +
                             "> is damaged."));
      AssertThrow(scalars.size() == 8 && scalars[7] == n_elements,
                  ExcMessage("--resume: the checkpoint <" + read_path +
                             "> has another number of elements than "
                             "<Boundary integral/Fault depth> and "
                             "<Element size> give."));
      clock.t        = scalars[0];
      clock.dt       = scalars[1];
      clock.last_dt  = scalars[2];
      clock.dt_min   = scalars[3];
      clock.dt_max   = scalars[4];
      clock.steps    = static_cast<unsigned long>(scalars[5]);
      clock.n_events = static_cast<unsigned long>(scalars[6]);
      return bytes.substr(static_cast<std::size_t>(in.tellg()));
    }



    void
    Checkpoint::write_clock(std::ostream      &out,
                            const Clock       &clock,
                            const unsigned int n_elements)
    {
      BinaryIO::write(out, std::string(tag));
      BinaryIO::write(out,
                      std::vector<double>{clock.t,
                                          clock.dt,
                                          clock.last_dt,
                                          clock.dt_min,
                                          clock.dt_max,
                                          double(clock.steps),
                                          double(clock.n_events),
                                          double(n_elements)});
    }



    void
    Checkpoint::store(Output::Directory &directory, const std::string &bytes)
    {
      // (A run killed between the two renames leaves the one before,
      // which --resume takes.)
      const std::string path_writing  = directory.record(writing);
      const std::string path_newest   = directory.record(newest);
      const std::string path_previous = directory.record(previous);
      directory.write(writing, bytes);
      if (std::filesystem::exists(path_newest))
        std::filesystem::rename(path_newest, path_previous);
      std::filesystem::rename(path_writing, path_newest);
    }
  } // namespace BoundaryIntegral
} // namespace rupture
