"""Tests of contrib/seas-bp3: what it reads of a finished run (the events,
the station's normal stress, the cost), the table it writes, and its
refusal of senses and dips it has no set-up for."""

import subprocess
import sys

import pytest

CSV = """# Earthquakes of the run
event,start (s),start (years),end (s),duration (s),hypocentre x (m),\
hypocentre y (m),peak slip rate (m/s),moment (N/m),ruptured length (m),\
mean slip (m),largest slip (m),complete
1,6.2e9,100.0,6.2e9,50,5000,-8660,2.0,1e11,17800,2.4,3.0,1
2,8.6e9,180.0,8.6e9,50,5000,-8660,3.0,1e11,17800,2.1,4.0,1
3,1.1e10,260.0,1.1e10,50,5000,-8660,4.0,1e11,17800,2.1,5.0,1
4,1.4e10,340.0,1.4e10,50,5000,-8660,6.0,1e11,17800,2.1,7.0,1
"""

STATION = """# This is the file header:
# location = on fault, 10 km down-dip
t slip slip_rate shear_stress normal_stress state
# Here is the time-series data.
0 0 -9 29.2 50.0 8.9
1e9 0.5 -9.5 31.0 48.5 9.1
2e9 2.0 -1 25.0 51.25 2.0
"""


def fake_run(path):
    path.mkdir(parents=True, exist_ok=True)
    (path / "events.csv").write_text(CSV)
    (path / "fltst_dp100.dat").write_text(STATION)
    (path / "summary.json").write_text(
        '{"status": "finished", "elements": 400, "steps": 10, '
        '"rejected steps": 1, "smallest time step": 0.001, '
        '"largest time step": 1e7, "wall time": 50, '
        '"stiffness wall time": 20}')


def test_measures_a_run(script, tmp_path):
    bp3 = script("seas-bp3")
    fake_run(tmp_path)
    m = bp3.measure(str(tmp_path))
    assert m["events"] == 4
    assert m["recurrence (years)"] == pytest.approx(80.0)
    # Means over the events after the first two.
    assert m["peak slip rate"] == pytest.approx(5.0)
    assert m["largest slip"] == pytest.approx(6.0)
    assert m["normal stress range"] == [48.5, 51.25]
    assert m["stiffness wall time"] == 20


def test_writes_the_table(script, tmp_path):
    bp3 = script("seas-bp3")
    case = {"dip": 60, "sense": "thrust", "h": 100}
    run = tmp_path / "runs"
    fake_run(run)
    row = bp3.measure(str(run))
    row.update(case=case)
    md = bp3.write([row], 1500, str(tmp_path / "doc"))
    text = open(md).read()
    assert "| 60 | thrust | 100 | 400 | 4 (4) | 100.00 | 80.000 | 5.000 | " \
        "6.000 | 48.50 to 51.25 | 10 | 1 | 50 | 20 |" in text


def test_a_run_without_summary_is_named(script, tmp_path):
    bp3 = script("seas-bp3")
    with pytest.raises(SystemExit) as e:
        bp3.measure(str(tmp_path))
    assert str(tmp_path) in str(e.value)


@pytest.mark.parametrize("arguments, message", [
    (["--senses", "oblique"], "neither 'thrust' nor 'normal'"),
    (["--dips", "45"], "60 and 30 are shipped")])
def test_refuses_what_it_has_no_set_up_for(arguments, message, tmp_path):
    import os
    path = os.path.join(os.path.dirname(__file__), "..", "seas-bp3")
    p = subprocess.run([sys.executable, path, "--rupture", "/bin/true",
                        "--work-dir", str(tmp_path)] + arguments,
                       capture_output=True, text=True)
    assert p.returncode != 0
    assert message in p.stderr


def test_reuse_only_without_runs_says_so(tmp_path):
    import os
    path = os.path.join(os.path.dirname(__file__), "..", "seas-bp3")
    p = subprocess.run([sys.executable, path, "--reuse-only",
                        "--work-dir", str(tmp_path)],
                       capture_output=True, text=True)
    assert p.returncode != 0
    assert "no finished run" in p.stderr


def test_plots_each_case_at_its_finest_spacing(script, tmp_path):
    bp3 = script("seas-bp3")
    results = []
    for h in (200, 100):
        case = {"dip": 30, "sense": "normal", "h": h}
        fake_run(tmp_path / ("dip30-normal-h%g-y1500" % h))
        results.append({"case": case})
    png = tmp_path / "bp3.png"
    bp3.plot(results, str(tmp_path), 1500, str(png))
    assert png.stat().st_size > 1000
