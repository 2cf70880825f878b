// The 1-D plane-wave slip-weakening interface (doc/verification.md,
// section 5): its analytic slip history, and the value of a column of a
// table of numbers at a time, for plane_wave.cc and hanging_plane_wave.cc.
#ifndef rupture_tests_fault_plane_wave_solution_h
#define rupture_tests_fault_plane_wave_solution_h

#include <cmath>
#include <vector>

namespace tests
{
  /// The analytic slip at time @p t: 0.1 (exp(2 t) - 1) until the slip
  /// reaches D_c = 1, then a slip rate of 2.2.
  inline double
  plane_wave_slip(const double t)
  {
    const double tw = 0.5 * std::log(11.);
    return t < tw ? 0.1 * (std::exp(2 * t) - 1) : 1 + 2.2 * (t - tw);
  }

  /// Column @p column of @p rows at time @p t (column @p time_column),
  /// linearly interpolated; the last row's value after its time.
  inline double
  value_at(const std::vector<std::vector<double>> &rows,
           const unsigned int                      time_column,
           const unsigned int                      column,
           const double                            t)
  {
    for (unsigned int i = 1; i < rows.size(); ++i)
      if (rows[i][time_column] >= t - 1e-12)
        {
          const double w = (t - rows[i - 1][time_column]) /
                           (rows[i][time_column] - rows[i - 1][time_column]);
          return (1 - w) * rows[i - 1][column] + w * rows[i][column];
        }
    return rows.empty() ? 0 : rows.back()[column];
  }
} // namespace tests

#endif
