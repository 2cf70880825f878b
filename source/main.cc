#include <rupture/simulator/run.h>

#include <deal.II/base/mpi.h>

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<std::string>           arguments(argv + 1, argv + argc);
  return rupture::run_program(arguments, MPI_COMM_WORLD);
}
