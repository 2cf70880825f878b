// The fault-only cycle solver on a dipping fault in a plane-strain body
// (SEAS BP3-QD, prm/seas/bp3-qd-60.prm), coarsened: node pairs 250 m apart
// with a characteristic slip distance four times the benchmark's (32 mm,
// so that 250 m resolve its process zone as 62.5 m resolve the
// benchmark's), a box of 100 km with cells growing by 1.3, to the end of
// the first event. Checked:
// - thrust and normal slip on the fault dipping at 60 degrees run their
//   events (the catalogue's start, peak slip rate and largest slip);
// - the normal stress, 50 MPa at the start, changes with the slip deficit
//   in opposite directions for thrust and normal slip (10 km down the
//   fault, after 20 years: opposite, the same size within 10 %; not
//   closer, since the creep below the locked part feels the normal stress
//   through f / a = 24), and it is, to the file's precision, 50 MPa plus
//   the body's normal stiffness (computed again by the test) times the
//   slip deficit of the slip profile written at the same step (300 years,
//   within 1e-3 of the change);
// - the thrust run's surface stations 8 km to either side of the trace:
//   their velocity is the rate of their displacement;
// - on a vertical fault the normal stress stays 50 MPa through the events
//   (the body's mirror symmetry: no normal stiffness).
// On two ranks (the columns and rows shared out) the output is the same.

