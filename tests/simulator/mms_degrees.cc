// Order p + 1 in space for every polynomial degree p = 1..4: the static
// manufactured solution of inputs/mms_static.prm (2-D elasticity on the
// unit square, one quasi-static step, so no time error) on meshes of
// h = 1/4, 1/8, 1/16. The L2 error of the displacement must fall as
// h^(p+1); each line prints the order between two meshes, and the last
// line of each degree whether the finest pair reached p + 1 - 0.2.

#include <deal.II/base/mpi.h>

#include "mms_orders.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // The unit square in 2 x 2 cells, refined once to three times.
  for (unsigned int p = 1; p <= 4; ++p)
    tests::print_mms_orders(
      std::string(SOURCE_DIR) + "/inputs/mms_static.prm", p, 1, 3, 0.5);
}
