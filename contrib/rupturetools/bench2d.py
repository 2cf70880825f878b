"""The on-fault stations of the 2-D SCEC benchmarks (TPV101-2D, TPV103-2D,
TPV205-2D): what a run gives at each, and how far it is from a reference
run."""

import math
import os

from . import files

# Along-strike positions of the stations, in hundreds of metres (the SCEC
# names: faultst075 is at 7.5 km); each but 0 also at -x.
STATIONS = [0, 15, 30, 45, 60, 75, 90, 120, 150]


def parse_list(text, kind=float):
    """The numbers of a comma-separated list (the studies' --degrees,
    --spacing, --courant, ...), empty items left out; ValueError for an
    item that is not a number of the kind."""
    return [kind(x) for x in text.split(",") if x.strip()]


def cell_size(p, spacing):
    """The cell size (m) for degree @p p nearest to node spacing @p spacing
    (not coarser) at which every station is a node: the stations lie every
    1.5 km from x = 0, a vertex, so the cell size divides 1500 m, or 3000 m
    at an even degree, whose cells have a node in their middle. Between
    nodes a station's slip rate is interpolated, and the interpolant of
    the arriving front rises when the node ahead starts to slip: the
    station would seem to rupture early (measured at degree 4, 400 m cells:
    up to 0.1 s)."""
    period = 3000.0 if p % 2 == 0 else 1500.0
    return period / max(1, math.ceil(period / (p * spacing) - 1e-9))


def mesh(p, spacing):
    """Cells along and across the fault, and the model's half widths (m),
    for degree @p p at (about) node spacing @p spacing: an even number of
    cells each way, so that x = 0 and the fault y = 0 are mesh lines."""
    h = cell_size(p, spacing)
    nx = 2 * max(1, round(30000.0 / h))
    ny = 2 * max(1, round(15000.0 / h))
    return nx, ny, nx * h / 2, ny * h / 2


def one_side_each(stations=STATIONS):
    """The stations of @p stations on each side on its own: "0", "+45",
    "-45", ... (for a problem that is not symmetric about x = 0)."""
    return [str(s) if s == 0 else sign + str(s) for s in stations for sign in "+-"
            if s != 0 or sign == "+"]


def station_label(station):
    """A station's position along strike in km: an int station is the
    mean of both sides ("4.5"), a signed str one side ("+4.5", "-4.5")."""
    if isinstance(station, str):
        value = int(station) / 10
        return "%g" % value if value == 0 or station[0] not in "+-" else "%+g" % value
    return "%g" % (station / 10)


def station_files(station):
    """The station files of @p station: an int is both sides (faultst045
    and faultst-045; 0 only one), a str with a sign one side."""
    if isinstance(station, str):
        s = int(station)
        return ["faultst%03d" % s if s >= 0 else "faultst-%03d" % -s]
    return ["faultst%03d" % station] + (["faultst-%03d" % station] if station else [])


def station_values(out, stations=STATIONS):
    """Rupture time, peak slip rate and final slip at each station of the
    run in directory @p out: {station: {"rupture", "peak", "slip"}}, for an
    int station the mean of +x and -x, for a signed str station ("+45",
    "-45", from one_side_each) that side alone (None where a station does
    not rupture)."""
    values = {}
    for s in stations:
        names = station_files(s)
        ms = [files.station_metrics(files.read_station(
            os.path.join(out, n + ".dat")).rows) for n in names]
        v = {}
        for key in ("rupture", "peak", "slip"):
            xs = [m[key] for m in ms]
            v[key] = None if any(x is None for x in xs) else sum(xs) / len(xs)
        values[s] = v
    return values


def errors(values, reference, stations=STATIONS):
    """The largest error over @p stations of @p values against
    @p reference (both as station_values gives them, keys as str or int):
    absolute for rupture times (s), relative for peak slip rate and final
    slip; inf where one ruptures and the other does not."""
    e = {"rupture": 0.0, "peak": 0.0, "slip": 0.0}
    get = lambda table, s: table[str(s)] if str(s) in table else table[s]
    for s in stations:
        mine, ref = get(values, s), get(reference, s)
        for key in e:
            if mine[key] is None or ref[key] is None:
                if mine[key] != ref[key]:
                    e[key] = math.inf
                continue
            d = abs(mine[key] - ref[key])
            e[key] = max(e[key], d if key == "rupture" else d / abs(ref[key]))
    return e
