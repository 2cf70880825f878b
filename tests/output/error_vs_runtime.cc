// The fast variant of contrib/error-vs-runtime (--quick: the 1-D plane-wave
// problem with both fault methods at h = 0.2 and 0.1), run with this
// build's program: the study runs, and for both methods the slip error
// falls when the cells are halved (measured: 3.8e-2 to 8.0e-3 implicit,
// 7.9e-2 to 2.4e-2 explicit).

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string top = std::string(SOURCE_DIR) + "/../../";
  // The test runs in build-*/tests/<room>/<name>.<build>/; the program of
  // this build is build-*/rupture.
  const std::string command = top +
                              "contrib/error-vs-runtime --quick --rupture "
                              "../../../rupture > study.txt 2>&1";
  const int status = std::system(command.c_str());
  std::printf("exit code %d\n", WIFEXITED(status) ? WEXITSTATUS(status) : -1);

  // Lines "method h = H DoFs N steps S wall W s error E".
  std::map<std::string, std::vector<double>> errors;
  std::istringstream lines(tests::read_file("study.txt"));
  std::string        line;
  while (std::getline(lines, line))
    {
      const auto p = line.find(" error ");
      if (line.rfind("implicit", 0) == 0 || line.rfind("explicit", 0) == 0)
        if (p != std::string::npos)
          errors[line.substr(0, 8)].push_back(std::atof(line.c_str() + p + 7));
    }
  for (const std::string method : {"implicit", "explicit"})
    {
      const auto &e = errors[method];
      std::printf("%s: %zu resolutions, error falls when h is halved: %s\n",
                  method.c_str(),
                  e.size(),
                  (e.size() == 2 && e[1] < 0.5 * e[0]) ? "yes" : "no");
    }
}
