"""Tests of contrib/seas-bp1-fd: the measures of a run (events merged, the
dynamic phases of summary.json, quasi-dynamic runs without them) and the
table."""

from test_seas_bp1 import CSV


def write_run(path, dynamic=True):
    path.mkdir()
    (path / "events.csv").write_text(CSV)
    extra = '"dynamic phases": 3, "dynamic steps": 4000, ' if dynamic else ""
    (path / "summary.json").write_text(
        '{"status": "finished", "elements": 200, "steps": 5000, ' + extra +
        '"rejected steps": 1, "smallest time step": 0.001, '
        '"largest time step": 1e7, "wall time": 5}')


def test_measure_reads_the_dynamic_phases(script, tmp_path):
    fd = script("seas-bp1-fd")
    write_run(tmp_path / "fd")
    write_run(tmp_path / "qd", dynamic=False)
    m = fd.measure(str(tmp_path / "fd"))
    assert m["events"] == 2 and m["catalogue rows"] == 3
    assert m["dynamic phases"] == 3 and m["dynamic steps"] == 4000
    assert m["first event (years)"] == 198.02
    # Two events: no recurrence, no means of the events after the first two.
    assert m["recurrence (years)"] is None and m["peak slip rate"] is None
    q = fd.measure(str(tmp_path / "qd"))
    assert q["dynamic phases"] == 0 and q["dynamic steps"] == 0


def test_write_makes_a_row_per_run(script, tmp_path):
    fd = script("seas-bp1-fd")
    write_run(tmp_path / "run")
    rows = []
    for mode in fd.EVENTS:
        r = fd.measure(str(tmp_path / "run"))
        r.update(mode=mode, h=100)
        rows.append(r)
    md = fd.write(rows, 1500, str(tmp_path / "doc"))
    text = open(md).read()
    assert "| fully dynamic | 100 | 2 (3) | 198.02 | - |" in text
    assert "| quasi-dynamic | 100 |" in text
    assert (tmp_path / "doc" / "seas-bp1-fd.json").exists()


def test_settings_choose_the_events_and_the_spacing(script):
    fd = script("seas-bp1-fd")
    s = fd.settings("quasi-dynamic", 50, 100)
    assert "Boundary integral/Events=quasi-dynamic" in s
    assert "Boundary integral/Element size=50" in s
    assert fd.directory("/w", "fully dynamic", 50, 100) == "/w/fd-h50-y100"
