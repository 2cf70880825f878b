"""Tests of the cycle measures of contrib/rupturetools/cycles.py that
contrib/seas-bp1 and contrib/sweep use: reading events.csv, merging the
events that start within a year of the one before, and the recurrence
interval."""

import math

from rupturetools import cycles


CSV = """# Earthquakes of the run: intervals ...
event,start (s),start (years),end (s),duration (s),hypocentre x (m),\
hypocentre y (m),peak slip rate (m/s),moment (N/m),ruptured length (m),\
mean slip (m),largest slip (m),complete
1,6.2e9,198.02,6.2e9,50,0,-16000,4.2,1e11,17800,2.4,2.8,1
2,6.2e9,198.0215,6.2e9,90,0,-17000,0.0018,1e9,200,0.1,0.1,1
3,8.6e9,273.0,8.6e9,50,0,-16000,3.9,1e11,17800,2.1,2.5,1
4,1.1e10,351.0,1.1e10,50,0,-16000,3.8,1e11,17800,2.1,2.6,0
"""


def test_read_catalogue_keeps_the_complete_rows(tmp_path):
    path = tmp_path / "events.csv"
    path.write_text(CSV)
    starts, peaks, slips = cycles.read_catalogue(str(path))
    assert starts == [198.02, 198.0215, 273.0]
    assert peaks == [4.2, 0.0018, 3.9]
    assert slips == [2.8, 0.1, 2.5]


def test_merge_counts_an_event_within_a_year_with_the_one_before():
    starts, peaks, slips = cycles.merge_events(
        [198.02, 198.0215, 273.0], [4.2, 0.0018, 3.9], [2.8, 0.1, 2.5])
    assert starts == [198.02, 273.0]
    assert peaks == [4.2, 3.9]
    assert slips == [2.8, 2.5]
    # A later, larger part raises the merged event's peak.
    _, peaks, _ = cycles.merge_events([10.0, 10.5], [1.0, 2.0], [1.0, 1.0])
    assert peaks == [2.0]


def test_recurrence_leaves_out_the_first_two_events():
    assert math.isclose(cycles.recurrence([100, 190, 270, 350, 430]), 80.0)
    assert cycles.recurrence([100, 190, 270]) is None


def test_seas_bp1_measures_a_run(script, tmp_path):
    bp1 = script("seas-bp1")
    (tmp_path / "events.csv").write_text(CSV)
    (tmp_path / "summary.json").write_text(
        '{"status": "finished", "elements": 200, "steps": 10, '
        '"rejected steps": 1, "smallest time step": 0.001, '
        '"largest time step": 1e7, "wall time": 5}')
    m = bp1.measure(str(tmp_path))
    assert m["events"] == 2 and m["catalogue rows"] == 3
    assert m["recurrence (years)"] is None
