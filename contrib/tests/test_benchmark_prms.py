"""Tests of contrib/benchmark-prms: it reads a run's settings back from the
parameters.prm the run wrote, and refuses a benchmark it does not know."""

import sys

import pytest


def test_settings_read_back(script, tmp_path):
    tool = script("benchmark-prms")
    (tmp_path / "parameters.prm").write_text(
        "subsection Damping\n  set Fault zone damping = 0.3\nend\n"
        "subsection Discretization\n  set Polynomial degree         = 2 # Gauss-Lobatto\nend\n"
        "subsection Scene\n  subsection Box\n    set Number of cells  = 48, 4, 28\n"
        "  end\nend\n"
        "subsection Time integration\n  set Courant fraction = 0.5\n  set End time = 12\nend\n")
    assert tool.settings(str(tmp_path)) == {"damping": "0.3", "degree": "2",
                                            "cells": "48, 4, 28", "courant": "0.5",
                                            "end time": "12"}


def test_unknown_benchmark_is_refused(script, monkeypatch):
    tool = script("benchmark-prms")
    monkeypatch.setattr(sys, "argv", ["benchmark-prms", "--only", "tpv999"])
    with pytest.raises(SystemExit) as e:
        tool.main()
    assert "tpv999" in str(e.value)
