"""Tests of contrib/degree-study-3d: its cases put every SCEC station of
prm/tpv101 on a node, it refuses cases it cannot run, and it measures
errors against a reference run on station files made here."""

import math

import pytest

from stations import write_station


def test_default_cases_put_stations_on_nodes(script):
    study = script("degree-study-3d")
    core_lower = (-18000.0, -1500.0, -10500.0)
    stations_x = (0.0, 9000.0, -9000.0, 12000.0, -12000.0)
    stations_z = (0.0, 4500.0, -4500.0)
    for p, h in study.parse_cases("1:250,2:500,3:750,4:1000"):
        assert h / p == 250
        nodes = [0.0, 1.0] if p % 2 else [0.0, 0.5, 1.0]
        for lower, coords in ((core_lower[0], stations_x), (core_lower[2], stations_z)):
            for c in coords:
                xi = (c - lower) / h - math.floor((c - lower) / h)
                assert min(abs(xi - n) for n in nodes) < 1e-9, (p, h, c)
        sets = study.case_sets(p, h, 0.3)
        assert "Discretization/Polynomial degree=%d" % p in sets
        assert "Damping/Fault zone damping=0.3" in sets


def test_bad_cases_are_refused(script):
    study = script("degree-study-3d")
    for text in ("2-500", "5:500", "1:400"):
        with pytest.raises(SystemExit):
            study.parse_cases(text)


def test_errors_against_a_reference_run(script, tmp_path):
    study = script("degree-study-3d")
    ref, run = tmp_path / "ref", tmp_path / "run"
    ref.mkdir()
    run.mkdir()
    write_station(ref, "faultst000dp075", 0.5, 2.0, 4.0)
    write_station(ref, "faultst090dp075", 4.0, 5.0, 2.0)
    write_station(run, "faultst000dp075", 0.5, 2.0, 4.0)
    write_station(run, "faultst090dp075", 4.2, 4.0, 2.2)
    names = ["faultst000dp075", "faultst090dp075"]
    reference = study.station_values(str(ref), names)
    values = study.station_values(str(run), names)
    e = study.bench2d.errors(values, reference, names)
    assert abs(e["rupture"] - 0.2) < 0.011
    assert abs(e["peak"] - 0.2) < 1e-12
    assert abs(e["slip"] - 0.1) < 1e-6
    row = {"degree": 2, "h": 500.0, "fraction": 0.3, "dofs": 10, "steps": 5,
           "wall": 12.0, "stations": values, "errors": e}
    text = study.markdown([row], "test")
    assert "| 2 | 500 | 250 | 1.2 per cell | 0.5 | 0.3 | 10 | 5 | 12 | 0.200 | 20.0 % | 10.00 % |" in text


def test_only_finished_with_nothing_finished_says_so(script, tmp_path, monkeypatch):
    study = script("degree-study-3d")
    monkeypatch.setattr(study.sys, "argv", ["degree-study-3d", "--only-finished",
                                            "--work-dir", str(tmp_path),
                                            "--output-dir", str(tmp_path)])
    with pytest.raises(SystemExit) as e:
        study.main()
    assert "none of the cases has finished" in str(e.value)


def test_save_reference_round_trip(script, tmp_path, monkeypatch):
    study = script("degree-study-3d")
    ref = tmp_path / "ref"
    ref.mkdir()
    write_station(ref, "faultst000dp075", 0.5, 2.0, 4.0)
    write_station(ref, "faultst090dp075", 4.0, 5.0, 2.0)
    saved = tmp_path / "reference.json"
    monkeypatch.setattr(study.sys, "argv", [
        "degree-study-3d", "--reference-run", str(ref), "--save-reference", str(saved),
        "--reference-label", "a test run", "--output-dir", str(tmp_path)])
    study.main()
    import json
    data = json.loads(saved.read_text())
    assert data["label"] == "a test run"
    assert "no summary.json" in data["note"]
    assert data["stations"] == study.station_values(
        str(ref), ["faultst000dp075", "faultst090dp075"])
    # Without a run to keep it refuses.
    monkeypatch.setattr(study.sys, "argv", [
        "degree-study-3d", "--save-reference", str(saved), "--only-finished"])
    with pytest.raises(SystemExit) as e:
        study.main()
    assert "needs --reference-run" in str(e.value)


