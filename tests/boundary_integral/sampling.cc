// The sampling of the boundary-integral method's series
// (BoundaryIntegral::CycleOutput) on the one-element spring-slider
// (inputs/spring_slider.prm, three cycles): a run that writes every step
// (<Sampling slip rate change> = 0) against the same run with rows only
// when log10 of the largest slip rate has changed by 0.5 since the last
// row or 1e7 s have passed, and slip profiles every 2e7 s between events
// and every second in them. Checked from the statistics of both runs:
// - the sampled run takes the same steps: each of its rows is the
//   every-step run's row of that step, digit for digit;
// - each sampled row (but the last, written at the end time) is due: the
//   rate changed by at least 0.5 or 1e7 s passed since the row before;
// - none is late: at no step between two rows was a row due already;
// - the station file has a row at each statistics row's time;
// - the profiles likewise: each due (the interval of its own step: 1 s
//   when the largest slip rate is at least the event slip rate 1 mm/s,
//   2e7 s otherwise), none late, the first at 0 and the last at the end.

#include <deal.II/base/mpi.h>

#include "../tests.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string prm = std::string(SOURCE_DIR) + "/inputs/spring_slider.prm";
  const double      change = 0.5, interval = 1e7, slow = 2e7, fast = 1;
  const int         every = tests::run_in("every", {prm}, {});
  const int         sampled =
    tests::run_in("sampled",
                  {prm},
                  {"Boundary integral/Sampling slip rate change=0.5",
                   "Boundary integral/Sampling interval=1e7",
                   "Boundary integral/Profile interval between events=2e7",
                   "Boundary integral/Profile interval during events=1"});
  std::printf("exit codes %d and %d\n", every, sampled);
  // Statistics: step, time, time step, largest slip rate, rejected steps.
  const auto all     = tests::read_statistics("every/statistics.dat");
  const auto rows    = tests::read_statistics("sampled/statistics.dat");
  const auto station = tests::read_statistics("sampled/slider.dat");
  std::map<long, std::vector<double>> by_step;
  for (const auto &r : all)
    by_step[long(r[0])] = r;
  const auto log_rate = [](const std::vector<double> &r) {
    return std::log10(r[3]);
  };

  bool same = true, due = true, late = false;
  for (std::size_t k = 0; k < rows.size(); ++k)
    {
      same = same && by_step.count(long(rows[k][0])) &&
             by_step[long(rows[k][0])] == rows[k];
      if (k == 0)
        continue;
      const auto &a = rows[k - 1], &b = rows[k];
      if (k + 1 < rows.size())
        due = due && (std::abs(log_rate(b) - log_rate(a)) >= change ||
                      b[1] - a[1] >= interval);
      for (long s = long(a[0]) + 1; s < long(b[0]); ++s)
        {
          const auto &r = by_step[s];
          late = late || std::abs(log_rate(r) - log_rate(a)) >= change ||
                 r[1] - a[1] >= interval;
        }
    }
  bool stations = station.size() == rows.size();
  for (std::size_t k = 0; stations && k < rows.size(); ++k)
    stations = std::abs(station[k][0] - rows[k][1]) <= 1e-9 * rows[k][1];
  std::printf("rows: %zu of %zu steps; the same rows as every step: %s; "
              "each due: %s; none late: %s; station rows at their times: "
              "%s\n",
              rows.size(),
              all.size(),
              same ? "yes" : "no",
              due ? "yes" : "no",
              late ? "no" : "yes",
              stations ? "yes" : "no");

  // Profiles: t, log10 of the largest slip rate, the slip; the first line
  // holds the depths.
  auto profiles = tests::read_statistics("sampled/slip_profiles.dat");
  profiles.erase(profiles.begin());
  const auto wanted = [&](const double log10_rate) {
    return log10_rate >= -3 ? fast : slow;
  };
  bool        profiles_due = true, profiles_late = false;
  std::size_t during = 0;
  for (std::size_t k = 1; k < profiles.size(); ++k)
    {
      const auto &a = profiles[k - 1], &b = profiles[k];
      during += b[1] >= -3;
      if (k + 1 < profiles.size())
        profiles_due = profiles_due && b[0] - a[0] >= wanted(b[1]);
      for (const auto &r : all)
        if (r[1] > a[0] && r[1] < b[0])
          profiles_late = profiles_late || r[1] - a[0] >= wanted(log_rate(r));
    }
  std::printf("profiles: %zu (%zu in events); the first at 0: %s, the last "
              "at the end: %s; each due: %s; none late: %s\n",
              profiles.size(),
              during,
              profiles.front()[0] == 0 ? "yes" : "no",
              profiles.back()[0] == all.back()[1] ? "yes" : "no",
              profiles_due ? "yes" : "no",
              profiles_late ? "no" : "yes");
  return 0;
}
