"""Tests of contrib/anisotropic-friction-study: the prestress keeps its
ellipse norm, the ellipse's normal, the front speeds and the rake measured
from output files made here."""

import math


def test_prestress_keeps_the_ellipse_norm(script):
    study = script("anisotropic-friction-study")
    for r in (1.0, 2.0, 4.0, 20.0):
        s = study.prestress_scale(r)
        # tau = T s (1, -1): |A^-1 tau| = T s sqrt(1 + 1/r^2) = T.
        assert math.isclose(s * math.sqrt(1 + 1 / r ** 2), 1.0)
    assert math.isclose(study.prestress_scale(1.0), math.sqrt(0.5))
    text = study.input_text(2.0, "0, 0, 1")
    assert "set Strength ratio = 2\n" in text
    assert "set First direction = 0, 0, 1\n" in text
    assert ("%.15g" % study.prestress_scale(2.0)) in text
    assert "Number of cells = 36, 8, 36" in text
    assert "Time step = 0.01\n" in text
    finer = study.input_text(2.0, "0, 0, 1", refine=2)
    assert "Number of cells = 144, 32, 144" in finer
    assert "Time step = 0.0025\n" in finer
    assert "Number of cells = 18, 4, 18" in study.input_text(2, "1, 0, 0", True)


def test_ellipse_normal(script):
    study = script("anisotropic-friction-study")
    assert math.isclose(study.ellipse_normal_rake(1.0, "1, 0, 0"), -45.0)
    assert math.isclose(study.ellipse_normal_rake(1.0, "0, 0, 1"), -45.0)
    # A^-2 tau: the component along e_2 shrinks by r^2.
    assert math.isclose(study.ellipse_normal_rake(2.0, "1, 0, 0"),
                        math.degrees(math.atan2(-0.25, 1)))
    assert math.isclose(study.ellipse_normal_rake(2.0, "0, 0, 1"),
                        math.degrees(math.atan2(-1, 0.25)))


def fronts(speed_x, speed_z, centre=4500.0):
    """rupture_time.dat rows of elliptic fronts from (0, centre); one node
    far away never ruptured."""
    rows = []
    for j in range(-4000, 4001, 250):
        for k in range(500, 8501, 250):
            t = math.hypot(j / speed_x, (k - centre) / speed_z)
            rows.append([float(j), float(k), t])
    rows[0][2] = 1e9
    return rows


def test_front_speeds(script, tmp_path):
    study = script("anisotropic-friction-study")
    lines = ["# Column #1 = Distance along strike (m)", "j k t"]
    lines += ["%g %g %.12g" % tuple(r) for r in fronts(2400.0, 1800.0)]
    (tmp_path / "rupture_time.dat").write_text("\n".join(lines) + "\n")
    rows = study.read_rupture_times(str(tmp_path / "rupture_time.dat"))
    assert len(rows) == 33 * 33
    assert math.isclose(study.front_speed(rows, True, 4500.0), 2400.0,
                        rel_tol=1e-9)
    assert math.isclose(study.front_speed(rows, False, 4500.0), 1800.0,
                        rel_tol=1e-9)
    assert study.front_speed(rows[:5], True, 4500.0) is None


def test_rake_leaves_out_small_slip(script):
    study = script("anisotropic-friction-study")
    slip = [[1.0, 0.0, -1.0], [2.0, 0.0, -1.0], [1.0, 0.0, -0.5],
            [0.0, 0.0, 0.01]]
    rake, n = study.rake_of_slip(slip)
    assert n == 3
    assert math.isclose(rake, math.degrees(math.atan2(-1, 2)))
    assert study.rake_of_slip([]) == (None, 0)


def write_fault_output(directory, slip, times):
    """fault.pvd and one ASCII fault_00000.vtu with two quads on a 3 x 2
    grid of nodes in the plane y = 0 (the middle nodes written twice, as
    each cell draws its own corners)."""
    nodes = [(x, 0.0, z) for z in (0.0, 500.0) for x in (0.0, 500.0, 1000.0)]
    quads = [(0, 1, 4, 3), (1, 2, 5, 4)]
    points = [nodes[i] for q in quads for i in q]
    point_slip = [slip[i] for q in quads for i in q]
    point_time = [times[i] for q in quads for i in q]
    n = len(points)

    def array(name, values, components):
        flat = " ".join("%.17g" % v for row in values
                        for v in (row if components > 1 else [row]))
        return ('<DataArray type="Float64" Name="%s" NumberOfComponents="%d"'
                ' format="ascii">%s</DataArray>' % (name, components, flat))
    vtu = "\n".join([
        '<VTKFile type="UnstructuredGrid" version="0.1">',
        "<UnstructuredGrid>",
        '<Piece NumberOfPoints="%d" NumberOfCells="2">' % n,
        "<Points>", array("points", points, 3), "</Points>",
        "<Cells>",
        '<DataArray type="Int32" Name="connectivity" format="ascii">%s'
        "</DataArray>" % " ".join(str(i) for i in range(n)),
        '<DataArray type="Int32" Name="offsets" format="ascii">4 8'
        "</DataArray>",
        '<DataArray type="UInt8" Name="types" format="ascii">9 9'
        "</DataArray>",
        "</Cells>",
        "<PointData>", array("slip", point_slip, 3),
        array("rupture_time", point_time, 1), "</PointData>",
        "</Piece>", "</UnstructuredGrid>", "</VTKFile>", ""])
    (directory / "fault_00000.vtu").write_text(vtu)
    (directory / "fault.pvd").write_text(
        '<VTKFile type="Collection" version="0.1"><Collection>'
        '<DataSet timestep="1.7" file="fault_00000.vtu"/>'
        "</Collection></VTKFile>\n")


def test_final_slip_reads_each_node_once(script, tmp_path):
    study = script("anisotropic-friction-study")
    slip = [[float(i), 0.0, -float(i)] for i in range(6)]
    times = [0.1 * i for i in range(5)] + [1e9]
    write_fault_output(tmp_path, slip, times)
    points, got_slip, got_times = study.final_slip(str(tmp_path))
    assert len(points) == 6
    assert points[0] == (0.0, 0.0) and points[-1] == (1000.0, 500.0)
    by_point = dict(zip(points, zip(got_slip, got_times)))
    assert by_point[(500.0, 0.0)] == ([1.0, 0.0, -1.0], 0.1)
    assert by_point[(1000.0, 500.0)][1] is None  # never ruptured
    rake, n = study.rake_of_slip(got_slip)
    assert n == 5 and math.isclose(rake, -45.0)
