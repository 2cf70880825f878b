"""Tests of contrib/room-graph: the rooms' dependencies read from the
include lines, their layers, and the cycles it reports."""
import os


def write(top, path, text):
    full = os.path.join(top, path)
    os.makedirs(os.path.dirname(full), exist_ok=True)
    with open(full, "w") as f:
        f.write(text)


def tree(tmp_path, cycle=False):
    top = str(tmp_path)
    write(top, "include/rupture/base/a.h", "#include <deal.II/base/point.h>\n")
    write(top, "include/rupture/mesh/m.h",
          "#include <rupture/base/a.h>\n#include <rupture/mesh/n.h>\n")
    write(top, "source/mesh/m.cc",
          '#include <rupture/mesh/m.h>\n#include "rupture/base/a.h"\n')
    write(top, "include/rupture/top/t.h",
          "#include <rupture/mesh/m.h>\n  #  include <rupture/base/a.h>\n")
    write(top, "source/top/t.cc", "// #include <rupture/ghost/x.h> is text\n"
          "#include <rupture/top/t.h>\n")
    if cycle:
        write(top, "source/base/a.cc", "#include <rupture/top/t.h>\n")
    return top


def test_edges_and_layers(script, tmp_path):
    tool = script("room-graph")
    rooms, edges = tool.rooms_and_edges(tree(tmp_path))
    assert rooms == ["base", "mesh", "top"]
    # Own headers do not count; a commented include does not either.
    assert edges == {("mesh", "base"): 2, ("top", "mesh"): 1,
                     ("top", "base"): 1}
    assert tool.cycles(rooms, edges) == []
    assert tool.layers(rooms, edges) == {"base": 0, "mesh": 1, "top": 2}
    text = tool.table(rooms, edges, tool.layers(rooms, edges))
    assert text.splitlines()[2] == "| 2 | `top/` | mesh (1), base (1) |"
    assert "| 0 | `base/` | deal.II only |" in text


def test_cycle_is_reported_and_checked(script, tmp_path, capsys):
    tool = script("room-graph")
    top = tree(tmp_path, cycle=True)
    rooms, edges = tool.rooms_and_edges(top)
    assert tool.cycles(rooms, edges) == [["base", "mesh", "top"]]
    assert tool.main(["--top", top]) == 0
    assert tool.main(["--top", top, "--check"]) == 1
    assert "cycle: base <-> mesh <-> top" in capsys.readouterr().out


def test_picture(script, tmp_path):
    tool = script("room-graph")
    top = tree(tmp_path)
    png = os.path.join(top, "rooms.png")
    assert tool.main(["--top", top, "--png", png, "--check"]) == 0
    with open(png, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"


def test_rupture_has_no_cycles(script):
    # rupture's own rooms: every dependency points down (doc/design.md).
    tool = script("room-graph")
    rooms, edges = tool.rooms_and_edges(tool.TOP)
    assert tool.cycles(rooms, edges) == []
    layer = tool.layers(rooms, edges)
    assert layer["simulator"] > layer["time_integration"]
    assert layer["base"] == 0
