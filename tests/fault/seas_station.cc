// Fault stations in the SCEC SEAS layout (<Fault/Output/Station format> =
// SEAS) on the steady rate-and-state creep of inputs/rate_and_state_creep.prm
// (a block pushed at V_p = 1e-5 m/s over a regularised aging-law fault):
// the header names the fields 't slip slip_rate shear_stress state'; one
// row per step; the columns are the SCEC file's along-strike slip, the
// log10 of its slip rate, its shear stress and log10 theta of the same
// run written the SCEC way; at the end the creep's steady state: log10
// V_p = -5, the steady strength 5.907903 MPa and log10(L / V_p) =
// log10(2000 s).

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        prm =
    std::string(SOURCE_DIR) + "/inputs/rate_and_state_creep.prm";
  tests::run_in("scec", {prm}, {"Fault/Output/Stations=mid: 500, 500"});
  tests::run_in("seas",
                {prm},
                {"Fault/Output/Stations=mid: 500, 500",
                 "Fault/Output/Station format=SEAS"});
  const std::string text = tests::read_file("seas/mid.dat");
  std::printf("field names: %s\n",
              text.find("\nt slip slip_rate shear_stress state\n") !=
                  std::string::npos ?
                "t slip slip_rate shear_stress state" :
                "missing");
  const auto scec = tests::read_statistics("scec/mid.dat"),
             seas = tests::read_statistics("seas/mid.dat");
  bool same       = !seas.empty() && seas.size() == scec.size();
  for (unsigned int i = 0; same && i < seas.size(); ++i)
    same = seas[i].size() == 5 && seas[i][0] == scec[i][0] &&
           std::abs(seas[i][1] - scec[i][1]) <= 1e-7 * std::abs(scec[i][1]) &&
           (scec[i][2] == 0 ?
              seas[i][2] == -300 :
              std::abs(seas[i][2] - std::log10(std::abs(scec[i][2]))) < 1e-6) &&
           std::abs(seas[i][3] - scec[i][3]) <= 1e-7 * std::abs(scec[i][3]) &&
           std::abs(seas[i][4] - scec[i][8]) <= 1e-7 * std::abs(scec[i][8]);
  std::printf("rows: %zu, each the SCEC file's slip, log10 slip rate, shear "
              "stress and log10 theta: %s\n",
              seas.size(),
              same ? "yes" : "no");
  const auto &last = seas.back();
  std::printf("last row: t = %.0f s, log10 V = %.4f, shear stress = %.6f "
              "MPa, log10 theta = %.5f (steady state: -5, 5.907903, %.5f)\n",
              last[0],
              last[2],
              last[3],
              last[4],
              std::log10(0.02 / 1e-5));
  return 0;
}
