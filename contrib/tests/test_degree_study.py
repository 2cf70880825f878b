"""Tests of contrib/degree-study: its cells put every station on a node,
and its order in time is read correctly from errors that shrink as a
known power of the Courant fraction."""

import math


def test_cells_put_stations_on_nodes(script):
    study = script("degree-study")
    for p in (1, 2, 3, 4):
        for spacing in (200.0, 100.0, 50.0):
            h = study.cell_size(p, spacing)
            assert h / p <= spacing + 1e-9
            # The stations lie every 1.5 km from x = 0, a vertex. The
            # Gauss-Lobatto nodes at the cell's ends and, at even degree,
            # its middle are the only ones at rational positions.
            nodes = [0.0, 1.0] + ([0.5] if p % 2 == 0 else [])
            for x in range(0, 15001, 1500):
                xi = x / h - math.floor(x / h)
                assert min(abs(xi - n) for n in nodes) < 1e-9, (p, spacing, x)


def test_order_of_a_known_power(script):
    study = script("degree-study")
    # e = C^2 and C^1: orders 2 and 1.
    assert abs(study.order(0.5 ** 2, 0.25 ** 2, 0.5, 0.25) - 2) < 1e-12
    assert abs(study.order(0.5, 0.25, 0.5, 0.25) - 1) < 1e-12
    assert study.order(0.0, 0.1, 0.5, 0.25) is None
    assert study.order(math.inf, 0.1, 0.5, 0.25) is None


def test_time_order_orders_share_the_helper():
    from rupturetools.time_order import orders
    got = orders([4.0, 1.0, 0.0])
    assert abs(got[0] - 2) < 1e-12 and math.isnan(got[1])


def test_order_rows_leave_out_the_reference(script):
    study = script("degree-study")
    rows = []
    for c in (0.5, 0.25, 0.125, 0.0625):
        # Errors against the run at 0.0625: second order in rupture time,
        # first in peak slip rate, exact final slip at 0.125.
        rows.append({"degree": 2, "spacing": 100.0, "courant": c,
                     "errors": {"rupture": 0.0 if c == 0.0625 else c ** 2,
                                "peak": 0.0 if c == 0.0625 else c,
                                "slip": 0.0 if c <= 0.125 else c}})
    lines = study.order_rows(rows)
    assert lines == ["| 2 | 100 | 0.5 / 0.25 | 2.00 | 1.00 | 1.00 |",
                     "| 2 | 100 | 0.25 / 0.125 | 2.00 | 1.00 | - |"]
