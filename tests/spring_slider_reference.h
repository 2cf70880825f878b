// The quasi-dynamic spring-slider, integrated accurately: the reference of
// the cycle tests (fault/spring_slider_cycles, boundary_integral/
// spring_slider). A block on a rate-and-state fault (regularised law,
// aging), a spring of stiffness k pushed at V_p, radiation damping eta:
//   tau0 + k (V_p t - delta) = sigma F(V, theta) + eta V,
//   d theta / dt = 1 - V theta / L,
// so that
//   dV/dt = (k (V_p - V) - sigma dF/dtheta dtheta/dt) / (sigma dF/dV + eta),
// integrated in (ln V, ln theta) by Dormand-Prince 5(4) with a relative
// error of 1e-11 per step.

#ifndef rupture_tests_spring_slider_reference_h
#define rupture_tests_spring_slider_reference_h

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

namespace slider_reference
{
  using Y = std::array<double, 2>; // ln V, ln theta

  struct Slider
  {
    double k, sigma, a, b, L, f0, V0, Vp, eta, tau0, theta0;

    // F and its derivatives in V and theta.
    void
    friction(const double V,
             const double theta,
             double      &F,
             double      &F_V,
             double      &F_theta) const
    {
      const double z =
        V / (2 * V0) * std::exp((f0 + b * std::log(V0 * theta / L)) / a);
      const double s = std::sqrt(1 + z * z);
      F              = a * std::asinh(z);
      F_V            = a * z / (s * V);
      F_theta        = z / s * b / theta;
    }

    Y
    rhs(const Y &y) const
    {
      const double V = std::exp(y[0]), theta = std::exp(y[1]);
      double       F, F_V, F_theta;
      friction(V, theta, F, F_V, F_theta);
      const double dtheta = 1 - V * theta / L;
      const double dV =
        (k * (Vp - V) - sigma * F_theta * dtheta) / (sigma * F_V + eta);
      return {dV / V, dtheta / theta};
    }

    // The slip of the slider in state y at time t: tau0 + k (V_p t - delta)
    // = sigma F + eta V.
    double
    slip_of(const double t, const Y &y) const
    {
      double F, F_V, F_theta;
      friction(std::exp(y[0]), std::exp(y[1]), F, F_V, F_theta);
      return Vp * t + (tau0 - sigma * F - eta * std::exp(y[0])) / k;
    }

    // ln V at t = 0: tau0 = sigma F(V, theta0) + eta V.
    double
    initial_log_rate() const
    {
      double lower = -60, upper = 5;
      for (unsigned int it = 0; it < 200; ++it)
        {
          const double m = 0.5 * (lower + upper);
          double       F, F_V, F_theta;
          friction(std::exp(m), theta0, F, F_V, F_theta);
          (sigma * F + eta * std::exp(m) < tau0 ? lower : upper) = m;
        }
      return 0.5 * (lower + upper);
    }

    // Dormand-Prince 5(4), adaptive, from t = 0 to end: the accepted steps'
    // times, slip rates and slips.
    void
    integrate(Y                    y,
              const double         end,
              std::vector<double> &t,
              std::vector<double> &V,
              std::vector<double> &D) const
    {
      static const double A[7][6] = {
        {0, 0, 0, 0, 0, 0},
        {1. / 5, 0, 0, 0, 0, 0},
        {3. / 40, 9. / 40, 0, 0, 0, 0},
        {44. / 45, -56. / 15, 32. / 9, 0, 0, 0},
        {19372. / 6561, -25360. / 2187, 64448. / 6561, -212. / 729, 0, 0},
        {9017. / 3168, -355. / 33, 46732. / 5247, 49. / 176, -5103. / 18656, 0},
        {35. / 384, 0, 500. / 1113, 125. / 192, -2187. / 6784, 11. / 84}};
      static const double e[7] = {71. / 57600,
                                  0,
                                  -71. / 16695,
                                  71. / 1920,
                                  -17253. / 339200,
                                  22. / 525,
                                  -1. / 40};
      double              time = 0, h = 1;
      t.push_back(time);
      V.push_back(std::exp(y[0]));
      D.push_back(slip_of(time, y));
      while (time < end)
        {
          h = std::min(h, end - time);
          std::array<Y, 7> K;
          for (unsigned int s = 0; s < 7; ++s)
            {
              Y ys = y;
              for (unsigned int j = 0; j < s; ++j)
                for (unsigned int i = 0; i < 2; ++i)
                  ys[i] += h * A[s][j] * K[j][i];
              K[s] = rhs(ys);
            }
          Y      next  = y;
          double error = 0;
          for (unsigned int i = 0; i < 2; ++i)
            {
              double err = 0;
              for (unsigned int s = 0; s < 7; ++s)
                {
                  next[i] += (s < 6 ? h * A[6][s] * K[s][i] : 0);
                  err += h * e[s] * K[s][i];
                }
              error = std::max(error, std::abs(err) / 1e-11);
            }
          if (error <= 1)
            {
              y = next;
              time += h;
              t.push_back(time);
              V.push_back(std::exp(y[0]));
              D.push_back(slip_of(time, y));
            }
          h *=
            std::clamp(0.9 * std::pow(std::max(error, 1e-30), -0.2), 0.2, 5.);
        }
    }
  };

