"""Tests of contrib/seas-bp1: reading events.csv, merging the events that
start within a year of the one before, and the recurrence interval."""

import math


CSV = """# Earthquakes of the run: intervals ...
event,start (s),start (years),end (s),duration (s),hypocentre x (m),\
hypocentre y (m),peak slip rate (m/s),moment (N/m),ruptured length (m),\
mean slip (m),largest slip (m),complete
1,6.2e9,198.02,6.2e9,50,0,-16000,4.2,1e11,17800,2.4,2.8,1
2,6.2e9,198.0215,6.2e9,90,0,-17000,0.0018,1e9,200,0.1,0.1,1
3,8.6e9,273.0,8.6e9,50,0,-16000,3.9,1e11,17800,2.1,2.5,1
4,1.1e10,351.0,1.1e10,50,0,-16000,3.8,1e11,17800,2.1,2.6,0
"""


def test_read_events_keeps_the_complete_rows(script, tmp_path):
    bp1 = script("seas-bp1")
    path = tmp_path / "events.csv"
    path.write_text(CSV)
    starts, peaks, slips = bp1.read_events(str(path))
    assert starts == [198.02, 198.0215, 273.0]
    assert peaks == [4.2, 0.0018, 3.9]
    assert slips == [2.8, 0.1, 2.5]


def test_merge_counts_an_event_within_a_year_with_the_one_before(script):
    bp1 = script("seas-bp1")
    starts, peaks, slips = bp1.merge([198.02, 198.0215, 273.0],
                                     [4.2, 0.0018, 3.9], [2.8, 0.1, 2.5])
    assert starts == [198.02, 273.0]
    assert peaks == [4.2, 3.9]
    assert slips == [2.8, 2.5]
    # A later, larger part raises the merged event's peak.
    _, peaks, _ = bp1.merge([10.0, 10.5], [1.0, 2.0], [1.0, 1.0])
    assert peaks == [2.0]


def test_recurrence_leaves_out_the_first_two_events(script):
    bp1 = script("seas-bp1")
    assert math.isclose(bp1.recurrence([100, 190, 270, 350, 430]), 80.0)
    assert bp1.recurrence([100, 190, 270]) is None
