"""Tests of contrib/damping-study's case parsing, the 2-D mesh it sets and
its reading of station files."""

import pytest


def test_cases_parse_and_check_the_core(script):
    study = script("damping-study")
    assert study.parse_cases("1:750,3:1500") == [(1, 750.0), (3, 1500.0)]
    with pytest.raises(SystemExit):
        study.parse_cases("1-750")
    with pytest.raises(SystemExit):
        study.parse_cases("5:750")
    # 700 m does not divide the 36 x 3 x 21 km core of the graded box ...
    with pytest.raises(SystemExit):
        study.parse_cases("1:700")
    # ... which the 2-D cases (node spacings) do not need.
    assert study.parse_cases("3:100", check=False) == [(3, 100.0)]


def test_sets_name_the_damping_and_the_mesh(script):
    study = script("damping-study")
    sets = study.sets(2, 750.0, 0.1)
    assert "Damping/Fault zone damping=0.1" in sets
    assert "Scene/Box/Number of cells=48, 4, 28" in sets
    assert "Discretization/Polynomial degree=2" in sets
    # 2-D: degree 3 at 100 m node spacing is 300 m cells over 60 x 30 km.
    sets_2d = study.sets_2d(3, 100.0, 0.3)
    assert "Scene/Box/Number of cells=200, 100" in sets_2d
    assert "Scene/Box/Lower corner=-30000, -15000" in sets_2d
    assert "Damping/Fault zone damping=0.3" in sets_2d
    assert study.directory("/w", 1, 500.0, 0.1) == "/w/tpv3/q1-500-eta0.1"


def test_read_columns_takes_time_and_along_strike_rate(tmp_path, script):
    study = script("damping-study")
    path = tmp_path / "reference-p1.dat"
    path.write_text("# problem=TPV3\n# x = 1\nt h-slip h-slip-rate h-shear-stress\n"
                    "0 0 0 70\n0.5 0.1 1.5 60\n1 0.4 0.5 63\n")
    t, rate = study.read_columns(str(path))
    assert t == [0.0, 0.5, 1.0]
    assert rate == [0.0, 1.5, 0.5]
