"""Tests of contrib/anisotropy-study: its transversely isotropic cases keep
the isotropic constants in the fault plane, and it measures front speeds
and station values from output files made here."""

import json
import math

from stations import write_station


def constants(text):
    return {k.strip(): float(v) for k, v in
            (item.split("=") for item in text.split(","))}


def test_cases_keep_the_plane_of_isotropy(script):
    study = script("anisotropy-study")
    names = [name for name, _, _ in study.CASES]
    assert names == ["isotropic", "soft-across", "stiff-across"]
    for name, _, sets in study.CASES[1:]:
        c = constants(sets[1].split("=", 1)[1])
        assert math.isclose(c["C11"], study.LAMBDA + 2 * study.MU, rel_tol=1e-6)
        assert math.isclose(c["C66"], study.MU, rel_tol=1e-6)
        assert "Material/Material axes=0, 1, 0" in sets
        # Positive definite: C11 > |C12|, C33 (C11 + C12) > 2 C13^2.
        c12 = c["C11"] - 2 * c["C66"]
        assert c["C11"] > abs(c12)
        assert c["C33"] * (c["C11"] + c12) > 2 * c["C13"] ** 2
    soft = constants(study.CASES[1][2][1].split("=", 1)[1])
    assert math.isclose(soft["C44"], 0.7 * study.MU, rel_tol=1e-6)


def write_rupture_times(path, speed_strike, speed_dip, hypocentre_dip):
    """A rupture_time.dat of a front that leaves the hypocentre (x = 0 at
    down-dip distance hypocentre_dip) at the given speeds along the axes
    (elliptic fronts); the corner (30 km, 0) never ruptures."""
    lines = ["# Column #1 = Distance along strike (m)",
             "# Column #2 = Distance down-dip (m)",
             "# Column #3 = Rupture time (s)", "j k t"]
    for k in range(0, 15001, 500):
        for j in range(-15000, 15001, 500):
            dx, dz = j / speed_strike, (k - hypocentre_dip) / speed_dip
            t = math.hypot(dx, dz)
            if j == 15000 and k == 0:
                t = 1e9
            lines.append("%g %g %g" % (j, k, t))
    path.write_text("\n".join(lines) + "\n")


def test_measures_front_speeds_and_stations(script, tmp_path):
    study = script("anisotropy-study")
    write_rupture_times(tmp_path / "rupture_time.dat", 3000.0, 2500.0, 7500.0)
    write_station(tmp_path, "faultst075dp075", 2.5, 3.0, 1.2, "TPV3")
    write_station(tmp_path, "faultst000dp135", 2.4, 2.0, 0.8, "TPV3")
    result, (js, ks, grid) = study.measure(str(tmp_path), 7500.0)
    assert math.isclose(result["front speed along strike"], 3000.0, rel_tol=1e-9)
    assert math.isclose(result["front speed along dip"], 2500.0, rel_tol=1e-9)
    assert grid[0][-1] is None  # never ruptured
    assert abs(result["faultst075dp075"]["rupture"] - 2.5) < 0.011
    assert math.isclose(result["faultst075dp075"]["slip"], 1.2, rel_tol=1e-6)
    assert math.isclose(result["faultst000dp135"]["peak"], 2.0)
    json.dumps(result)


def test_unruptured_segment_has_no_speed(script):
    study = script("anisotropy-study")
    assert study.front_speed([0.0, 1.0, 2.0], [0.0, None, 2.0], 0.5, 1.5) is None
    assert study.front_speed([0.0, 1.0, 2.0], [0.0, 1.0, 2.0], 0.5, 1.5) == 1.0
