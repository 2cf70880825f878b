// What the tests of the criterion "wavefield" compare: receivers' velocities
// against a reference run, and the DoFs over the steps of an adaptive run.
#ifndef rupture_tests_simulator_wavefield_runs_h
#define rupture_tests_simulator_wavefield_runs_h

#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace wavefield_runs
{
  /// Run the input @p input of tests/simulator/inputs into @p directory
  /// with the receivers @p receivers and the --set entries @p settings.
  inline int
  run(const std::string       &input,
      const std::string       &directory,
      const std::string       &receivers,
      std::vector<std::string> settings,
      const MPI_Comm           communicator)
  {
    settings.push_back("Output/Receivers=" + receivers);
    return tests::run_in(directory,
                         {std::string(SOURCE_DIR) + "/inputs/" + input},
                         settings,
                         communicator);
  }

  /// The receiver's table (t, ux, vx, uy, vy[, uz, vz]).
  inline std::vector<std::vector<double>>
  receiver(const std::string &directory, const std::string &name)
  {
    return tests::read_statistics(directory + "/" + name + ".dat");
  }

  /// The largest difference of the velocities of @p a from those of the
  /// reference @p ref (interpolated linearly to its times), relative to
  /// the reference's largest velocity.
  inline double
  difference(const std::vector<std::vector<double>> &a,
             const std::vector<std::vector<double>> &ref)
  {
    if (a.size() < 2 || ref.empty())
      return 1e9;
    double       largest = 0, worst = 0;
    unsigned int j = 0;
    for (const auto &row : ref)
      {
        while (j + 2 < a.size() && a[j + 1][0] < row[0])
          ++j;
        const double w =
          std::clamp((row[0] - a[j][0]) / (a[j + 1][0] - a[j][0]), 0., 1.);
        for (unsigned int c = 2; c < row.size(); c += 2)
          {
            const double value = (1 - w) * a[j][c] + w * a[j + 1][c];
            worst              = std::max(worst, std::abs(value - row[c]));
            largest            = std::max(largest, std::abs(row[c]));
          }
      }
    return largest > 0 ? worst / largest : 1e9;
  }

  /// The sum over the steps of the DoFs (the statistics' column "Degrees
  /// of freedom", with <Mesh refinement>), and their peak.
  inline std::pair<double, double>
  dof_steps(const std::string &directory)
  {
    double sum = 0, peak = 0;
    for (const double n :
         tests::read_adaptive_columns(directory + "/statistics").dofs)
      {
        sum += n;
        peak = std::max(peak, n);
      }
    return {sum, peak};
  }

  inline const char *
  yes(const bool b)
  {
    return b ? "yes" : "no";
  }

  /// The mean over @p names of the receivers' differences of each run of
  /// @p runs from the run "fixed" in @p directory, and whether every
  /// receiver's difference of the last run is below @p fraction of the
  /// first's and below the second last's (the first's, of two runs).
  inline std::pair<std::vector<double>, bool>
  compare(const std::string              &directory,
          const std::vector<std::string> &runs,
          const std::vector<std::string> &names,
          const double                    fraction)
  {
    std::vector<double> means(runs.size(), 0.);
    bool                every = true;
    for (const std::string &r : names)
      {
        const auto          ref = receiver(directory + "/fixed", r);
        std::vector<double> d;
        for (unsigned int k = 0; k < runs.size(); ++k)
          {
            d.push_back(
              difference(receiver(directory + "/" + runs[k], r), ref));
            means[k] += d.back() / names.size();
          }
        every = every && d.back() < fraction * d.front() &&
                d.back() < d[d.size() - 2];
      }
    return {means, every};
  }
} // namespace wavefield_runs

#endif
