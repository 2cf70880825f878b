// Order p + 1 in space for every polynomial degree p = 1..4 in 3-D: the
// static manufactured solution of inputs/mms_static_3d.prm (elasticity on
// the unit cube, u = (1, 2, 3) sin(pi x) sin(pi y) sin(pi z), one
// quasi-static step, so no time error, solved matrix-free with the
// geometric multigrid at each degree) on two meshes, h = 1/4 and 1/8 at
// degree 1, h = 1/2 and 1/4 at degrees 2 to 4 (h along x and y; the cells
// are half as long along z). Degree 4's finer mesh takes most of the test's
// time (about 90 s in a Debug build). The L2
// error of the displacement must fall as h^(p+1): each degree prints the
// order between its two meshes and whether it reached p + 1 - 0.2.

#include <deal.II/base/mpi.h>

#include "mms_orders.h"

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // The unit cube in 1 x 1 x 2 cells; h is the cell size along x and y.
  for (unsigned int p = 1; p <= 4; ++p)
    {
      const unsigned int coarse = (p == 1 ? 2 : 1);
      tests::print_mms_orders(std::string(SOURCE_DIR) +
                                "/inputs/mms_static_3d.prm",
                              p,
                              coarse,
                              coarse + 1,
                              1.0);
    }
}
