// Cochard and Madariaga's rate weakening (the review's eq. 5.9) with
// sigma_0 = 10 MPa, V0 = 0.5 m/s and a residual strength of 2 MPa:
// - the strength at rest, at V0 and at fast slip, and that it does not
//   depend on the normal traction;
// - its derivative with respect to the slip increment against central
//   differences;
// - the uniqueness check: an impedance above sigma_0 / V0 passes, one
//   below it throws, naming the point and the parameters;
// - a parameter out of range is refused with its name.

#include <rupture/base/utilities.h>
#include <rupture/friction/interface.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <cstdio>

using namespace dealii;
using rupture::Friction::State;

namespace
{
  std::unique_ptr<rupture::Friction::Interface>
  make(const std::string &drop = "1e7")
  {
    ParameterHandler prm;
    prm.enter_subsection("Fault");
    rupture::Friction::declare_parameters(prm);
    prm.set("Friction law", "cochard madariaga");
    prm.enter_subsection("Cochard Madariaga");
    prm.set("Maximum traction drop", drop);
    prm.set("Reference slip rate", "0.5");
    prm.set("Residual strength", "2e6");
    prm.leave_subsection();
    auto law = rupture::Friction::create(prm);
    prm.leave_subsection();
    return law;
  }

  const Point<3> origin(1000, 0, -7500);
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                       law = make();
  State                            state;
  law->initialize_state(origin, state);
  const double dt = 0.01;

  std::printf("1. Strength (MPa) at the slip rate V, pressures 0 and 50 "
              "MPa\n");
  for (const double V : {0., 0.5, 5., 500.})
    {
      double       dl = 0, dp = 0;
      const double s0 = law->strength(origin, state, V * dt, dt, 0, dl, dp);
      const double s1 = law->strength(origin, state, V * dt, dt, 5e7, dl, dp);
      std::printf("   V = %-5g %.6f %.6f (2 + 10 V0/(V0 + V) = %.6f), "
                  "d/dpressure = %g, friction coefficient = %g\n",
                  V,
                  s0 / 1e6,
                  s1 / 1e6,
                  2 + 10 * 0.5 / (0.5 + V),
                  dp,
                  law->coefficient(origin, state, V * dt, dt, dl));
    }

  std::printf("\n2. d strength / d slip increment against central "
              "differences\n");
  for (const double V : {0.1, 0.5, 5.})
    {
      double       d = 0, u = 0, p = 0;
      const double l = V * dt, h = 1e-6 * l;
      law->strength(origin, state, l, dt, 1e7, d, p);
      const double fd = (law->strength(origin, state, l + h, dt, 1e7, u, p) -
                         law->strength(origin, state, l - h, dt, 1e7, u, p)) /
                        (2 * h);
      std::printf("   V = %-4g %s\n",
                  V,
                  std::abs(d - fd) < 1e-6 * std::abs(fd) ? "agrees" :
                                                           "DIFFERS");
    }

  std::printf("\n3. Uniqueness: sigma_0 / V0 = 2e7 Pa s/m\n");
  for (const double Z : {1e8, 1e7})
    try
      {
        law->check_uniqueness(origin, state, 1e7, Z);
        std::printf("   Z = %g: unique\n", Z);
      }
    catch (const ExceptionBase &e)
      {
        std::printf("   Z = %g: refused:\n     %s\n",
                    Z,
                    rupture::Utilities::message_of(e).c_str());
      }

  std::printf("\n4. A negative traction drop\n");
  try
    {
      const auto bad = make("-1");
      State      s;
      bad->initialize_state(origin, s);
      std::printf("   accepted\n");
    }
  catch (const ExceptionBase &e)
    {
      std::printf("   refused: %s\n",
                  rupture::Utilities::message_of(e).c_str());
    }
}
