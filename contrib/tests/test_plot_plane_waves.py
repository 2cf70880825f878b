"""Tests of contrib/plot-plane-waves: it reads every wave of the plane-wave
test's output and refuses a file without them."""

import os

import pytest


def test_reads_the_test_output(script, tmp_path):
    plot = script("plot-plane-waves")
    path = tmp_path / "output"
    path.write_text(
        "  TI, axis (1,2,3) (1,0,0) qP : Christoffel 4803.3 m/s, measured "
        "4805.7 m/s, 0.05 %\n"
        "  TI, axis (1,2,3) (0,1,-1) qS2: Christoffel 2231.8 m/s, measured "
        "2231.9 m/s, -0.01 %\n"
        "3-D TI, axis (1,2,3): every speed within 0.5 %: yes\n"
        "  2-D orthotropic (1,1) qS : Christoffel 2840.2 m/s, measured "
        "2840.5 m/s, 0.01 %\n")
    waves = plot.read_waves(str(path))
    assert waves == [
        ("TI, axis (1,2,3)", "(1,0,0)", "qP", 4803.3, 4805.7, 0.05),
        ("TI, axis (1,2,3)", "(0,1,-1)", "qS2", 2231.8, 2231.9, -0.01),
        ("2-D orthotropic", "(1,1)", "qS", 2840.2, 2840.5, 0.01)]
    picture = tmp_path / "waves.png"
    plot.plot(str(picture), waves)
    assert picture.stat().st_size > 0


def test_the_shipped_output_has_46_waves(script):
    plot = script("plot-plane-waves")
    path = os.path.join(plot.TOP, "tests", "elasticity",
                        "anisotropic_plane_waves.output")
    waves = plot.read_waves(path)
    assert len(waves) == 46
    assert max(abs(w[5]) for w in waves) < 0.5


def test_refuses_a_file_without_waves(script, tmp_path):
    plot = script("plot-plane-waves")
    path = tmp_path / "output"
    path.write_text("nothing here\n")
    with pytest.raises(SystemExit):
        plot.read_waves(str(path))


def test_refuses_a_missing_file(script, tmp_path):
    plot = script("plot-plane-waves")
    with pytest.raises(SystemExit):
        plot.read_waves(str(tmp_path / "nothing"))