def test_from_json_measures_stored_runs_against_a_new_reference(script, tmp_path,
                                                                monkeypatch):
    import json
    study = script("degree-study-3d")
    stations = {"faultst000dp075": {"rupture": 0.5, "peak": 2.0, "slip": 4.0},
                "faultst090dp075": {"rupture": 4.2, "peak": 4.0, "slip": 2.2}}
    stored = tmp_path / "stored.json"
    stored.write_text(json.dumps({"reference": "old", "runs": [
        {"degree": 2, "h": 500.0, "fraction": 0.0, "ranks": 2, "dofs": 10, "steps": 5,
         "wall": 12.0, "stations": stations, "errors": {}}]}))
    reference = tmp_path / "reference.json"
    reference.write_text(json.dumps({"label": "new", "note": "", "stations": {
        "faultst000dp075": {"rupture": 0.5, "peak": 2.0, "slip": 4.0},
        "faultst090dp075": {"rupture": 4.0, "peak": 5.0, "slip": 2.0}}}))
    out = tmp_path / "out"
    monkeypatch.setattr(study.sys, "argv", [
        "degree-study-3d", "--from-json", str(stored), "--reference-json",
        str(reference), "--output-dir", str(out)])
    study.main()
    text = (out / "tpv101-3d-degrees.md").read_text()
    assert "Reference: new." in text
    assert "| 2 | 500 | 250 | 1.2 per cell | 0.5 | 0 | 10 | 5 | 12 | 0.200 | 20.0 % | 10.00 % |" in text


def test_from_json_refuses_a_file_without_runs(script, tmp_path, monkeypatch):
    study = script("degree-study-3d")
    reference = tmp_path / "reference.json"
    reference.write_text('{"label": "new", "note": "", "stations": {}}')
    for content in ("not json", '{"reference": "x"}', '{"runs": [{"degree": 1}]}'):
        stored = tmp_path / "stored.json"
        stored.write_text(content)
        monkeypatch.setattr(study.sys, "argv", [
            "degree-study-3d", "--from-json", str(stored), "--reference-json",
            str(reference), "--output-dir", str(tmp_path / "out")])
        with pytest.raises(SystemExit) as e:
            study.main()
        assert "--from-json" in str(e.value)
    assert not (tmp_path / "out").exists()


def test_courant_fraction_names_the_run_and_is_set(script):
    study = script("degree-study-3d")
    assert study.case_directory("/w", 3, 750.0, 0.0) == "/w/q3-750-eta0"
    assert study.case_directory("/w", 3, 750.0, 0.0, 0.25) == "/w/q3-750-eta0-c0.25"
    assert "Time integration/Courant fraction=0.25" in study.case_sets(3, 750.0, 0.0, 0.25)


def test_courant_list_is_checked(script, tmp_path, monkeypatch):
    study = script("degree-study-3d")
    for bad in ("fast", "0", "1.5"):
        monkeypatch.setattr(study.sys, "argv", ["degree-study-3d", "--courant", bad,
                                                "--only-finished", "--work-dir",
                                                str(tmp_path)])
        with pytest.raises(SystemExit) as e:
            study.main()
        assert "--courant" in str(e.value)


