// Convergence in space against manufactured solutions in 3-D in an
// anisotropic medium whose tensor's shape varies in space
// (inputs/tensor_field_mms_3d.prm and tensor_field_mms_3d_static.prm,
// written by contrib/make-mms): a general tensor with all 21 constants
// non-zero in the model's frame, nine of them (C11, C22, C33, C12, C44,
// C16, C26, C46, C66) independent functions of x, y, z, density factor
// 1 + x^2 / 2 on the clamped unit cube, u = U(x) (1 + t^2). Dynamics with
// implicit Newmark (assembled matrices, the tensor at each quadrature
// point) and the explicit scheme (the matrix-free operator's tensor per
// quadrature point, the lumped mass, the stable step bounded by the energy
// ratio), which both integrate u exactly in time; and statics (the same u
// without inertia) with the quasi-static scheme. L2 errors at t = 0.5 on
// 4 and 8 cells per side (and 16 for implicit Newmark at degree 1):
// second order at degree 1, third at degree 2. (Debug: some 3 minutes.)

#include <deal.II/base/mpi.h>

#include "mms_ladder.h"

#include <cstdio>
#include <string>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string inputs = std::string(SOURCE_DIR) + "/inputs/";
  for (const std::string scheme :
       {"implicit Newmark", "explicit central difference", "quasi-static"})
    for (const unsigned int degree : {1u, 2u})
      {
        if (scheme[0] == 'e' && degree == 2)
          continue; // (the explicit Q2 kernel is the 2-D test's)
        std::printf("%s, degree %u:\n", scheme.c_str(), degree);
        tests::print_mms_ladder(inputs + (scheme[0] == 'q' ?
                                            "tensor_field_mms_3d_static.prm" :
                                            "tensor_field_mms_3d.prm"),
                                scheme,
                                {},
                                degree,
                                degree == 1 && scheme[0] == 'i' ? 3 : 2);
      }
}
