"""Earthquake cycles: events in a slip-rate history, and the quasi-dynamic
spring-slider with regularised rate and state and the aging law, integrated
accurately (the reference of tests/fault/spring_slider_cycles.cc and
contrib/spring-slider)."""

import math

YEAR = 3.15576e7


def find_events(t, V, start=1e-3, stop=1e-4):
    """Events in the slip-rate history V(t): an event starts when V passes
    @p start (the time interpolated in ln V) and ends when V falls below
    @p stop. Returns (start times, peak slip rates)."""
    starts, peaks, on = [], [], False
    for i in range(1, len(t)):
        if not on and V[i] >= start:
            l0 = math.log(max(V[i - 1], 1e-300))
            l1 = math.log(V[i])
            w = (math.log(start) - l0) / (l1 - l0)
            starts.append(t[i - 1] + w * (t[i] - t[i - 1]))
            peaks.append(0.0)
            on = True
        if on:
            peaks[-1] = max(peaks[-1], V[i])
        if V[i] < stop:
            on = False
    return starts, peaks


def cycle(starts, peaks, skip=1):
    """The mean interval between events and their mean peak slip rate,
    leaving out the first @p skip events (which the initial state
    shapes); None with fewer than skip + 2 events."""
    if len(starts) < skip + 2:
        return None
    n = len(starts) - skip
    period = (starts[-1] - starts[skip]) / (n - 1)
    return period, sum(peaks[skip:]) / n


def read_catalogue(path):
    """The complete events of an events.csv (the event catalogue of
    rupture's runs): (start years, peak slip rates, largest slips)."""
    import csv
    starts, peaks, slips = [], [], []
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f
                                      if not line.startswith("#"))]
    if not rows:
        return starts, peaks, slips
    col = {name: i for i, name in enumerate(rows[0])}
    for r in rows[1:]:
        if r[col["complete"]] != "1":
            continue
        starts.append(float(r[col["start (years)"]]))
        peaks.append(float(r[col["peak slip rate (m/s)"]]))
        slips.append(float(r[col["largest slip (m)"]]))
    return starts, peaks, slips


def merge_events(starts, peaks, slips, gap=1.0):
    """The events with those that start within @p gap years of the start
    of the event before counted with it: at coarse resolution the largest
    slip rate can dip below 1 mm/s for a moment while an event dies out
    and rise again (a second front), which the catalogue lists as an event
    of its own."""
    kept = ([], [], [])
    for s, p, d in zip(starts, peaks, slips):
        if kept[0] and s - kept[0][-1] < gap:
            kept[1][-1] = max(kept[1][-1], p)
            kept[2][-1] = max(kept[2][-1], d)
            continue
        for column, value in zip(kept, (s, p, d)):
            column.append(value)
    return kept


def recurrence(starts, skip=2):
    """The mean interval between the events after the first @p skip (the
    SEAS benchmarks' recurrence interval); None with fewer than skip + 2."""
    if len(starts) < skip + 2:
        return None
    later = starts[skip:]
    return (later[-1] - later[0]) / (len(later) - 1)


class Slider:
    """tau0 + k (V_p t - delta) = sigma F(V, theta) + eta V with
    F = a asinh(V / (2 V0) exp((f0 + b ln(V0 theta / L)) / a)) and
    d theta / dt = 1 - V theta / L."""

    def __init__(self, k, sigma, a, b, L, f0, V0, Vp, eta, tau0, theta0):
        self.__dict__.update(k=k, sigma=sigma, a=a, b=b, L=L, f0=f0, V0=V0,
                             Vp=Vp, eta=eta, tau0=tau0, theta0=theta0)

    def friction(self, V, theta):
        """F and its derivatives in V and theta."""
        z = V / (2 * self.V0) * math.exp(
            (self.f0 + self.b * math.log(self.V0 * theta / self.L)) / self.a)
        s = math.sqrt(1 + z * z)
        return (self.a * math.asinh(z), self.a * z / (s * V),
                z / s * self.b / theta)

    def initial_rate(self):
        """V at t = 0: tau0 = sigma F(V, theta0) + eta V, by bisection."""
        lo, hi = -60.0, 5.0
        for _ in range(200):
            m = 0.5 * (lo + hi)
            F = self.friction(math.exp(m), self.theta0)[0]
            if self.sigma * F + self.eta * math.exp(m) < self.tau0:
                lo = m
            else:
                hi = m
        return math.exp(0.5 * (lo + hi))

    def rhs(self, y):
        """d/dt of (ln V, ln theta)."""
        V, theta = math.exp(y[0]), math.exp(y[1])
        _, F_V, F_theta = self.friction(V, theta)
        dtheta = 1 - V * theta / self.L
        dV = ((self.k * (self.Vp - V) - self.sigma * F_theta * dtheta) /
              (self.sigma * F_V + self.eta))
        return (dV / V, dtheta / theta)

    def integrate(self, end, tolerance=1e-11):
        """Dormand-Prince 5(4) from t = 0 to @p end with an error of
        @p tolerance per step in (ln V, ln theta): the accepted steps' times
        and slip rates."""
        A = [[], [1 / 5], [3 / 40, 9 / 40], [44 / 45, -56 / 15, 32 / 9],
             [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729],
             [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176,
              -5103 / 18656],
             [35 / 384, 0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84]]
        E = [71 / 57600, 0, -71 / 16695, 71 / 1920, -17253 / 339200,
             22 / 525, -1 / 40]
        y = (math.log(self.initial_rate()), math.log(self.theta0))
        time, h = 0.0, 1.0
        ts, Vs = [0.0], [math.exp(y[0])]
        while time < end:
            h = min(h, end - time)
            K = []
            for s in range(7):
                ys = [y[i] + h * sum(A[s][j] * K[j][i] for j in range(s))
                      for i in range(2)]
                K.append(self.rhs(ys))
            new = [y[i] + h * sum(A[6][j] * K[j][i] for j in range(6))
                   for i in range(2)]
            error = max(abs(h * sum(E[s] * K[s][i] for s in range(7)))
                        for i in range(2)) / tolerance
            if error <= 1:
                y = new
                time += h
                ts.append(time)
                Vs.append(math.exp(y[0]))
            h *= min(5.0, max(0.2, 0.9 * max(error, 1e-30) ** -0.2))
        return ts, Vs


def test_slider():
    """The slider of tests/fault/inputs/spring_slider_cycles.prm."""
    mu, p_t = 2.5e10 / 2.5, 5e11
    return Slider(k=1 / (1000 / mu + 1 / p_t), sigma=1e7, a=0.01, b=0.015,
                  L=1e-3, f0=0.6, V0=1e-6, Vp=1e-9, eta=4.62e6,
                  tau0=6345387.768569107, theta0=1.2e6)
