"""Tests of contrib/adaptive-study: the runs it sets, its reading of a
run's cost and its comparison of stations."""

import json


def test_runs_share_the_finest_size(script):
    study = script("adaptive-study")
    runs = dict(study.cases_of(300.0))
    assert "Scene/Box/Number of cells=200,104" in runs["h"]
    assert "Scene/Box/Number of cells=100,52" in runs["2h"]
    # Cells four times as large, refined two levels where the rupture is;
    # every run in the same box.
    assert "Scene/Box/Number of cells=50,26" in runs["adaptive"]
    assert all("Scene/Box/Lower corner=-30000, -15600" in sets
               for sets in runs.values())
    assert "Mesh refinement/Levels=2" in runs["adaptive"]
    band = runs["band"]
    assert "Discretization/Refinement region levels=2" in band
    assert any(s.startswith("Discretization/Refinement region=abs(y) < 750")
               for s in band)


def test_3d_cases_widen_the_core_and_run_on_two_ranks(script):
    study = script("adaptive-study")
    assert study.dimension("tpv101") == 3 and study.dimension("tpv3") == 3
    assert study.dimension("tpv101-2d") == 2
    runs = dict(study.cases_of(750.0, "tpv101"))
    assert "Scene/Box/Number of cells=48,8,28" in runs["h"]
    assert "Scene/Box/Number of cells=24,4,14" in runs["2h"]
    assert "Scene/Box/Number of cells=12,2,7" in runs["adaptive"]
    assert all("Scene/Box/Grading/Core lower corner=-18000, -3000, -10500"
               in sets for sets in runs.values())
    assert "Mesh refinement/Interval=40" in runs["adaptive"]
    assert any(s.startswith("Discretization/Refinement region=abs(y) < "
                            "1875 && abs(x) < 18000 && abs(z) < 10500")
               for s in runs["band"])


def _run(directory, dofs_column, summary_dofs):
    directory.mkdir()
    names = ["Time step number", "Time (s)"]
    rows = [[0, 0], [1, 0.1], [2, 0.2]]
    if dofs_column:
        names.append("Degrees of freedom")
        for row, d in zip(rows, dofs_column):
            row.append(d)
    header = "".join("# %d: %s\n" % (i + 1, n) for i, n in enumerate(names))
    (directory / "statistics").write_text(
        header + "".join(" ".join(str(v) for v in r) + "\n" for r in rows))
    (directory / "summary.json").write_text(json.dumps(
        {"status": "finished", "dofs": summary_dofs, "wall time": 3.5}))
    (directory / "log.txt").write_text(
        "   Mesh adapted after step 1: ...\n   Mesh adapted after step 2:\n"
        if dofs_column else "")


def test_cost_of_fixed_and_adaptive_runs(tmp_path, script):
    study = script("adaptive-study")
    _run(tmp_path / "fixed", None, 100)
    fixed = study.run_measures(str(tmp_path / "fixed"))
    assert fixed["peak dofs"] == 100 and fixed["dof-steps"] == 200
    assert fixed["steps"] == 2 and fixed["adaptations"] == 0
    _run(tmp_path / "adaptive", [10, 30, 20], 20)
    adaptive = study.run_measures(str(tmp_path / "adaptive"))
    # The initial row's DoFs are no step's.
    assert adaptive["peak dofs"] == 30 and adaptive["dof-steps"] == 50
    assert adaptive["adaptations"] == 2 and adaptive["wall time"] == 3.5


def test_stations_compared_with_the_finest_fixed_run(script):
    study = script("adaptive-study")
    def m(rupture, slip, peak):
        return {"rupture": rupture, "slip": slip, "peak": peak}
    runs = {"h": {"stations": {"a": m(1.0, 2.0, 4.0), "b": m(None, 0, 0)}},
            "2h": {"stations": {"a": m(1.1, 2.2, 3.0)}},
            "adaptive": {"stations": {"a": m(0.98, 1.9, 4.4)}},
            "band": {"stations": {}}}
    rows = study.compare(runs)
    # A station h never ruptures is left out; a run without it gives None.
    assert [r["station"] for r in rows] == ["a"]
    assert rows[0]["band"] is None
    d = rows[0]["adaptive"]
    assert abs(d["rupture"] + 0.02) < 1e-12
    assert abs(d["slip"] + 0.05) < 1e-12 and abs(d["peak"] - 0.1) < 1e-12
