#ifndef rupture_base_on_root_h
#define rupture_base_on_root_h

#include <rupture/base/utilities.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <exception>
#include <string>

namespace rupture
{
  namespace Utilities
  {
    /**
     * Run @p action on rank 0 of @p communicator and throw its error on
     * every rank (a failure to write a file must not leave the other ranks
     * waiting in the next collective call). Collective.
     */
    template <typename Action>
    void
    on_root(const MPI_Comm communicator, const Action &action)
    {
      std::string error;
      if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
        try
          {
            action();
          }
        catch (const dealii::ExceptionBase &e)
          {
            error = message_of(e);
          }
        catch (const std::exception &e)
          {
            error = e.what();
          }
      error = dealii::Utilities::MPI::broadcast(communicator, error, 0);
      AssertThrow(error.empty(), dealii::ExcMessage(error));
    }
  } // namespace Utilities
} // namespace rupture

#endif
