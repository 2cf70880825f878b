// The fast variant of contrib/stability-study (--quick): a handful of stiff
// and extreme cases (penalty 1e-2 and 1e6 times the element stiffness,
// L_d = 1e-4, explicit steps of 10 dt_c and one above dt_c that the input
// check must refuse, nu = 0.499, a material contrast of 1000, a fault that
// opens), run with this build's program. Each must end as the study
// expects: "ok" (ran to the end, energy within tolerance, all values
// finite) or "failed" (stopped with a diagnosis, never a crash or NaN). The
// script's exit code is 1 if a case ends otherwise or crashes.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string top     = std::string(SOURCE_DIR) + "/../../";
  const std::string command = top +
                              "contrib/stability-study --quick --jobs 1 "
                              "--rupture ../../../rupture > study.txt 2>&1";
  const int status = std::system(command.c_str());
  std::printf("exit code %d\n", WIFEXITED(status) ? WEXITSTATUS(status) : -1);

  // The first lines are "case-id result wall [diagnosis]", one per case, in
  // the order the runs ended; sort them so that the output is stable.
  std::vector<std::string> cases;
  std::istringstream       lines(tests::read_file("study.txt"));
  std::string              line;
  while (std::getline(lines, line) && line.rfind("#", 0) != 0)
    {
      std::istringstream words(line);
      std::string        id, result;
      words >> id >> result;
      if (id.find('/') != std::string::npos)
        cases.push_back(id + ": " + result);
    }
  std::sort(cases.begin(), cases.end());
  for (const auto &c : cases)
    std::printf("%s\n", c.c_str());
}
