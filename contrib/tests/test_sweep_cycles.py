"""Tests of contrib/sweep's summary of earthquake-cycle cases
(rupturetools/sweep_summary.py): the cycle columns from a case's
events.csv and the cycles.png plot."""

import math
import os

from rupturetools import sweep_summary

HEADER = ("# Earthquakes of the run\n"
          "event,start (s),start (years),end (s),duration (s),"
          "hypocentre x (m),hypocentre y (m),peak slip rate (m/s),"
          "moment (N/m),ruptured length (m),mean slip (m),largest slip (m),"
          "complete\n")


def catalogue(directory, events):
    """Write an events.csv of (start years, peak rate, largest slip,
    complete) rows."""
    rows = [f"{i + 1},0,{s},0,0,0,0,{p},0,0,0,{d},{c}"
            for i, (s, p, d, c) in enumerate(events)]
    (directory / "events.csv").write_text(HEADER + "\n".join(rows) + "\n")


def test_cycle_columns_average_the_events_after_the_first_two(tmp_path):
    catalogue(tmp_path, [(100, 5.0, 3.0, 1), (180, 4.0, 2.8, 1),
                         (260, 2.0, 2.0, 1), (340, 4.0, 3.0, 1),
                         (420, 9.0, 9.0, 0)])
    row = sweep_summary.cycle_columns(str(tmp_path))
    assert row["events"] == 4  # the incomplete last event left out
    assert math.isclose(row["recurrence"], 80.0)
    assert math.isclose(row["event peak slip rate"], 3.0)
    assert math.isclose(row["event slip"], 2.5)


def test_cycle_columns_without_enough_events(tmp_path):
    row = sweep_summary.cycle_columns(str(tmp_path))
    assert all(v is None for v in row.values())
    catalogue(tmp_path, [(100, 5.0, 3.0, 1), (180, 4.0, 2.8, 1),
                         (260, 2.0, 2.0, 1)])
    row = sweep_summary.cycle_columns(str(tmp_path))
    assert row["events"] == 3 and row["recurrence"] is None
    assert row["event slip"] is None and row["event peak slip rate"] is None


def test_plot_cycles_writes_the_picture_with_missing_values(tmp_path):
    sweep = {"title": "a cycle sweep", "output": str(tmp_path),
             "vary": [{"alias": "L"}, {"alias": "b"}]}
    rows = []
    for L in ("0.004", "0.008", "0.016"):
        for b in ("0.015", "0.02"):
            rows.append({"L": L, "b": b, "events": 5,
                         "recurrence": 80 * float(L) / 0.008,
                         "event slip": 2.0, "event peak slip rate": 1.0})
    rows[0].update(recurrence=None, **{"event slip": None,
                                       "event peak slip rate": None})
    sweep_summary.plot_cycles(sweep, rows)
    assert os.path.getsize(tmp_path / "cycles.png") > 1000


def test_boundary_integral_cycles_are_their_own_outcome(tmp_path):
    """A finished case with an event catalogue but no single rupture's area
    (the boundary-integral method's summary.json) is 'earthquake cycles',
    whatever the fault size, and its sweep draws cycles.png only."""
    sweep = {"title": "cycles", "output": str(tmp_path), "derive": [],
             "vary": [{"alias": "L", "entry": "Fault/Rate and state/"
                       "Characteristic slip distance"}],
             "whole fault fraction": 0.95, "fault size": 40000}
    cases = [{"L": 0.004}, {"L": 0.008}]
    for i in range(2):
        d = tmp_path / f"case-{i:04d}"
        d.mkdir()
        (d / "summary.json").write_text(
            '{"status": "finished", "end": "end time"}')
        catalogue(d, [(100, 5.0, 3.0, 1), (180, 4.0, 2.8, 1),
                      (260, 2.0, 2.0, 1), (340 + 10 * i, 4.0, 3.0, 1)])
    rows, _ = sweep_summary.summarise(sweep, cases)
    assert [r["outcome"] for r in rows] == ["earthquake cycles"] * 2
    assert math.isclose(rows[1]["recurrence"], 90.0)
    assert sweep_summary.plot(sweep, rows, None) == ["cycles.png"]
    assert os.path.exists(tmp_path / "cycles.png")
    assert not os.path.exists(tmp_path / "outcome-map.png")
