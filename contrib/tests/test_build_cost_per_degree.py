"""Tests of contrib/build-cost-per-degree: the copies it compiles keep
exactly the degrees asked for, and it reads the compiler's command from
CMake's flags.make."""

import os

import pytest

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

SWITCH = """  switch (degree)
    {
      case 1:
        run<1>();
        break;
      case 2:
        run<2>();
        break;
      case 3:
        run<3>();
        break;
      default:
        run<-1>();
    }
"""


def test_keep_degrees_removes_the_higher_branches(script):
    tool = script("build-cost-per-degree")
    one = tool.keep_degrees(SWITCH, 1)
    assert "run<1>" in one and "run<-1>" in one
    assert "run<2>" not in one and "run<3>" not in one
    assert tool.keep_degrees(SWITCH, 3) == SWITCH
    assert "case" not in tool.keep_degrees(SWITCH, 0)
    with pytest.raises(SystemExit):
        tool.keep_degrees(SWITCH, 4)


def test_the_operator_source_has_every_degree(script):
    tool = script("build-cost-per-degree")
    with open(os.path.join(TOP, tool.SOURCE)) as f:
        text = f.read()
    assert tool.keep_degrees(text, 4) == text
    one = tool.keep_degrees(text, 1)
    for k in (2, 3, 4):
        for name in ("local_apply", "local_diagonals"):
            assert "%s<%d>" % (name, k) not in one
    assert "local_apply<1>" in one and "local_apply<-1>" in one


def test_compile_command_from_flags_make(script, tmp_path):
    tool = script("build-cost-per-degree")
    directory = tmp_path / "CMakeFiles" / "rupture-lib.dir"
    directory.mkdir(parents=True)
    (directory / "flags.make").write_text(
        "# compile CXX with /usr/bin/c++\n"
        "CXX_DEFINES = -DNDEBUG\n\n"
        "CXX_INCLUDES = -I/x/include\n\n"
        "CXX_FLAGS = -O2 -std=c++17\n\n"
        "# Custom options: CMakeFiles/rupture-lib.dir/source/operators/"
        "elastic_operator.cc.o_OPTIONS = -march=native\n\n"
        "# Custom defines: CMakeFiles/rupture-lib.dir/source/operators/"
        "elastic_operator.cc.o_DEFINES = RUPTURE_SIMD\n")
    assert tool.compile_command(str(tmp_path)) == [
        "/usr/bin/c++", "-DNDEBUG", "-I/x/include", "-O2", "-std=c++17",
        "-march=native", "-DRUPTURE_SIMD"]
    with pytest.raises(SystemExit):
        tool.compile_command(str(tmp_path / "missing"))


def test_factory_limit_removed(script):
    tool = script("build-cost-per-degree")
    text = "#if X\n#  define FE_EVAL_FACTORY_DEGREE_MAX 4\n#endif\n"
    assert tool.without_factory_limit(text) == "#if X\n#endif\n"
    assert tool.without_factory_limit("#if X\n#endif\n") is None
    with open(os.path.join(TOP, tool.SOURCE)) as f:
        assert tool.without_factory_limit(f.read()) is not None
