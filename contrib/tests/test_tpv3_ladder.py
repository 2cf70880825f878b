"""Tests of contrib/tpv3-ladder's run settings: the layout's shift of the
mesh, per degree and for both methods, and the names of the cases."""

import pytest


def corner(sets, entry):
    values = [s.split("=", 1)[1] for s in sets if s.startswith(entry + "=")]
    assert len(values) == 1, (entry, sets)
    return [float(v) for v in values[0].split(",")]


def test_offset_shifts_explicit_and_implicit_runs(script):
    ladder = script("tpv3-ladder")
    for method in ("explicit", "implicit"):
        sets = ladder.case_sets(method, 100.0, "graded", 0.0, [], "offset", 1, "/o")
        # Degree 1: half a cell along strike (x) and dip (z), none normal to the fault.
        assert corner(sets, "Scene/Box/Grading/Core lower corner") == [-17950.0, -1500.0,
                                                                       -10450.0]
        assert corner(sets, "Scene/Box/Lower corner") == [-59950.0, -45000.0, -49950.0]
        assert "Scene/Box/Number of cells=360, 30, 210" in sets


def test_edges_layout_keeps_the_box(script):
    ladder = script("tpv3-ladder")
    sets = ladder.case_sets("explicit", 500.0, "graded", 0.0, [], "edges", 1, "/o")
    assert not any("corner" in s for s in sets)


def test_offset_per_degree_lands_on_area_borders(script):
    ladder = script("tpv3-ladder")
    # Odd degrees: the middle of the cell; even degrees: the end of the
    # first Gauss-Lobatto node's weight (1/6 of the cell at degree 2).
    assert ladder.offset_fraction(1) == 0.5
    assert ladder.offset_fraction(3) == 0.5
    assert ladder.offset_fraction(2) == pytest.approx(1.0 / 6.0)
    assert ladder.offset_fraction(4) == pytest.approx(0.05)
    sets = ladder.case_sets("explicit", 300.0, "graded", 0.0, [], "offset", 3, "/o")
    assert corner(sets, "Scene/Box/Grading/Core upper corner") == [18150.0, 1500.0, 10650.0]
    assert "Discretization/Polynomial degree=3" in sets
    assert "Scene/Box/Number of cells=120, 10, 70" in sets


def test_offset_refuses_cells_that_do_not_divide_the_square(script):
    ladder = script("tpv3-ladder")
    with pytest.raises(SystemExit):
        ladder.case_sets("explicit", 200.0, "graded", 0.0, [], "offset", 2, "/o")
    with pytest.raises(SystemExit):
        ladder.case_sets("explicit", 700.0, "graded", 0.0, [], "edges", 1, "/o")


def test_case_names(script):
    ladder = script("tpv3-ladder")
    assert ladder.case_name("explicit", 0.0, "", "offset", 3) == "explicit Q3 offset"
    assert ladder.case_name("explicit", 0.0, "zone-damped-0.3", "offset", 1) == \
        "explicit zone-damped-0.3 offset"
    assert ladder.case_name("implicit", 0.1, "", "edges", 1, 2.0) == "implicit damped dt x2"


def test_run_facts_come_from_the_summary(tmp_path):
    from rupturetools import runs
    (tmp_path / "summary.json").write_text(
        '{"status": "finished", "dofs": 1200, "steps": 31, "wall time": 2.5,'
        ' "peak memory, largest rank (B)": 3.5e9}')
    assert runs.facts(str(tmp_path)) == {"dofs": 1200, "steps": 31, "memory": 3.5}
    (tmp_path / "summary.json").write_text('{"status": "finished", "dofs": 1200}')
    with pytest.raises(SystemExit, match="steps"):
        runs.facts(str(tmp_path))
    with pytest.raises(SystemExit, match="no readable summary.json"):
        runs.facts(str(tmp_path / "missing"))


def test_adaptive_runs_start_coarse_and_refine_to_h(script):
    ladder = script("tpv3-ladder")
    assert ladder.adaptive_levels(750.0, 187.5) == 2
    assert ladder.adaptive_levels(750.0, 46.875) == 4
    for bad in (100.0, 750.0, 1500.0, 0.0, -187.5):
        with pytest.raises(SystemExit):
            ladder.adaptive_levels(750.0, bad)
    with pytest.raises(SystemExit):
        ladder.adaptive_levels(-750.0, 187.5)
    sets = ladder.case_sets("explicit", 93.75, "graded", 0.0, [], "offset", 1, "/o",
                            adaptive=750.0)
    # The coarse core cells, three levels down to 93.75 m at the front ...
    assert "Scene/Box/Number of cells=48, 4, 28" in sets
    assert "Mesh refinement/Levels=3" in sets
    assert "Mesh refinement/Criteria=rupture front" in sets
    # ... and the shift of the finest cells (half of 93.75 m at degree 1),
    # given after the fixed run's cell count, which it replaces.
    assert "Scene/Box/Grading/Core lower corner=-17953.125, -1500, -10453.125" in sets
    assert sets.index("Scene/Box/Number of cells=48, 4, 28") > sets.index(
        "Scene/Box/Number of cells=384, 32, 224")
    assert ladder.case_name("explicit", 0, "", "offset", 1, adaptive=750.0) == \
        "explicit adaptive from 750 m offset"
    # Implicit runs ignore it; a core it does not divide is refused.
    assert not any("Mesh refinement" in s for s in ladder.case_sets(
        "implicit", 93.75, "graded", 0.0, [], "offset", 1, "/o", adaptive=750.0))
    with pytest.raises(SystemExit):
        ladder.adaptive_sets(700.0, 175.0, "graded")


def test_peak_dofs_and_dof_steps_from_the_statistics(script, tmp_path):
    ladder = script("tpv3-ladder")
    (tmp_path / "statistics").write_text(
        "# 1: Time step number\n# 2: Time (s)\n# 3: Degrees of freedom\n"
        "0 0 100\n1 0.1 100\n2 0.2 300\n3 0.3 200\n")
    assert ladder.dof_measures(str(tmp_path), 200, 3) == (300, 600.0)
    # Without the column: the summary's DoFs times the steps.
    (tmp_path / "statistics").write_text("# 1: Time step number\n# 2: Time (s)\n0 0\n1 0.1\n")
    assert ladder.dof_measures(str(tmp_path), 200, 3) == (200, 600.0)


def test_mpirun_runs_as_root_and_oversubscribed(script, tmp_path, monkeypatch):
    """--np N starts mpirun with Open MPI's run-as-root variables (CI and
    containers run as root; before 2026-12-06 the ladder failed at once
    there) and the same command as the other scripts (runs.mpi_prefix)."""
    from rupturetools import runs
    assert runs.mpi_prefix(1) == []
    assert runs.mpi_prefix(2) == ["mpirun", "--oversubscribe", "-np", "2"]
    env = runs.mpi_env()
    assert env["OMPI_ALLOW_RUN_AS_ROOT"] == "1"
    assert env["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] == "1"

    ladder = script("tpv3-ladder")
    seen = {}

    class Failed:
        returncode = 1
        stderr = "stopped by the test"

    def fake_run(args, **kwargs):
        seen["args"], seen["env"] = args, kwargs.get("env")
        return Failed()

    monkeypatch.setattr(ladder.subprocess, "run", fake_run)
    row = ladder.run("/bin/rupture", "explicit", 1500.0, str(tmp_path), "graded", 0.0, [],
                     "", "edges", 2)
    assert row is None
    assert seen["args"][:5] == ["mpirun", "--oversubscribe", "-np", "2", "/bin/rupture"]
    assert seen["env"]["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] == "1"
