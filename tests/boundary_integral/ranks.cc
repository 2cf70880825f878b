// The boundary-integral method on two ranks (each owns half of the rows
// of the dense stiffness and the ranks exchange their rates) takes the
// same steps as on one: SEAS BP1-QD (prm/seas/bp1-qd-bi.prm) with
// elements of 500 m over its first 250 years, through the first event,
// run by rank 0 alone and by both ranks, gives the same statistics,
// station rows and event catalogue, digit for digit.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cstdio>
#include <string>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  if (rank != 0)
    std::freopen("/dev/null", "w", stdout);
  const std::string prm =
    std::string(SOURCE_DIR) + "/../../prm/seas/bp1-qd-bi.prm";
  const std::vector<std::string> settings = {
    "Boundary integral/Element size=500",
    "Time integration/End time=7.9e9",
    "Boundary integral/Profile interval between events=0",
    "Boundary integral/Profile interval during events=0",
    "Test mode=true"};
  // Rank 0 alone.
  MPI_Comm alone;
  MPI_Comm_split(MPI_COMM_WORLD, rank == 0 ? 0 : MPI_UNDEFINED, 0, &alone);
  if (rank == 0)
    {
      std::vector<std::string> arguments = {prm,
                                            "--set",
                                            "Output directory=one"};
      for (const auto &s : settings)
        arguments.insert(arguments.end(), {"--set", s});
      std::filesystem::remove_all("one");
      std::printf("one rank: exit code %d\n", tests::run_on(alone, arguments));
      MPI_Comm_free(&alone);
    }
  MPI_Barrier(MPI_COMM_WORLD);
  const int code = tests::run_in("all", {prm}, settings);
  std::printf("all ranks: exit code %d\n", code);
  if (rank == 0)
    {
      const auto events = tests::read_csv("all/events.csv");
      std::printf("events: %zu, the first from %.0f to %.0f years\n",
                  events.size(),
                  events.empty() ? 0. : events[0][2],
                  events.empty() ? 0. : events[0][3] / 3.15576e7);
      for (const std::string file :
           {"statistics.dat", "events.csv", "fltst_dp075.dat"})
        std::printf("%s the same: %s\n",
                    file.c_str(),
                    tests::read_file("one/" + file) ==
                        tests::read_file("all/" + file) ?
                      "yes" :
                      "no");
    }
  return 0;
}
