// The clock of adaptive steps (PhaseClock::enter_adaptive_step()): a phase
// that starts after 100 years of loading (3.15576e9 s) takes a million
// steps of about a millisecond (1e-3 (1 + 0.5 sin k) s) and then the
// rest to its end. The absolute time after each step is the start plus
// the exact sum of the steps (summed in long double) to within half a
// unit in the last place of a double at 3e9 s (2.4e-7 s), where adding
// the steps in double drifts by far more; the phase time since the start
// is that sum to within an ulp of the absolute time (adaptive steps have
// its resolution, which is why they are not offered after a loading
// phase); the last step ends at the phase's end exactly and the
// compensation is reset.

#include <rupture/time_integration/phase_clock.h>

#include <cmath>
#include <cstdio>

int
main()
{
  using rupture::TimeIntegration::PhaseClock;
  PhaseClock   clock;
  const double start = 3.15576e9, duration = 1200;
  clock.begin_phase(start, 0);
  clock.start_dynamic_phase(start);
  double      now = start, naive = start, worst = 0, worst_phase = 0;
  long double exact = 0;
  for (unsigned int k = 1; k <= 1000000; ++k)
    {
      const double dt = 1e-3 * (1 + 0.5 * std::sin(double(k)));
      exact += dt;
      naive += dt;
      now   = clock.enter_adaptive_step(k, now, dt, duration, false);
      worst = std::max(worst,
                       double(std::fabs((long double)now -
                                        ((long double)start + exact))));
      worst_phase =
        std::max(worst_phase,
                 double(std::fabs((long double)clock.phase_time - exact)));
    }
  const double ulp = std::nextafter(start, 2 * start) - start;
  std::printf("after 1e6 steps: time within half an ulp of the exact sum "
              "(%.1e s): %s\n",
              ulp / 2,
              worst <= ulp / 2 ? "yes" : "no");
  std::printf("adding the steps in double drifts by more than 100 ulps: %s\n",
              std::fabs((long double)naive - ((long double)start + exact)) >
                  100 * ulp ?
                "yes" :
                "no");
  std::printf("phase time the exact sum within an ulp of the absolute "
              "time: %s\n",
              worst_phase <= ulp ? "yes" : "no");
  std::printf("steps in the phase: %u\n", clock.steps_in_phase);
  now = clock.enter_adaptive_step(1000001, now, 1e-3, duration, true);
  std::printf("the last step ends at the phase's end exactly: %s, phase "
              "time %g s, compensation reset: %s\n",
              now == start + duration ? "yes" : "no",
              clock.phase_time,
              clock.compensation == 0 ? "yes" : "no");
  return 0;
}
