// The rake on the fault surface output (Fault/Output, field "rake": the
// slip's direction from strike, positive up-dip) of the 3-D rupture of
// anisotropic_friction_3d.prm, whose prestress points 30 degrees from
// strike: with isotropic friction (strength ratio 1) the slip follows the
// traction (rake about 30 degrees at every node that slipped more than
// 10 cm); with the friction ellipse twice as strong along dip (ratio 2)
// the slip turns towards strike, along the ellipse's normal at a traction
// 30 degrees from strike, atan(tan(30) / 4) = 8.2 degrees. With r = 2 the
// centre station's directions file follows the sliding rule too, and the
// surface field slip_traction_angle is the angle between the surface's
// slip velocity and shear traction.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>


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
                     "Fault/Output/Output interval=0.6"});
      const std::string vtu  = tests::read_file(out + "/fault/fault_00060.vtu");
      const auto        rake = tests::vtu_field(vtu, "rake");
      const auto        slip = tests::vtu_field(vtu, "slip");
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
      // The surface field slip_traction_angle at 0.6 s, while the fault
      // slides: at every node whose slip rate exceeds 1 mm/s, the angle
      // between the fields slip_velocity and shear_traction (to 0.01
      // degrees). Its median over the nodes sliding faster than 0.1 m/s:
      // small with isotropic friction (the slip follows the traction), the
      // turn of the sliding rule with r = 2 (from the traction's 30 degrees
      // towards the normal's 8; a few arresting nodes slide against the
      // traction, hence the median).
      {
        const std::string mid =
          tests::read_file(out + "/fault/fault_00030.vtu");
        const auto angle = tests::vtu_field(mid, "slip_traction_angle");
        const auto v     = tests::vtu_field(mid, "slip_velocity");
        const auto tau   = tests::vtu_field(mid, "shear_traction");
        double     error = 0;
        std::vector<double> fast;
        for (unsigned int i = 0;
             i < angle.size() && 3 * i + 2 < v.size() && 3 * i + 2 < tau.size();
             ++i)
          {
            const double vv = std::sqrt(v[3 * i] * v[3 * i] +
                                        v[3 * i + 1] * v[3 * i + 1] +
                                        v[3 * i + 2] * v[3 * i + 2]),
                         tt = std::sqrt(tau[3 * i] * tau[3 * i] +
                                        tau[3 * i + 1] * tau[3 * i + 1] +
                                        tau[3 * i + 2] * tau[3 * i + 2]);
            if (!(vv > 1e-3 && tt > 0))
              continue;
            const double dot = v[3 * i] * tau[3 * i] +
                               v[3 * i + 1] * tau[3 * i + 1] +
                               v[3 * i + 2] * tau[3 * i + 2];
            const double expected =
              std::acos(std::max(-1., std::min(1., dot / (vv * tt)))) * 180 /
              M_PI;
            error = std::max(error, std::abs(angle[i] - expected));
            if (vv > 0.1)
              fast.push_back(angle[i]);
          }
        std::sort(fast.begin(), fast.end());
        const double median = fast.empty() ? -1 : fast[fast.size() / 2];
        std::printf(
          "strength ratio %s at 0.6 s: field slip_traction_angle equal to "
          "the angle between slip_velocity and shear_traction within 0.01 "
          "degrees: %s; %s nodes sliding faster than 0.1 m/s, their median "
          "angle %s\n",
          ratio.c_str(),
          error <= 0.01 ? "yes" : "no",
          fast.size() >= 10 ? "10 or more" : "fewer than 10",
          ratio == "1" ?
            (median >= 0 && median < 5 ? "below 5 degrees" : "NOT below 5") :
            (median > 15 && median < 35 ? "between 15 and 35 degrees" :
                                          "NOT between 15 and 35"));
      }
      // The station directions (<name>-rake.dat: t, rake of the slip,
      // direction of the frictional slip rate, direction of the shear
      // traction, angle between the two), written with anisotropic
      // friction only. Where the centre slides, the slip rate's direction
      // is the ellipse's normal at the traction: its dip component scaled
      // by 1 / r^2 (e_2 lies along dip).
      const std::string directions = out + "/center-rake.dat";
      if (ratio == "1")
        {
          std::printf("strength ratio 1: no station directions file: %s\n",
                      tests::file_exists(directions) ? "no" : "yes");
          continue;
        }
      const auto   rows    = tests::read_statistics(directions);
      unsigned int sliding = 0;
      double       worst = 0, angle_error = 0, largest_angle = 0;
      for (const auto &row : rows)
        if (row.size() == 5 && row[2] != 0)
          {
            const double t = row[3] * M_PI / 180;
            const double normal =
              std::atan2(std::sin(t) / 4, std::cos(t)) * 180 / M_PI;
            worst =
              std::max(worst, std::abs(std::remainder(row[2] - normal, 360.)));
            // The last column: the angle between the frictional slip rate
            // and the shear traction, both in the fault plane.
            angle_error =
              std::max(angle_error,
                       std::abs(
                         row[4] -
                         std::abs(std::remainder(row[2] - row[3], 360.))));
            largest_angle = std::max(largest_angle, row[4]);
            ++sliding;
          }
      std::printf("strength ratio 2, centre station: %s rows, sliding in more "
                  "than 5: %s, frictional slip rate within 1 degree of the "
                  "ellipse's normal at the station's traction: %s, final "
                  "rake %.0f degrees\n",
                  rows.size() == 61 ? "61" : "not 61",
                  sliding > 5 ? "yes" : "no",
                  worst <= 1 ? "yes" : "no",
                  rows.empty() ? 0. : rows.back()[1]);
      std::printf("strength ratio 2, centre station: the angle between slip "
                  "rate and shear traction equal to the difference of their "
                  "directions within 0.01 degrees: %s; largest angle %.0f "
                  "degrees (not 0: the slip leaves the traction)\n",
                  angle_error <= 0.01 ? "yes" : "no",
                  largest_angle);
    }
}
