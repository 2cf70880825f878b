"""The SCEC-style station names of the shipped examples agree with their
positions: faultst<along strike>[dp<down dip>] in hectometres, along strike
from x = 0 and down dip from <Fault/Output/Down-dip origin> (or, when that
is empty, the model's top, the last coordinate of the box's upper corner)
on the vertical faults y = 0 of the benchmarks."""

import glob
import os
import re

import pytest

PRM = os.path.join(os.path.dirname(__file__), "..", "..", "prm")
NAME = re.compile(r"^faultst(-?\d{3})(?:dp(\d{3}))?$")


def entry(text, name):
    m = re.search(r"^\s*set\s+%s\s*=\s*(.*)$" % re.escape(name), text, re.M)
    return m.group(1).strip() if m else ""


def named_stations():
    cases = []
    for path in sorted(glob.glob(os.path.join(PRM, "*", "*.prm"))):
        text = open(path).read()
        stations = entry(text, "Stations")
        if not stations or entry(text, "Plane normal").replace(" ", "") not in ("0,1", "0,1,0"):
            continue
        origin = entry(text, "Down-dip origin")
        top = float(origin) if origin else float(entry(text, "Upper corner").split(",")[-1])
        for item in stations.split(";"):
            name, coordinates = item.split(":")
            if NAME.match(name.strip()):
                cases.append((os.path.basename(path), name.strip(),
                              [float(c) for c in coordinates.split(",")], top))
    return cases


CASES = named_stations()


def test_the_benchmarks_have_named_stations():
    files = {c[0] for c in CASES}
    assert {"tpv3.prm", "tpv101.prm", "tpv102.prm", "tpv103.prm", "tpv101-2d.prm",
            "tpv205-2d.prm"} <= files


@pytest.mark.parametrize("prm,name,point,top", CASES,
                         ids=["%s:%s" % (c[0], c[1]) for c in CASES])
def test_name_matches_position(prm, name, point, top):
    strike, dip = NAME.match(name).groups()
    assert float(strike) * 100 == pytest.approx(point[0], abs=1e-6)
    if len(point) == 3:
        assert dip is not None, "a 3-D station needs its down-dip distance in its name"
        assert float(dip) * 100 == pytest.approx(top - point[2], abs=1e-6)
    else:
        assert dip is None
