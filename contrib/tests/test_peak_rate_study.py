"""Tests of contrib/peak-rate-study: the observed order and Richardson
limit of a known power law at halved and at uneven spacings, what it
refuses, the distance within the goal, and the cases it runs."""

import math


def test_observed_order_and_limit_of_a_power_law(script):
    study = script("peak-rate-study")
    for q in (1.0, 1.5, 2.0):
        law = lambda h: 3.0 + 2.0 * (h / 100.0) ** q
        for spacings in ([100.0, 50.0, 25.0], [250.0, 500.0 / 3.0, 100.0]):
            got_q, limit = study.observed([law(h) for h in spacings], spacings)
            assert abs(got_q - q) < 1e-9 and abs(limit - 3.0) < 1e-9
    # From below as well (the values rise towards the limit).
    law = lambda h: 10.0 - (h / 100.0) ** 2
    got_q, limit = study.observed([law(h) for h in (100.0, 50.0, 25.0)], [100.0, 50.0, 25.0])
    assert abs(got_q - 2.0) < 1e-9 and abs(limit - 10.0) < 1e-9


def test_observed_refuses_what_does_not_converge(script):
    study = script("peak-rate-study")
    spacings = [100.0, 50.0, 25.0]
    assert study.observed([1.0, 2.0, 1.5], spacings) == (None, None)  # sign change
    assert study.observed([1.0, 2.0, 3.5], spacings) == (None, None)  # growing steps
    assert study.observed([2.0, 2.0, 2.0], spacings) == (None, 2.0)   # no change at all


def test_reach_stops_at_the_first_station_beyond_the_goal(script):
    study = script("peak-rate-study")
    stations = [0, 15, 30, 45]
    assert study.reach({"0": 0.01, "15": 0.04, "30": 0.06, "45": 0.01}, stations, 5) == 1.5
    assert study.reach({"0": 0.06, "15": 0.0, "30": 0.0, "45": 0.0}, stations, 5) == -1
    assert study.reach({"0": 0.0, "15": None, "30": 0.0, "45": 0.0}, stations, 5) == 0
    assert study.reach({s: 0.0 for s in ("0", "15", "30", "45")}, stations, 5) == 4.5
    # Both sides of a distance must be within the goal (TPV205-2D's).
    sides = ["0", "+45", "-45", "+120", "-120"]
    errors = {"0": 0.0, "+45": 0.01, "-45": 0.01, "+120": 0.01, "-120": 0.051}
    assert study.reach(errors, sides, 5) == 4.5


def test_cases_put_stations_on_nodes_and_set_the_damping(script):
    study = script("peak-rate-study")
    sets = study.case_sets(3, 25.0, 0.1, 0.5, 7.0)
    assert "Scene/Box/Number of cells=800, 400" in sets
    assert "Damping/Fault zone damping=0.1" in sets
    assert "Time integration/End time=7" in sets
    assert not any(s.startswith("Time integration/End time")
                   for s in study.case_sets(3, 25.0, 0.0, 0.5, None))
    assert study.case_name(3, 25.0, 0.1, 0.5) == "q3-h75m-c0.5-eta0.1"
    assert math.isclose(study.cell_size(3, 100.0), 300.0)