def test_merge_json_keeps_earlier_runs_and_replaces_the_same_case(script, tmp_path,
                                                                   monkeypatch):
    import json
    study = script("degree-study-3d")
    stations = {"faultst000dp075": {"rupture": 0.5, "peak": 2.0, "slip": 4.0}}
    stored = tmp_path / "stored.json"
    stored.write_text(json.dumps({"reference": "old", "runs": [
        {"degree": 2, "h": 500.0, "fraction": 0.0, "ranks": 2, "dofs": 10, "steps": 5,
         "wall": 12.0, "stations": stations, "errors": {}},
        {"degree": 3, "h": 750.0, "fraction": 0.0, "ranks": 2, "dofs": 20, "steps": 6,
         "wall": 30.0, "stations": stations, "errors": {}}]}))
    newer = tmp_path / "newer.json"
    newer.write_text(json.dumps({"reference": "old", "runs": [
        {"degree": 2, "h": 500.0, "fraction": 0.0, "courant": 0.25, "ranks": 2,
         "dofs": 10, "steps": 10, "wall": 24.0, "stations": stations, "errors": {}}]}))
    reference = tmp_path / "reference.json"
    reference.write_text(json.dumps({"label": "ref", "note": "", "stations": stations}))
    out = tmp_path / "out"
    monkeypatch.setattr(study.sys, "argv", [
        "degree-study-3d", "--from-json", str(newer), "--merge-json", str(stored),
        "--reference-json", str(reference), "--output-dir", str(out)])
    study.main()
    rows = json.loads((out / "tpv101-3d-degrees.json").read_text())["runs"]
    assert [(r["degree"], study.courant_of(r)) for r in rows] == [(2, 0.5), (2, 0.25),
                                                                  (3, 0.5)]


def test_growth_per_node_grades_by_degree(script):
    study = script("degree-study-3d")
    assert study.growth_per_cell(1, 1.2) == 1.2
    assert abs(study.growth_per_cell(3, 1.2) - 1.728) < 1e-12
    assert study.growth_per_cell(4, 1.2) == 2.0
    sets = study.case_sets(3, 750.0, 0.0, 0.5, per_node=1.2)
    assert "Scene/Box/Grading/Growth factor=1.728" in sets
    assert not any("Growth" in s for s in study.case_sets(3, 750.0, 0.0))
    assert study.case_directory("/w", 3, 750.0, 0.0, 0.25, 1.2) == "/w/q3-750-eta0-c0.25-g1.2"
    assert study.grading_of({"growth per node": 1.2}) == "1.2 per node"
    assert study.grading_of({}) == "1.2 per cell"


def test_core_keeps_a_face_on_the_fault(script):
    study = script("degree-study-3d")
    # 1000 m cells: 3 across the 3 km core would put the fault in a cell's
    # middle; the core widens to 4 cells over |y| < 2 km.
    sets = study.case_sets(4, 1000.0, 0.0)
    assert "Scene/Box/Number of cells=36, 4, 21" in sets
    assert "Scene/Box/Grading/Core lower corner=-18000, -2000, -10500" in sets
    assert "Scene/Box/Grading/Core upper corner=18000, 2000, 10500" in sets
    # An even count keeps the prm's core.
    sets = study.case_sets(3, 750.0, 0.0)
    assert "Scene/Box/Number of cells=48, 4, 28" in sets
    assert not any("Core" in s for s in sets)


def test_half_space_core_for_tpv102(script, tmp_path, monkeypatch):
    study = script("degree-study-3d")
    prm, core = study.BENCHMARKS["tpv102"]
    assert prm.endswith("tpv102.prm")
    # The core reaches the free surface: 18 km deep, 250 m divides it.
    assert study.parse_cases("1:250,3:750", core) == [(1, 250.0), (3, 750.0)]
    sets = study.case_sets(3, 750.0, 0.0, core=core)
    assert "Scene/Box/Number of cells=48, 4, 24" in sets
    # Widened normal to the fault only; the top stays at the surface.
    sets = study.case_sets(4, 1000.0, 0.0, core=core)
    assert "Scene/Box/Grading/Core upper corner=18000, 2000, 7500" in sets
    assert "Scene/Box/Grading/Core lower corner=-18000, -2000, -10500" in sets
    # 1400 m divides neither core: refused with the core's size.
    with pytest.raises(SystemExit) as e:
        study.parse_cases("1:1400", core)
    assert "36 x 3 x 18 km" in str(e.value)
    # No stored reference for tpv102: the script says what to give.
    monkeypatch.setattr(study.sys, "argv", ["degree-study-3d", "--benchmark", "tpv102",
                                            "--only-finished", "--work-dir", str(tmp_path)])
    with pytest.raises(SystemExit) as e:
        study.main()
    assert "--reference-run" in str(e.value)
