"""Tests of rupturetools.bench2d and of contrib/degree-study's mesh sizing,
on station files made here."""

import math

import pytest

from rupturetools import bench2d

from stations import write_station


def test_station_values_average_both_sides(tmp_path):
    write_station(tmp_path, "faultst000", 0.5, 2.0, 1.0)
    write_station(tmp_path, "faultst045", 2.0, 4.0, 2.0)
    write_station(tmp_path, "faultst-045", 2.2, 2.0, 1.0)
    v = bench2d.station_values(str(tmp_path), stations=[0, 45])
    assert abs(v[0]["rupture"] - 0.5) < 0.011
    assert abs(v[45]["rupture"] - 2.1) < 0.011
    assert abs(v[45]["peak"] - 3.0) < 1e-12
    assert abs(v[45]["slip"] - 1.5) < 1e-9


def test_errors_absolute_in_time_relative_otherwise():
    ref = {"0": {"rupture": 1.0, "peak": 10.0, "slip": 2.0},
           "45": {"rupture": 2.0, "peak": 5.0, "slip": 4.0}}
    mine = {0: {"rupture": 1.1, "peak": 11.0, "slip": 2.0},
            45: {"rupture": 1.95, "peak": 5.0, "slip": 3.0}}
    e = bench2d.errors(mine, ref, stations=[0, 45])
    assert abs(e["rupture"] - 0.1) < 1e-12
    assert abs(e["peak"] - 0.1) < 1e-12
    assert abs(e["slip"] - 0.25) < 1e-12
    mine[45]["rupture"] = None
    assert math.isinf(bench2d.errors(mine, ref, stations=[0, 45])["rupture"])


def test_degree_study_mesh_puts_every_station_on_a_node(script):
    study = script("degree-study")
    for p in (1, 2, 3, 4):
        nodes = [0.0, 1.0] if p % 2 else [0.0, 0.5, 1.0]
        for spacing in (200, 100, 50, 25):
            h = study.cell_size(p, spacing)
            assert h <= p * spacing + 1e-9
            nx, ny, half_x, half_y = study.mesh(p, spacing)
            assert nx % 2 == 0 and ny % 2 == 0
            assert abs(half_x - 30000) <= h and abs(half_y - 15000) <= h
            for station in range(0, 15001, 1500):
                xi = station / h - math.floor(station / h)
                assert min(abs(xi - n) for n in nodes) < 1e-9, (p, spacing, station)
    assert study.mesh(4, 100) == (160, 80, 30000, 15000)
    assert study.cell_size(2, 100) == 200 and study.cell_size(3, 100) == 300


def test_one_side_each_keeps_the_sides_apart(tmp_path):
    assert bench2d.one_side_each([0, 45]) == ["0", "+45", "-45"]
    assert [bench2d.station_label(s) for s in ("0", "+45", "-45", 45)] == \
        ["0", "+4.5", "-4.5", "4.5"]
    write_station(tmp_path, "faultst000", 0.5, 2.0, 1.0)
    write_station(tmp_path, "faultst045", 2.0, 4.0, 2.0)
    write_station(tmp_path, "faultst-045", 2.2, 2.0, 1.0)
    v = bench2d.station_values(str(tmp_path), stations=bench2d.one_side_each([0, 45]))
    assert abs(v["+45"]["rupture"] - 2.0) < 0.011
    assert abs(v["-45"]["rupture"] - 2.2) < 0.011
    assert abs(v["-45"]["peak"] - 2.0) < 1e-12
    ref = {"0": v["0"], "+45": v["+45"], "-45": dict(v["-45"], slip=2.0)}
    e = bench2d.errors(v, ref, stations=["0", "+45", "-45"])
    assert abs(e["slip"] - 0.5) < 1e-9 and e["rupture"] == 0.0


def test_parse_list_reads_numbers_and_refuses_others():
    assert bench2d.parse_list("100, 50,,25") == [100.0, 50.0, 25.0]
    assert bench2d.parse_list("2,3,4", int) == [2, 3, 4]
    assert bench2d.parse_list("") == []
    with pytest.raises(ValueError):
        bench2d.parse_list("2,three", int)
