// <Solver/Limit stick crossings> on the reduced 2-D Northeast-Japan model
// of scene/northeast_japan_fault_2d.prm, run through its whole rupture
// (8 s), with Newton's method started from u + dt v. Fault nodes that come to
// rest make a full Newton step jump from slip in one direction across the stick
// region into slip in the other; the limit stops them inside the stick region.
// It changes only how Newton's method gets to the solution of each step, not
// the solution: the run with the limit needs fewer Newton iterations, and its
// fault results agree with those of the run without it to 1e-3 (the runs differ
// by the Newton tolerance and by where steps were cut).
//
// Second, a node whose solution does lie on the far side of its stick region:
// the 1-D column of inputs/plane_wave.prm with time steps 1000 times its
// explicit limit (20.4 s; the study of doc/stability.md). The limit stops the
// node in stick, the next iteration sends it back, and so on; the step is then
// tried once more without the limit ("tried again without the limit" in the
// log, once) instead of being cut until the run stops. The final slip equals
// that of the run without the limit to 1e-9.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Every rank reads the statistics; only the first one prints.
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::freopen("/dev/null", "w", stdout);
  const std::string prm =
    std::string(SOURCE_DIR) + "/../scene/northeast_japan_fault_2d.prm";
  // 0-based columns of statistics with a fault.
  const unsigned int newton = 10, slip = 14, rate = 15, moment = 16;

  std::vector<double> results[2];
  unsigned int        iterations[2] = {0, 0};
  for (unsigned int limit = 0; limit < 2; ++limit)
    {
      if (tests::run({prm,
                      "--set",
                      "Output directory=output-stick-crossings",
                      "--set",
                      "Time integration/End time=8",
                      "--set",
                      "Solver/Newton predictor=constant velocity",
                      "--set",
                      std::string("Solver/Limit stick crossings=") +
                        (limit ? "true" : "false")}) != 0)
        std::printf("run failed\n");
      const auto rows =
        tests::read_statistics("output-stick-crossings/statistics");
      for (const auto &r : rows)
        iterations[limit] += static_cast<unsigned int>(r[newton]);
      results[limit] = rows.back();
      std::printf("limit %-5s: %u Newton iterations; at t = 8 s max slip "
                  "%.4g m, max slip rate %.4g m/s, moment %.4g N\n",
                  limit ? "true" : "false",
                  iterations[limit],
                  results[limit][slip],
                  results[limit][rate],
                  results[limit][moment]);
    }
  std::printf("fewer Newton iterations with the limit: %s\n",
              iterations[1] < iterations[0] ? "yes" : "no");
  bool same = true;
  for (const unsigned int c : {slip, rate, moment})
    same = same && std::abs(results[1][c] - results[0][c]) <=
                     1e-3 * std::abs(results[0][c]);
  std::printf("same fault results (1e-3): %s\n", same ? "yes" : "no");

  const std::string column = std::string(SOURCE_DIR) + "/inputs/plane_wave.prm";
  double            column_slip[2] = {0, 0};
  for (unsigned int limit = 0; limit < 2; ++limit)
    {
      const int code =
        tests::run({column,
                    "--set",
                    "Output directory=output-stick-crossings-column",
                    "--set",
                    "Time integration/Time step=20.4124",
                    "--set",
                    "Time integration/End time=4082.48",
                    "--set",
                    std::string("Solver/Limit stick crossings=") +
                      (limit ? "true" : "false")});
      unsigned int  retries = 0, cuts = 0;
      std::ifstream log("output-stick-crossings-column/log.txt");
      std::string   line;
      while (std::getline(log, line))
        {
          retries +=
            line.find("tried again without the limit") != std::string::npos;
          cuts += line.find("the step is cut in half") != std::string::npos;
        }
      const auto rows =
        tests::read_statistics("output-stick-crossings-column/statistics");
      column_slip[limit] = rows.empty() ? 0 : rows.back()[slip];
      std::printf("column, dt = 1000 x the explicit limit, limit %-5s: exit "
                  "code %d, %u retries without the limit, %u step cuts, "
                  "final slip %.6g\n",
                  limit ? "true" : "false",
                  code,
                  retries,
                  cuts,
                  column_slip[limit]);
    }
  std::printf("same final slip (1e-9): %s\n",
              column_slip[0] > 0 && std::abs(column_slip[1] - column_slip[0]) <=
                                      1e-9 * column_slip[0] ?
                "yes" :
                "no");
}
