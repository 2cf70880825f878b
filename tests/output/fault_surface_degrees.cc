// The fault surface files (fault-*.vtu) at degrees 1 to 4, in 2-D and 3-D:
// every fault node pair is a point, each fault face whose nodes are all
// fault nodes is written as p sub-segments (2-D) or p x p sub-quadrilaterals
// (3-D) between its Gauss-Lobatto nodes, and these sub-cells tile the
// faces. The fault region is 4 km wide (4 x 4 km in 3-D) in 1 km cells; the
// nodes on its edge are welded, so the faces that touch the edge are left
// out and the faces written cover the inner 2 km (2 x 2 km). Checked: the
// number of points ((4p - 1)^(dim - 1) pairs), of sub-cells (2p, or 4p^2),
// every point on the fault plane inside the region, no sub-cell with a
// repeated point, the sub-cells' lengths (areas, by the shoelace formula
// in their VTK order, so that a twisted quadrilateral would show) adding
// up to the faces' 2 km (4 km^2), and one orientation for all of them.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  /// The numbers of the first DataArray of @p text whose opening tag
  /// @p tag (a regular expression) matches.
  std::vector<double>
  numbers_of(const std::string &text, const std::string &tag)
  {
    const std::regex    array(tag + "[^>]*>([^<]*)<");
    std::smatch         m;
    std::vector<double> values;
    if (std::regex_search(text, m, array))
      {
        std::istringstream in(m[1].str());
        double             v;
        while (in >> v)
          values.push_back(v);
      }
    return values;
  }

  std::string
  prm(const unsigned int dim, const unsigned int degree)
  {
    std::ostringstream p;
    p << "set Dimension = " << dim << "\nset Test mode = true\n"
      << "subsection Discretization\n  set Polynomial degree = " << degree
      << "\nend\nsubsection Scene\n  subsection Box\n";
    if (dim == 2)
      p << "    set Lower corner = -3000, -2000\n"
           "    set Upper corner = 3000, 2000\n"
           "    set Number of cells = 6, 4\n";
    else
      p << "    set Lower corner = -3000, -2000, -3000\n"
           "    set Upper corner = 3000, 2000, 3000\n"
           "    set Number of cells = 6, 4, 6\n";
    p << "  end\nend\nsubsection Material\n  set Density = 2670\n"
         "  set P-wave speed = 6000\n  set S-wave speed = 3464\nend\n"
         "subsection Fault\n  set Model = traction at split nodes\n";
    if (dim == 2)
      p << "  set Plane point = 0, 0\n  set Plane normal = 0, 1\n"
           "  set Fault region = abs(x) <= 2000 ? 1 : 0\n"
           "  set Initial traction = 70e6; -120e6\n";
    else
      p << "  set Plane point = 0, 0, 0\n  set Plane normal = 0, 1, 0\n"
           "  set Fault region = (abs(x) <= 2000 && abs(z) <= 2000) ? 1 : 0\n"
           "  set Initial traction = 70e6; -120e6; 0\n";
    p << "  subsection Output\n    set Output interval = 0\n  end\nend\n"
         "subsection Time integration\n"
         "  set Scheme = explicit central difference\n"
         "  set End time = 0.002\n  set Time step = 0.001\nend\n"
         "subsection Output\n  set Output interval = -1\nend\n";
    return p.str();
  }

  void
  check(const unsigned int dim, const unsigned int degree)
  {
    const std::string dir =
      "q" + std::to_string(degree) + "-" + std::to_string(dim) + "d";
    const std::string file = dir + ".prm";
    {
      std::ofstream out(file);
      out << prm(dim, degree);
    }
    std::string errors;
    const int   code =
      tests::run_capture({file, "--set", "Output directory=" + dir}, errors);
    if (code != 0)
      {
        std::printf(
          "%u-D Q%u: exit code %d\n%s", dim, degree, code, errors.c_str());
        return;
      }
    // The first file that fault.pvd lists.
    const std::string pvd = tests::read_file(dir + "/fault.pvd");
    std::smatch       m;
    std::regex_search(pvd, m, std::regex("file=\"([^\"]+)\""));
    const std::string text = tests::read_file(dir + "/" + m[1].str());

    const auto         xyz        = numbers_of(text, "<Points><DataArray");
    const auto         conn       = numbers_of(text, "Name=\"connectivity\"");
    const auto         types      = numbers_of(text, "Name=\"types\"");
    const unsigned int n_points   = xyz.size() / 3;
    const unsigned int per_cell   = (dim == 2 ? 2 : 4);
    const unsigned int n_cells    = types.size();
    const unsigned int expected_p = std::pow(4 * degree - 1, dim - 1);
    const unsigned int expected_c =
      (dim == 2 ? 2 * degree : 4 * degree * degree);

    bool on_plane = true;
    for (unsigned int i = 0; i < n_points; ++i)
      on_plane = on_plane && std::abs(xyz[3 * i + 1]) < 1e-6 &&
                 std::abs(xyz[3 * i]) < 2000 &&
                 (dim == 2 || std::abs(xyz[3 * i + 2]) < 2000);

    bool   distinct = conn.size() == n_cells * per_cell;
    double total = 0, positive = 0, negative = 0;
    for (unsigned int c = 0; distinct && c < n_cells; ++c)
      {
        std::set<int> seen;
        for (unsigned int k = 0; k < per_cell; ++k)
          seen.insert(static_cast<int>(conn[c * per_cell + k]));
        distinct     = distinct && seen.size() == per_cell;
        const auto x = [&](const unsigned int k, const unsigned int d) {
          return xyz[3 * static_cast<unsigned int>(conn[c * per_cell + k]) + d];
        };
        double measure;
        if (dim == 2)
          measure = x(1, 0) - x(0, 0);
        else
          {
            // Shoelace in the x-z plane, in the cell's vertex order.
            measure = 0;
            for (unsigned int k = 0; k < 4; ++k)
              measure +=
                x(k, 0) * x((k + 1) % 4, 2) - x((k + 1) % 4, 0) * x(k, 2);
            measure /= 2;
          }
        total += std::abs(measure);
        (measure > 0 ? positive : negative) += 1;
      }
    const double expected_measure = (dim == 2 ? 2000. : 4e6);
    std::printf("%u-D Q%u: %u points (expected %u), %u sub-cells (expected "
                "%u), on the fault plane inside the region: %s, no repeated "
                "point: %s, total %s %.6g (expected %.6g), one orientation: "
                "%s\n",
                dim,
                degree,
                n_points,
                expected_p,
                n_cells,
                expected_c,
                on_plane ? "yes" : "no",
                distinct ? "yes" : "no",
                dim == 2 ? "length" : "area",
                total,
                expected_measure,
                (positive == 0 || negative == 0) ? "yes" : "no");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int dim : {2u, 3u})
    for (unsigned int degree = 1; degree <= 4; ++degree)
      check(dim, degree);
}
