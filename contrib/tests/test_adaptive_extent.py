"""Tests of contrib/adaptive-extent: its runs and its table."""


def test_runs_share_the_box_and_the_reference_comes_first(script):
    study = script("adaptive-extent")
    cases = study.cases()
    names = [name for name, _, _ in cases]
    assert names[0] == "fixed-300"
    assert len(set(names)) == len(names)
    runs = {name: sets for name, _, sets in cases}
    assert "Scene/Box/Number of cells=200, 112" in runs["fixed-300"]
    assert "Scene/Box/Number of cells=25, 14" in runs["front-3-extra-8000"]
    assert "Mesh refinement/Extra band=8000" in runs["front-3-extra-8000"]
    assert "Mesh refinement/Levels=3" in runs["front-3-extra-0"]
    assert "Mesh refinement/Criteria=process zone" in runs["fault-3"]
    assert "Discretization/Refinement region levels=3" in runs["band-3"]
    assert "Scene/Box/Number of cells=50, 28" in runs["front-2-extra-5000"]


def test_table_gives_errors_against_the_first_run(script):
    study = script("adaptive-extent")
    results = [
        ("ref", "reference", {"peak dofs": 100, "dof-steps": 1e4,
                              "slip": {"faultst075": 4.0,
                                       "faultst120": 2.0}}),
        ("a", "a |y| band", {"peak dofs": 10, "dof-steps": 5e3,
                             "slip": {"faultst075": 4.2,
                                      "faultst120": 1.9}})]
    lines = study.table(results).splitlines()
    assert lines[2] == "| reference | 100 | 1e+04 | +0.0 % | +0.0 % |"
    assert lines[3] == "| a \\|y\\| band | 10 | 5e+03 | +5.0 % | -5.0 % |"


def test_cause_cases_weld_the_barrier_and_add_the_wavefield(script):
    study = script("adaptive-extent")
    runs = {name: sets for name, _, sets in study.cases()}
    welded = runs["front-3-welded"]
    assert "Fault/Fault region=abs(x) < 15600 ? 1 : 0" in welded
    assert "Mesh refinement/Levels=3" in welded
    waves = runs["front-3-wavefield"]
    criteria = [s for s in waves if s.startswith("Mesh refinement/Criteria")]
    assert criteria == ["Mesh refinement/Criteria=rupture front, wavefield"]
    assert "Mesh refinement/Wavefield levels=3" in waves
    # Every plotted run is one of the cases.
    assert {name for name, _ in study.PLOTTED} <= set(runs)


def test_slip_history_reads_the_station(script, tmp_path):
    study = script("adaptive-extent")
    (tmp_path / "faultst075.dat").write_text(
        "# station\nt h-slip h-slip-rate h-shear-stress\n"
        "0 0 0 70\n0.5 0.25 1 60\n1 0.75 0.5 63\n")
    t, slip = study.slip_history(str(tmp_path))
    assert t == [0.0, 0.5, 1.0]
    assert slip == [0.0, 0.25, 0.75]
