"""Tests of contrib/benchmark-long-run: its parameter file and its
command line."""
import os


def test_parameters(script):
    tool = script("benchmark-long-run")
    text = tool.parameters(1000, "/tmp/out")
    assert "include " in text
    included = text.split("\n")[0].split(" ", 1)[1]
    assert os.path.isfile(included)
    # The end time is the steps times the step.
    assert "set End time = 6.25\n" in text
    assert "set Output directory = /tmp/out" in text
    assert "set Scheme = explicit central difference" in text


def test_needs_a_binary(script, capsys):
    tool = script("benchmark-long-run")
    try:
        tool.main([])
        raised = False
    except SystemExit as e:
        raised = e.code != 0
    assert raised
