"""Tests of contrib/rupturetools/cycles.py (events in a slip-rate history,
the spring-slider reference) and contrib/spring-slider's cases."""

import math

from rupturetools import cycles


def test_events_start_where_the_rate_passes_the_threshold():
    # ln V rises linearly from 1e-4 to 1e-2 between t = 0 and 2: it passes
    # 1e-3 at t = 1; the event ends below 1e-4, and a second one starts.
    t = [0, 2, 3, 4, 5, 6]
    V = [1e-4, 1e-2, 5e-2, 5e-5, 2e-3, 1e-6]
    starts, peaks = cycles.find_events(t, V)
    assert len(starts) == 2
    assert math.isclose(starts[0], 1.0, rel_tol=1e-12)
    assert peaks == [5e-2, 2e-3]
    # Dipping below 1e-3 but not below 1e-4 does not end an event.
    starts, _ = cycles.find_events([0, 1, 2, 3], [1e-5, 2e-3, 5e-4, 2e-3])
    assert len(starts) == 1


def test_cycle_leaves_out_the_first_event():
    assert cycles.cycle([0.5, 4, 8, 12], [1, 2, 3, 4]) == (4.0, 3.0)
    assert cycles.cycle([0.5, 4], [1, 2]) is None


def test_slider_starts_in_balance_and_cycles():
    s = cycles.test_slider()
    V = s.initial_rate()
    F = s.friction(V, s.theta0)[0]
    assert math.isclose(s.sigma * F + s.eta * V, s.tau0, rel_tol=1e-12)
    # k is below (b - a) sigma / L: stick-slip with a period of about 4.1
    # years (the first event comes early, from the initial state).
    t, rates = s.integrate(3.0e8, tolerance=1e-8)
    starts, peaks = cycles.find_events(t, rates)
    assert len(starts) == 3
    period, peak = cycles.cycle(starts, peaks)
    assert abs(period / cycles.YEAR - 4.1016) < 0.002
    assert abs(peak - 0.2474) < 0.001


def test_cases_set_the_controller_and_the_friction_time(script):
    study = script("spring-slider")
    sets = study.sets("centred", 0.05, 2.5e6)
    assert "Fault/Penalty friction time=centred" in sets
    assert ("Time integration/Step controller/State evolution fraction=0.05"
            in sets)
    assert "Time integration/Step controller/Maximum time step=2.5e+06" in sets
    assert study.directory("/w", "end of step", 0.1, 1e7) == \
        "/w/end-of-step-xi0.1-max1e+07"
