"""Tests of contrib/stability-study's reading of a run: everything comes
from the files the program writes (summary.json and statistics), nothing
from its screen output."""

import json

from rupturetools import stability_cases, stability_runs

STATISTICS = """# 1: Time step number
# 2: Time (s)
# 3: Time step size (s)
# 5: Kinetic energy (J)
# 6: Strain energy (J)
# 7: Work of loads and boundary reactions (J)
# 8: Energy dissipated by damping and absorbing boundaries (J)
# 9: Energy balance error (J): kinetic + strain + dissipated + fault work - work - initial energy
# 11: Newton iterations
# 12: Open fault nodes
# 13: Maximum slip (m)
# 14: Work done on the fault: penalty springs plus friction (J)
"""


def write_run(directory, rows, summary):
    directory.mkdir()
    names = ["step", "t", "dt", "k", "s", "w", "d", "e", "newton", "open", "slip", "fw"]
    lines = [" ".join(str(row[n]) for n in names) for row in rows]
    # The column numbers above are positions among the columns written.
    header = "\n".join("# %d: %s" % (i + 1, line.split(": ", 1)[1])
                       for i, line in enumerate(STATISTICS.strip().splitlines()))
    (directory / "statistics").write_text(header + "\n" + "\n".join(lines) + "\n")
    if summary is not None:
        (directory / "summary.json").write_text(json.dumps(summary))


def row(step, t, newton, e=0.0):
    return {"step": step, "t": t, "dt": 0.01, "k": 1.0, "s": 2.0, "w": 0.0, "d": 0.0,
            "e": e, "newton": newton, "open": 0, "slip": 0.1 * step, "fw": 0.0}


def test_analyse_reads_the_files(tmp_path):
    case = stability_cases.Case("time-step", "column", "implicit", "1")
    run = tmp_path / "run"
    write_run(run, [row(0, 0.0, 0), row(1, 0.01, 3), row(2, 0.02, 7, e=1e-9)],
              {"status": "finished", "steps": 2, "stable time step": None,
               "time step": 0.01, "step cuts": 2,
               "energy balance": {"error": 1e-9, "scale": 3.0, "tolerance": 1e-8,
                                  "within": True}})
    r = {"timeout": False, "rc": 0, "stdout": "", "stderr": "", "end": 0.02}
    stability_runs.analyse(case, r, str(run))
    assert r["cuts"] == 2
    assert r["dt"] == 0.01
    assert r["dt_stable"] is None
    assert r["own_verdict"] == "yes" and r["own_tolerance"] == 1e-8
    assert r["last_t"] == 0.02 and r["steps"] == 2
    assert r["max_newton"] == 7
    assert r["result"] == "ok" and not r["refused"]


def test_a_refused_input_has_no_summary(tmp_path):
    case = stability_cases.Case("time-step", "column", "explicit", "1")
    r = {"timeout": False, "rc": 1, "stdout": "", "end": 1.0,
         "stderr": "\nError: <Time integration/Time step> = -1 is not allowed.\n"}
    stability_runs.analyse(case, r, str(tmp_path / "never-opened"))
    assert r["refused"] and r["result"] == "failed"
    assert r["cuts"] == 0 and r["last_t"] is None


def test_balance_off_is_reported(tmp_path):
    case = stability_cases.Case("time-step", "column", "explicit", "1")
    run = tmp_path / "run"
    write_run(run, [row(0, 0.0, 0), row(1, 0.01, 0, e=0.5)],
              {"status": "finished", "steps": 1, "stable time step": 0.02,
               "time step": 0.01, "step cuts": 0,
               "energy balance": {"error": 0.5, "scale": 3.0, "tolerance": 1e-2,
                                  "within": False}})
    r = {"timeout": False, "rc": 0, "stdout": "", "stderr": "", "end": 0.01}
    stability_runs.analyse(case, r, str(run))
    assert r["dt_stable"] == 0.02
    assert r["result"] == "ran, balance off"


def test_anisotropic_friction_cases_keep_the_ellipse_norm():
    """The prestress of the anisotropic friction family is scaled so that
    its ellipse norm |A^-1 tau| (strike component, dip component / r) is
    the isotropic 70 MPa for every ratio r, in both schemes."""
    import re
    cases = [c for c in stability_cases.build_cases()
             if c.family == "anisotropic friction" and c.base == "patch3d"]
    ratios = set()
    for c in cases:
        sets = dict(s.split("=", 1) for s in c.sets)
        if "Fault/Initial traction" not in sets:
            continue
        r = float(sets["Fault/Anisotropic friction/Strength ratio"])
        factors = [float(f) for f in re.findall(r"\* ([0-9.e+-]+)", sets["Fault/Initial traction"])]
        strike, dip = factors
        assert abs((strike ** 2 + (dip / r) ** 2) ** 0.5 - 1) < 1e-8
        ratios.add((r, c.scheme))
    assert {r for r, _ in ratios} == {0.05, 0.1, 0.5, 1, 2, 10, 20}
    assert {s for _, s in ratios} == {"implicit", "explicit"}
    assert "patch3d" in stability_cases.BASES
