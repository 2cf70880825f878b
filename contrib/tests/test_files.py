"""Tests of rupturetools.files on small files made here."""

import pytest

from rupturetools import files


STATISTICS = """# 1: Time step number
# 2: Time (s)
# 9: Energy balance error (J): kinetic + strain - work
# 14: Slipping area (m^2, m in 2-D)
0 0 0 0 0 0 0 0 1e-3 0 0 0 0 2
1 0.5 0 0 0 0 0 0 2e-3 0 0 0 0 4
"""

STATION = """# problem=TPV101-2D
# location= 0 km along strike, 7.5 km down-dip
t h-slip h-slip-rate h-shear-stress
0 0 0 70
0.5 0.001 0.0005 71
1.0 0.004 0.0025 69
"""


def test_statistics_by_name(tmp_path):
    p = tmp_path / "statistics"
    p.write_text(STATISTICS)
    t = files.read_statistics(str(p))
    assert len(t) == 2
    assert t["Time"] == [0.0, 0.5]
    assert t["Energy balance error"] == [1e-3, 2e-3]
    assert t["Slipping area"] == [2.0, 4.0]
    # Columns without a header line get a name of their own.
    assert t.names[2] == "column 3"
    with pytest.raises(KeyError, match="Kinetic energy"):
        t["Kinetic energy"]


def test_station_by_name(tmp_path):
    p = tmp_path / "faultst000dp075.dat"
    p.write_text(STATION)
    s = files.read_station(str(p))
    assert s.names == ["t", "h-slip", "h-slip-rate", "h-shear-stress"]
    assert s["h-shear-stress"] == [70.0, 71.0, 69.0]
    assert "h-slip" in s and "n-stress" not in s


def test_station_errors(tmp_path):
    p = tmp_path / "broken.dat"
    p.write_text("# nothing\n0 1 2\n")
    with pytest.raises(ValueError, match="field-name line"):
        files.read_station(str(p))
    p.write_text("t h-slip\n0 x\n")
    with pytest.raises(ValueError, match="line 2"):
        files.read_station(str(p))


def test_crossing_time_and_value_at():
    t = [0.0, 1.0, 2.0, 3.0]
    v = [0.0, 0.0005, 0.0015, 0.01]
    # Between 1 and 2: 0.0005 + (t - 1) 0.001 = 0.001 at t = 1.5.
    assert files.crossing_time(t, v, 1e-3) == pytest.approx(1.5)
    assert files.crossing_time(t, v, 1.0) is None
    # Negative rates count by magnitude.
    assert files.crossing_time(t, [-x for x in v], 1e-3) == pytest.approx(1.5)
    assert files.value_at(t, v, 2.5) == pytest.approx(0.00575)
    assert files.value_at(t, v, 3.0) == pytest.approx(0.01)
    with pytest.raises(ValueError):
        files.value_at(t, v, 4.0)


def test_station_metrics():
    rows = [[0.0, 0.0, 0.0], [1.0, 0.1, 0.0005], [2.0, 0.5, 0.0015],
            [3.0, 0.9, -0.002]]
    m = files.station_metrics(rows)
    assert m["rupture"] == pytest.approx(1.5)
    assert m["peak"] == pytest.approx(0.002)
    assert m["slip"] == pytest.approx(0.9)
