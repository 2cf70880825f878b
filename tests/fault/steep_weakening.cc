// The diagnosis of a Newton failure caused by steep slip weakening, on the
// 1-D column of inputs/plane_wave.prm (implicit penalty method, dt = 0.01).
// - L_d = 1e-3 (weakening slope (mu_0 - mu_d) |T_n| / L_d = 1000 Pa/m,
//   below the penalty 1e5 but above the stiffness of the body that holds a
//   fault node at this time step): with Newton held to 2 iterations and one
//   step cut, the run stops and the message says that slip weakening is
//   steeper than the body at the slipping nodes and advises a shorter time
//   step; the cut before it names the same reason. With the default
//   iteration limit the same run converges.
// - Penalty 2 below the slope 10 of L_d = 0.1: the traction snaps to the
//   residual strength, and the failure message asks for a larger
//   tangential penalty or L_d.
// - The control: L_d = 1 (slope 1 Pa/m) held to one Newton iteration also
//   fails, and its message names neither cause.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cstdio>
#include <string>

namespace
{
  bool
  contains(const std::string &text, const std::string &what)
  {
    return text.find(what) != std::string::npos;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string prm = std::string(SOURCE_DIR) + "/inputs/plane_wave.prm";

  const auto run = [&](const std::string &dc,
                       const std::string &penalty,
                       const std::string &iterations,
                       const std::string &directory,
                       std::string       &screen,
                       std::string       &errors) {
    std::ostringstream sink;
    std::streambuf    *old = std::cout.rdbuf(sink.rdbuf());
    std::ostringstream error_sink;
    std::streambuf    *old_err = std::cerr.rdbuf(error_sink.rdbuf());
    const int          code    = rupture::run_program(
      {prm,
                   "--set",
                   "Fault/Linear slip weakening/Slip-weakening distance=" + dc,
                   "--set",
                   "Fault/Normal penalty=" + penalty,
                   "--set",
                   "Fault/Tangential penalty=" + penalty,
                   "--set",
                   "Solver/Maximum Newton iterations=" + iterations,
                   "--set",
                   "Solver/Maximum step cuts=1",
                   "--set",
                   "Solver/Linear solver=direct",
                   "--set",
                   "Time integration/End time=0.5",
                   "--set",
                   "Output directory=" + directory},
      MPI_COMM_WORLD);
    std::cout.rdbuf(old);
    std::cerr.rdbuf(old_err);
    screen = sink.str();
    errors = error_sink.str();
    return code;
  };

  std::string screen, errors;
  int         code = run("1e-3", "1e5", "2", "steep", screen, errors);
  std::printf("L_d = 1e-3, 2 Newton iterations: exit code %d\n", code);
  std::printf("  the step was cut first, naming the weakening: %s\n",
              contains(screen, "weakening steeper than the body") ? "yes" :
                                                                    "no");
  std::printf("  the message names weakening steeper than the body: %s\n",
              contains(errors,
                       "slip weakening is steeper than the stiffness "
                       "of the body") ?
                "yes" :
                "no");
  std::printf("  and advises a shorter time step: %s\n",
              contains(errors, "reduce <Time integration/Time step>") ? "yes" :
                                                                        "no");

  code = run("1e-3", "1e5", "25", "steep_default", screen, errors);
  std::printf("L_d = 1e-3, default Newton iterations: exit code %d\n", code);

  // The control: gentle weakening (L_d = 1, slope 1 Pa/m) held to one
  // Newton iteration fails too, but names neither cause.
  code = run("1", "1e5", "1", "gentle", screen, errors);
  std::printf("L_d = 1, 1 Newton iteration: exit code %d\n", code);
  std::printf("  the message names slip weakening: %s\n",
              contains(errors, "weakening is steeper") ? "yes" : "no");

  code = run("0.1", "2", "1", "snap", screen, errors);
  std::printf("L_d = 0.1, penalty 2, 1 Newton iteration: exit code %d\n", code);
  std::printf("  the message names weakening steeper than the penalty: %s\n",
              contains(errors, "steeper than the tangential penalty") ? "yes" :
                                                                        "no");
  std::printf("  and advises a larger penalty or L_d: %s\n",
              contains(errors, "raise <Fault/Tangential penalty> or L_d") ?
                "yes" :
                "no");
}