#include <rupture/boundary_integral/plane_strain_finite_elements.h>

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
  /// Column @p c of @p rows (a station file) at the time @p t,
  /// interpolated linearly between the rows around it.
  double
  at(const std::vector<std::vector<double>> &rows,
     const double                            t,
     const unsigned int                      c)
  {
    for (std::size_t k = 1; k < rows.size(); ++k)
      if (rows[k][0] >= t)
        {
          const double w = (t - rows[k - 1][0]) / (rows[k][0] - rows[k - 1][0]);
          return (1 - w) * rows[k - 1][c] + w * rows[k][c];
        }
    return rows.back()[c];
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::freopen("/dev/null", "w", stdout);
  const std::string prm =
    std::string(SOURCE_DIR) + "/../../prm/seas/bp3-qd-60.prm";
  const std::vector<std::string> common = {
    "Boundary integral/Element size=250",
    "Boundary integral/Domain size=100e3",
    "Boundary integral/Cell growth factor=1.3",
    "Fault/Rate and state/Characteristic slip distance=0.032",
    "Termination/Number of events=1",
    "Boundary integral/Profile interval between events=0",
    "Boundary integral/Profile interval during events=0",
    "Test mode=true"};
  const double year = 3.15576e7;

  std::vector<std::vector<std::vector<double>>> stations;
  for (const std::string sense : {"thrust", "normal"})
    {
      std::vector<std::string> settings = common;
      settings.push_back("Boundary integral/Sense of slip=" + sense);
      if (sense == std::string("thrust"))
        {
          settings.push_back("Boundary integral/Profile interval between "
                             "events=1.57788e9");
          settings.push_back("Boundary integral/Surface stations=surfst_m08: "
                             "-8000, 0; surfst_p08: 8000, 0");
        }
      const int  code   = tests::run_in(sense, {prm}, settings);
      const auto events = tests::read_csv(sense + "/events.csv");
      std::printf("%s: exit code %d, %zu events\n",
                  sense.c_str(),
                  code,
                  events.size());
      // Columns: event, start (s), start (years), end, duration,
      // hypocentre x, y, peak slip rate, moment, ruptured length, mean
      // slip, largest slip.
      for (const auto &e : events)
        std::printf("  event %.0f: starts at %.1f years, peak slip rate "
                    "%.2f m/s, largest slip %.2f m\n",
                    e[0],
                    e[2],
                    e[7],
                    e[11]);
      stations.push_back(tests::read_statistics(sense + "/fltst_dp100.dat"));
      const auto &first = stations.back().front();
      std::printf("  10 km down the fault: %zu columns, normal stress %.6f "
                  "MPa at the start\n",
                  first.size(),
                  first[4]);
    }
  const double early_thrust = at(stations[0], 20 * year, 4) - 50,
               early_normal = at(stations[1], 20 * year, 4) - 50;
  std::printf("after 20 years: normal stress changes %.4f (thrust) and %.4f "
              "(normal) MPa: opposite, the same within 10 %%: %s\n",
              early_thrust,
              early_normal,
              early_thrust * early_normal < 0 &&
                  std::abs(early_thrust + early_normal) <
                    0.1 * std::abs(early_thrust) ?
                "yes" :
                "no");

  // The thrust fault's normal stress against its slip deficit: the
  // profile nearest to 300 years.
  {
    const auto  profiles = tests::read_statistics("thrust/slip_profiles.dat");
    std::size_t row      = 1;
    for (std::size_t k = 1; k < profiles.size(); ++k)
      if (std::abs(profiles[k][0] - 300 * year) <
          std::abs(profiles[row][0] - 300 * year))
        row = k;
    const double t = profiles[row][0];
    rupture::BoundaryIntegral::PlaneStrainFiniteElements::Settings body;
    body.fault_extent  = 40e3;
    body.node_spacing  = 250;
    body.degree        = 2;
    body.domain_size   = 100e3;
    body.growth        = 1.3;
    body.dip           = 60;
    body.thrust        = true;
    body.shear_modulus = 2670. * 3464 * 3464;
    body.lambda        = 2670. * 6000 * 6000 - 2 * body.shear_modulus;
    const rupture::BoundaryIntegral::PlaneStrainFiniteElements stiffness(
      body, MPI_COMM_WORLD);
    const unsigned int n = stiffness.size();
    unsigned int       i = 0;
    while (i < n && std::abs(stiffness.depth(i) - 10e3) > 1e-6)
      ++i;
    const auto N      = stiffness.normal_rows(i, i + 1);
    double     change = 0;
    for (unsigned int j = 0; j < n; ++j)
      change += N[j] * (profiles[row][2 + j] - 1e-9 * t);
    double station = 0;
    for (const auto &r : stations[0])
      if (std::abs(r[0] - t) <= 1e-9 * t)
        station = r[4] - 50;
    std::printf("at %.0f years, 10 km down the thrust fault (node %u of "
                "%u, %zu profile values): the normal stress changed by "
                "%.4f MPa, the normal stiffness times the slip deficit "
                "gives %.4f: within 1e-3: %s\n",
                t / year,
                i,
                n,
                profiles[row].size() - 2,
                station,
                change / 1e6,
                std::abs(station - change / 1e6) < 1e-3 * std::abs(station) ?
                  "yes" :
                  "no");
  }

  // The surface stations: the velocity is the rate of the displacement
  // (between rows 50 and 60 years apart, in the first 300 years: within
  // 1 % of the largest velocity).
  for (const std::string name : {"surfst_m08", "surfst_p08"})
    {
      const auto rows    = tests::read_statistics("thrust/" + name + ".dat");
      double     largest = 0, mismatch = 0;
      for (const auto &r : rows)
        if (r[0] < 300 * year)
          largest = std::max(largest, std::hypot(r[3], r[4]));
      for (double t = 50 * year; t < 300 * year; t += 50 * year)
        for (unsigned int c = 0; c < 2; ++c)
          {
            const double rate =
              (at(rows, t + 10 * year, 1 + c) - at(rows, t, 1 + c)) /
              (10 * year);
            const double mean =
              0.5 * (at(rows, t + 10 * year, 3 + c) + at(rows, t, 3 + c));
            mismatch = std::max(mismatch, std::abs(rate - mean));
          }
      const auto &last = rows.back();
      std::printf("%s: %zu rows, %zu columns; at the event's end (%.1f years) "
                  "displaced by (%.3f, %.3f) m; velocity the displacement's "
                  "rate within 1 %%: %s\n",
                  name.c_str(),
                  rows.size(),
                  last.size(),
                  last[0] / year,
                  last[1],
                  last[2],
                  mismatch < 0.01 * largest ? "yes" : "no");
    }

  // A vertical fault.
  std::vector<std::string> settings = common;
  settings.push_back("Boundary integral/Dip=90");
  settings.push_back("Fault/Rate and state/Direct effect=if(-y < 15e3, 0.010, "
                     "if(-y < 18e3, 0.010 + 0.015 * (-y - 15e3) / 3e3, "
                     "0.025))");
  settings.push_back("Fault/Output/Stations=fltst_dp100: 0, -10000");
  const int  code   = tests::run_in("vertical", {prm}, settings);
  const auto events = tests::read_csv("vertical/events.csv");
  const auto rows   = tests::read_statistics("vertical/fltst_dp100.dat");
  double     change = 0, largest_rate = -300;
  for (const auto &row : rows)
    {
      change       = std::max(change, std::abs(row[4] - 50));
      largest_rate = std::max(largest_rate, row[2]);
    }
  std::printf("vertical: exit code %d, %zu events, slip rate up to 10^%.1f "
              "m/s at 10 km, normal stress within 1e-6 MPa of 50: %s\n",
              code,
              events.size(),
              largest_rate,
              change < 1e-6 ? "yes" : "no");
  return 0;
}
