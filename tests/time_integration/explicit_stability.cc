// The explicit scheme is stable up to the time step the program computes
// (Irons' element bound, a safe lower bound of the true limit) and blows up
// above it: at 0.95 times the stable step the energy stays bounded; at 1.5
// and 2 times the run stops, before writing the step, as soon as its energy
// balance error reaches half of the energy in play (or a value is no longer
// finite), with a message naming the step, the place and the stable limit.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        prm =
    std::string(SOURCE_DIR) + "/inputs/explicit_blow_up.prm";

  // First learn the stable step from the log of a short run.
  tests::run({prm, "--set", "Time integration/End time=1e-3"});
  const double stable =
    tests::find_number("output-blow-up/log.txt", "Stable explicit time step:");
  std::printf("stable step found: %s\n", stable > 0 ? "yes" : "no");

  for (const double factor : {0.95, 1.5, 2.0})
    {
      std::printf("dt = %.2f x stable step:\n", factor);
      std::string errors;
      const int   code = tests::run_capture(
        {prm,
           "--set",
           "Time integration/Time step=" + std::to_string(factor * stable),
           "--set",
           "Time integration/End time=" + std::to_string(4000 * stable)},
        errors);
      std::printf("  exit code %d\n", code);
      std::printf("  stopped as unstable, naming the stable limit: %s\n",
                  ((errors.find("no longer finite") != std::string::npos ||
                    errors.find("the explicit scheme is unstable") !=
                      std::string::npos) &&
                   errors.find("stable limit") != std::string::npos) ?
                    "yes" :
                    "no");
      std::printf("  names the step and the place: %s\n",
                  (errors.find("At step ") != std::string::npos &&
                   errors.find("largest in component") != std::string::npos) ?
                    "yes" :
                    "no");
      if (code != 0)
        {
          // The statistics of the steps before the stop are kept, and none
          // of the values written is a NaN or Inf.
          const auto rows = tests::read_statistics("output-blow-up/statistics");
          const std::string::size_type at = errors.find("At step ");
          const unsigned int           failed_step =
            at == std::string::npos ? 0 : std::atoi(errors.c_str() + at + 8);
          bool finite = true;
          for (const auto &r : rows)
            for (const double v : r)
              finite = finite && std::isfinite(v);
          std::printf("  statistics kept up to the step before the stop: %s, "
                      "all finite: %s\n",
                      (!rows.empty() && failed_step > 1 &&
                       static_cast<unsigned int>(rows.back()[0]) ==
                         failed_step - 1) ?
                        "yes" :
                        "no",
                      finite ? "yes" : "no");
        }
      if (code == 0)
        {
          const auto rows = tests::read_statistics("output-blow-up/statistics");
          double     e0 = rows[0][4] + rows[0][5], emax = e0;
          for (const auto &r : rows)
            emax = std::max(emax, r[4] + r[5]);
          std::printf("  energy bounded within 1%%: %s\n",
                      emax < 1.01 * e0 ? "yes" : "no");
        }
    }
}
