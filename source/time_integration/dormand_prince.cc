// The Dormand-Prince 5(4) pair with its step controller.

#include <rupture/base/binary_io.h>
#include <rupture/time_integration/dormand_prince.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rupture
{
  namespace TimeIntegration
  {
    namespace
    {
      // The Butcher tableau (Dormand and Prince 1980; Hairer, Norsett and
      // Wanner, Solving ODEs I, table 5.2).
      constexpr double c[7]    = {0, 1. / 5, 3. / 10, 4. / 5, 8. / 9, 1, 1};
      constexpr double a[7][6] = {
        {0, 0, 0, 0, 0, 0},
        {1. / 5, 0, 0, 0, 0, 0},
        {3. / 40, 9. / 40, 0, 0, 0, 0},
        {44. / 45, -56. / 15, 32. / 9, 0, 0, 0},
        {19372. / 6561, -25360. / 2187, 64448. / 6561, -212. / 729, 0, 0},
        {9017. / 3168, -355. / 33, 46732. / 5247, 49. / 176, -5103. / 18656, 0},
        {35. / 384, 0, 500. / 1113, 125. / 192, -2187. / 6784, 11. / 84}};
      // The fifth-order weights minus the fourth-order ones.
      constexpr double e[7] = {71. / 57600,
                               0,
                               -71. / 16695,
                               71. / 1920,
                               -17253. / 339200,
                               22. / 525,
                               -1. / 40};
    } // namespace



    DormandPrince::DormandPrince(const Rhs &rhs, const Settings &settings)
      : rhs(rhs)
      , settings(settings)
      , k(7)
    {}



    double
    DormandPrince::advance(double              &t,
                           std::vector<double> &y,
                           double              &dt,
                           const double         t_end)
    {
      const std::size_t n = y.size();
      AssertThrow(settings.absolute_tolerance.size() == n,
                  dealii::ExcInternalError());
      if (k[0].size() != n)
        have_first_stage = false;
      for (auto &stage_rate : k)
        stage_rate.resize(n);
      stage.resize(n);
      if (!have_first_stage)
        {
          rhs(t, y, k[0]);
          have_first_stage = true;
        }
      while (true)
        {
          dt = std::min(dt, settings.maximum_step);
          // The last step lands on t_end exactly (and one within a
          // millionth of a step of it is stretched to it rather than
          // followed by a sliver; relative to the step, so that a rejected
          // step is never stretched back to its old length).
          bool last = false;
          if (t_end - t <= dt * (1 + 1e-6))
            {
              dt   = t_end - t;
              last = true;
            }
          for (unsigned int s = 1; s < 7; ++s)
            {
              for (std::size_t i = 0; i < n; ++i)
                {
                  double sum = 0;
                  for (unsigned int r = 0; r < s; ++r)
                    sum += a[s][r] * k[r][i];
                  stage[i] = y[i] + dt * sum;
                }
              rhs(t + c[s] * dt, stage, k[s]);
            }
          // Stage 7 is at the fifth-order solution itself: stage = y new.
          double ratio  = 0;
          bool   finite = true;
          for (std::size_t i = 0; i < n; ++i)
            {
              double error = 0;
              for (unsigned int s = 0; s < 7; ++s)
                error += e[s] * k[s][i];
              error *= dt;
              const double scale =
                settings.absolute_tolerance[i] +
                settings.relative_tolerance *
                  std::max(std::abs(y[i]), std::abs(stage[i]));
              const double r = std::abs(error) / scale;
              finite         = finite && std::isfinite(r);
              ratio          = std::max(ratio, r);
            }
          if (!finite)
            ratio = 1e10;
          const double factor =
            ratio > 0 ? 0.9 * std::pow(ratio, -0.2) : settings.maximum_growth;
          if (ratio <= 1)
            {
              const double taken = dt;
              // The time as a compensated (Kahan) sum of the steps: over
              // 10^10 s of steps of milliseconds a plain sum drifts.
              if (last)
                {
                  t            = t_end;
                  compensation = 0;
                }
              else
                {
                  const double step = dt - compensation;
                  const double sum  = t + step;
                  compensation      = (sum - t) - step;
                  t                 = sum;
                }
              y.swap(stage);
              std::swap(k[0], k[6]);
              dt = taken * std::clamp(factor, 0.2, settings.maximum_growth);
              dt = std::max(dt, settings.minimum_step);
              return taken;
            }
          ++n_rejected;
          dt *= std::clamp(factor, 0.2, 0.9);
          if (dt < settings.minimum_step)
            {
              std::ostringstream message;
              message << "At t = " << t
                      << " s the step that meets the error tolerance fell "
                         "below the minimum time step of "
                      << settings.minimum_step
                      << " s. Give a smaller minimum, a larger tolerance, "
                         "or (without radiation damping) a quasi-dynamic "
                         "problem: a purely quasi-static one has no "
                         "solution once the fault becomes unstable.";
              AssertThrow(false, dealii::ExcMessage(message.str()));
            }
        }
    }



    void
    DormandPrince::save(std::ostream &out) const
    {
      BinaryIO::write(out,
                      std::vector<double>{double(have_first_stage),
                                          double(n_rejected),
                                          compensation});
      BinaryIO::write(out, have_first_stage ? k[0] : std::vector<double>());
    }



    void
    DormandPrince::load(std::istream &in)
    {
      std::vector<double> scalars;
      BinaryIO::read(in, scalars);
      AssertThrow(scalars.size() == 3,
                  dealii::ExcMessage("The checkpoint's time integrator is "
                                     "damaged."));
      have_first_stage = scalars[0] != 0;
      n_rejected       = static_cast<unsigned long>(scalars[1]);
      compensation     = scalars[2];
      k.resize(7);
      BinaryIO::read(in, k[0]);
    }
  } // namespace TimeIntegration
} // namespace rupture
