#ifndef rupture_simulator_run_h
#define rupture_simulator_run_h

#include <deal.II/base/mpi.h>

#include <string>
#include <vector>

namespace rupture
{
  /**
   * The whole program behind the command line
   *   rupture [--help] [--print-parameters [markdown|prm]]
   *           [--set "Section/Entry=value"]... file.prm
   * with MPI already initialised. Returns the exit code: 0 on success, 1 on
   * any error, after printing one clear message. Tests call it directly.
   */
  int
  run_program(const std::vector<std::string> &arguments,
              const MPI_Comm                  communicator);
} // namespace rupture

#endif
