// The rake on the fault surface output (Fault/Output, field "rake": the
// slip's direction from strike, positive up-dip) of the 3-D rupture of
// anisotropic_friction_3d.prm, whose prestress points 30 degrees from
// strike: with isotropic friction (strength ratio 1) the slip follows the
// traction (rake about 30 degrees at every node that slipped more than
// 10 cm); with the friction ellipse twice as strong along dip (ratio 2)
// the slip turns towards strike, along the ellipse's normal at a traction
// 30 degrees from strike, atan(tan(30) / 4) = 8.2 degrees.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  std::vector<double>
  field(const std::string &vtu, const std::string &name)
  {
    const std::string   tag = "Name=\"" + name + "\"";
    std::vector<double> values;
    const auto          at = vtu.find(tag);
    if (at == std::string::npos)
      return values;
    const auto         start = vtu.find('>', at) + 1;
    std::istringstream in(
      vtu.substr(start, vtu.find("</DataArray>", at) - start));
    double v;
    while (in >> v)
      values.push_back(v);
    return values;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        prm =
    std::string(SOURCE_DIR) + "/anisotropic_friction_3d.prm";
  for (const std::string ratio : {"1", "2"})
    {
      const std::string out = "ratio-" + ratio;
      tests::run_in(out,
                    {prm},
                    {"Fault/Anisotropic friction/Strength ratio=" + ratio,
                     "Fault/Output/Output interval=1.2"});
      const std::string vtu  = tests::read_file(out + "/fault/fault_00060.vtu");
      const auto        rake = field(vtu, "rake");
      const auto        slip = field(vtu, "slip");
      double            low = 1e300, high = -1e300;
      unsigned int      n = 0;
      for (unsigned int i = 0; i < rake.size() && 3 * i + 2 < slip.size(); ++i)
        if (std::hypot(slip[3 * i], slip[3 * i + 2]) > 0.1)
          {
            low  = std::min(low, rake[i]);
            high = std::max(high, rake[i]);
            ++n;
          }
      const bool expected = n > 10 && (ratio == "1" ? (low > 25 && high < 35) :
                                                      (low > 5 && high < 12));
      std::printf("strength ratio %s: %u nodes slipped more than 10 cm, rake "
                  "from %.1f to %.1f degrees, within %s: %s\n",
                  ratio.c_str(),
                  n,
                  low,
                  high,
                  ratio == "1" ? "25-35 (the prestress at 30)" :
                                 "5-12 (the ellipse's normal, 8.2)",
                  expected ? "yes" : "no");
    }
}
