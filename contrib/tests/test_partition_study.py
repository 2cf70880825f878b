"""Tests of contrib/partition-study's cost model and load balance."""

import pytest


def test_weight_from_two_runs_on_one_mesh(script):
    study = script("partition-study")
    # 1000 cells at 1 us per step each, a fault cell 3 us more: 100 fault
    # cells take 1.3 ms per step, 40 take 1.12 ms.
    w, ordinary, extra = study.fault_cell_weight(1.3e-3, 100, 1.12e-3, 40,
                                                 1000)
    assert extra == pytest.approx(3e-6)
    assert ordinary == pytest.approx(1e-6)
    assert w == pytest.approx(4.0)
    with pytest.raises(ValueError):
        study.fault_cell_weight(1e-3, 10, 1e-3, 10, 100)


def test_load_balance_counts_fault_cells_by_weight(script):
    study = script("partition-study")
    assert study.load_balance([100, 100], [0, 0], 5) == pytest.approx(1.0)
    # 100 + 4 * 50 = 300 against 100: the mean is 200.
    assert study.load_balance([100, 100], [50, 0], 5) == pytest.approx(1.5)
    assert study.load_balance([60, 140], [45, 5], 3) == pytest.approx(1.0)
    assert study.largest_over_mean([1, 3]) == pytest.approx(1.5)


def test_step_time_leaves_out_the_loops_adaptations(script, tmp_path):
    study = script("partition-study")
    s = {"time loop wall time": 12.0, "steps": 100,
         "partition": {"cells per rank": [3, 4],
                       "fault cells per rank": [1, 2]}}
    assert study.step_time(s) == pytest.approx(0.12)
    assert study.step_time(s, 2.0) == pytest.approx(0.1)
    assert study.cells(s) == 7 and study.fault_cells(s) == 3
    # The cumulative column: 0.5 s before the first step, 2.5 s at the end.
    (tmp_path / "statistics").write_text(
        "# 1: Time step number\n# 2: Mesh adaptation wall time (s)\n"
        "0 0.5\n1 0.5\n2 1.5\n3 2.5\n")
    assert study.loop_adaptations(str(tmp_path)) == pytest.approx(2.0)
    assert study.loop_adaptations(str(tmp_path / "none")) == 0.
