// Convergence in space against a manufactured solution of 2-D dynamics in
// an anisotropic medium whose tensor's shape varies in space
// (inputs/tensor_field_mms.prm, written by contrib/make-mms): a general
// tensor whose in-plane constants C11, C22, C12, C16, C26 and C66 are
// independent functions of x and y (<Material/Stiffness> as functions),
// density factor 1 + x^2 / 2, u = U(x) (1 + t^2), which both time
// integrators integrate exactly, so that the error left is the space
// discretization's. L2 errors at t = 0.5 with h halved: second order at
// degree 1 and third at degree 2, with implicit Newmark (assembled
// matrices, the tensor at each quadrature point) and the explicit scheme
// (the matrix-free operator's tensor per quadrature point, lumped mass,
// the stable step bounded by the energy ratio to the reference tensor).

#include <deal.II/base/mpi.h>

#include "mms_ladder.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        prm =
    std::string(SOURCE_DIR) + "/inputs/tensor_field_mms.prm";
  for (const std::string scheme : {"implicit Newmark",
                                   "explicit central "
                                   "difference"})
    for (const unsigned int degree : {1u, 2u})
      {
        std::printf("%s, degree %u:\n", scheme.c_str(), degree);
        tests::print_mms_ladder(prm, scheme, {}, degree);
      }
}
