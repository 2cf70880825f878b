"""Tests of contrib/anisotropy-convergence: the observed orders, the
Markdown table and the plot, from made-up errors; every case names an
input that exists."""

import math
import os


def test_orders_of_halved_errors(script):
    study = script("anisotropy-convergence")
    o = study.orders([1.0, 0.25, 0.0625, 0.0078125])
    assert [round(x, 12) for x in o] == [2.0, 2.0, 3.0]
    assert math.isnan(study.orders([1.0, 0.0])[0])


def test_cases_name_existing_inputs(script):
    study = script("anisotropy-convergence")
    for _, prm, scheme, degree, meshes in study.CASES:
        assert os.path.isfile(os.path.join(study.INPUTS, prm))
        assert degree in (1, 2) and meshes >= 2
        assert scheme in ("implicit Newmark", "explicit central difference",
                          "quasi-static")


def test_table_and_plot(script, tmp_path):
    study = script("anisotropy-convergence")
    results = [dict(case="2-D, explicit", degree=1, errors=[0.1, 0.025],
                    wall=[0.5, 1.0]),
               dict(case="3-D, quasi-static", degree=2,
                    errors=[0.01, 0.00125], wall=[2.0, 9.0])]
    text = study.markdown(results, "2026-12-07")
    assert "| 2-D, explicit | 1 | 1/4, 1/8 | 1.00e-01, 2.50e-02 | 2.00 | " \
           "0.5, 1.0 |" in text
    assert "| 3-D, quasi-static | 2 | 1/4, 1/8 | 1.00e-02, 1.25e-03 | " \
           "3.00 |" in text
    png = tmp_path / "plot.png"
    study.plot(results, str(png))
    assert png.stat().st_size > 1000