  struct Events
  {
    std::vector<double> start, peak;
  };

  // Events in a slip-rate history: from the slip rate passing 1 mm/s
  // (interpolated in ln V) to its fall below 0.1 mm/s.
  inline Events
  find_events(const std::vector<double> &t, const std::vector<double> &V)
  {
    Events events;
    bool   on = false;
    for (unsigned int i = 1; i < t.size(); ++i)
      {
        if (!on && V[i] >= 1e-3)
          {
            const double l0 = std::log(std::max(V[i - 1], 1e-300)),
                         l1 = std::log(V[i]);
            const double w  = (std::log(1e-3) - l0) / (l1 - l0);
            events.start.push_back(t[i - 1] + w * (t[i] - t[i - 1]));
            events.peak.push_back(0);
            on = true;
          }
        if (on)
          events.peak.back() = std::max(events.peak.back(), V[i]);
        if (V[i] < 1e-4)
          on = false;
      }
    return events;
  }

  // Print the events of a run (@p label: "FE", "BI") beside the slider's:
  // start (years) and peak slip rate.
  inline void
  print_events(const Events &reference, const Events &events, const char *label)
  {
    const double yr = 3.15576e7;
    std::printf(
      "  event  start (yr): ODE     %s        peak V (m/s): ODE   %s\n",
      label,
      label);
    for (unsigned int i = 0;
         i < std::max(events.start.size(), reference.start.size());
         ++i)
      {
        const auto get = [i](const std::vector<double> &v, const double s) {
          return i < v.size() ? v[i] * s : 0.;
        };
        std::printf("  %5u  %10.4f  %10.4f     %8.4f  %8.4f\n",
                    i + 1,
                    get(reference.start, 1 / yr),
                    get(events.start, 1 / yr),
                    get(reference.peak, 1),
                    get(events.peak, 1));
      }
  }

  // Each event's slip in a history of times t, slip rates V and slips D:
  // between the crossings of 1 mm/s (interpolated in ln V).
  inline std::vector<double>
  event_slips(const std::vector<double> &t,
              const std::vector<double> &V,
              const std::vector<double> &D)
  {
    std::vector<double> slips;
    const auto          at = [&](const unsigned int i, const double rate) {
      const double w = (std::log(rate) - std::log(V[i - 1])) /
                       (std::log(V[i]) - std::log(V[i - 1]));
      return D[i - 1] + w * (D[i] - D[i - 1]);
    };
    double start = 0;
    for (unsigned int i = 1; i < t.size(); ++i)
      if (V[i - 1] < 1e-3 && V[i] >= 1e-3)
        start = at(i, 1e-3);
      else if (V[i - 1] >= 1e-3 && V[i] < 1e-3)
        slips.push_back(at(i, 1e-3) - start);
    return slips;
  }

  // The mean interval and peak after the first event.
  inline std::array<double, 2>
  cycle(const Events &events)
  {
    const unsigned int n = events.start.size();
    if (n < 3)
      return {0, 0};
    double peak = 0;
    for (unsigned int i = 1; i < n; ++i)
      peak += events.peak[i] / (n - 1);
    return {(events.start[n - 1] - events.start[1]) / (n - 2), peak};
  }
} // namespace slider_reference

#endif
