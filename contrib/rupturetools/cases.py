"""The cases P:H (degree, cell size) of the studies on the 3-D graded box
of prm/tpv3, prm/tpv101 and prm/tpv103."""

import sys

# The uniform core of the graded box (m): its lower and upper corners in
# prm/tpv3, prm/tpv101 and prm/tpv103 (whole space, the hypocentre at the
# origin) ...
GRADED_CORE = ((-18000.0, -1500.0, -10500.0), (18000.0, 1500.0, 10500.0))
# ... and in prm/tpv102 (half space: the core reaches the free surface
# 7.5 km above the hypocentre).
HALF_SPACE_CORE = ((-18000.0, -1500.0, -10500.0), (18000.0, 1500.0, 7500.0))


def core_size(core=GRADED_CORE):
    """The core's extent (m) along x, y, z."""
    return tuple(u - l for l, u in zip(*core))


def parse(text, core=GRADED_CORE):
    """[(degree, cell size)] from 'P:H,P:H'; exits naming what is wrong: not
    P:H, a degree outside 1..4, or (unless @p core is None) a cell size that
    does not divide the core."""
    cases = []
    size = core_size(core) if core else None
    for item in text.split(","):
        try:
            p, h = item.split(":")
            cases.append((int(p), float(h)))
        except ValueError:
            sys.exit("--cases: '%s' is not P:H (degree:cell size in m)" % item)
        if not 1 <= cases[-1][0] <= 4:
            sys.exit("--cases: degree %d is not in 1..4" % cases[-1][0])
        if size and any(abs(c / cases[-1][1] - round(c / cases[-1][1])) > 1e-9
                        for c in size):
            sys.exit("--cases: %g m does not divide the %s km core of "
                     "the graded box" % (cases[-1][1],
                                         " x ".join("%g" % (c / 1000) for c in size)))
    return cases


def core_sets(h, core=GRADED_CORE):
    """The --set entries for cells of @p h m in the core: 'Scene/Box/Number
    of cells', and, where the core's width normal to the fault (y, the
    fault being the plane y = 0 in the middle) would be an odd number of
    cells, which puts no face on the fault plane, the core's corners
    widened by one cell to an even number (1000 m: 4 cells over |y| < 2
    km instead of 3 over |y| < 1.5 km)."""
    n = [round(c / h) for c in core_size(core)]
    sets = []
    if n[1] % 2:
        n[1] += 1
        (xl, _, zl), (xu, _, zu) = core
        y = n[1] * h / 2
        sets = ["Scene/Box/Grading/Core lower corner=%g, %g, %g" % (xl, -y, zl),
                "Scene/Box/Grading/Core upper corner=%g, %g, %g" % (xu, y, zu)]
    return ["Scene/Box/Number of cells=%d, %d, %d" % tuple(n)] + sets
