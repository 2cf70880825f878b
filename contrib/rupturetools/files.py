"""Readers of the files rupture writes, by column name.

- Station files (SCEC layout: '#' header lines, a field-name line starting
  with 't ', then one row per sample): read_station().
- The statistics table (a '# N: Name (unit)' header line per column, then
  one row per step): read_statistics().
"""

import re


class Table:
    """Rows of numbers with named columns: table["t"] is a column (list),
    table.rows the rows, table.names the column names in order."""

    def __init__(self, names, rows):
        self.names = list(names)
        self.rows = rows
        self._index = {n: i for i, n in enumerate(self.names)}

    def __len__(self):
        return len(self.rows)

    def __contains__(self, name):
        return name in self._index

    def index(self, name):
        try:
            return self._index[name]
        except KeyError:
            raise KeyError("no column %r; the columns are: %s"
                           % (name, ", ".join(self.names))) from None

    def __getitem__(self, name):
        i = self.index(name)
        return [r[i] for r in self.rows]


def _numbers(line, path, number):
    try:
        return [float(v) for v in line.split()]
    except ValueError:
        raise ValueError("%s, line %d: not a row of numbers: %r"
                         % (path, number, line.strip()[:80])) from None


def read_station(path):
    """A station file (fault station 'faultst*.dat' or a receiver) as a
    Table whose names are those of its field-name line ('t', 'h-slip',
    'h-slip-rate', 'h-shear-stress', ...)."""
    names, rows = None, []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            if line.startswith("#") or not line.strip():
                continue
            if names is None and line.startswith("t "):
                names = line.split()
                continue
            rows.append(_numbers(line, path, number))
    if names is None:
        raise ValueError("%s: no field-name line (one starting with 't ')"
                         % path)
    return Table(names, rows)


_COLUMN = re.compile(r"^#\s*(\d+):\s*(.*?)\s*$")


def read_statistics(path):
    """The statistics table as a Table whose names are the column titles
    without their units and remarks ('Time', 'Kinetic energy', 'Energy
    balance error', ...)."""
    names, rows = {}, []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            if line.startswith("#"):
                m = _COLUMN.match(line)
                if m:
                    title = re.split(r"\s*\(", m.group(2))[0]
                    names[int(m.group(1))] = title
                continue
            if line.strip():
                rows.append(_numbers(line, path, number))
    ordered = [names.get(i, "column %d" % i)
               for i in range(1, 1 + max(names or [0]))]
    return Table(ordered, rows)


def crossing_time(times, values, threshold):
    """The first time a sampled |value| exceeds threshold, linearly
    interpolated between the samples (the SCEC rupture time with 1 mm/s);
    None if it never does."""
    for (t0, a), (t1, b) in zip(zip(times, values),
                                zip(times[1:], values[1:])):
        a, b = abs(a), abs(b)
        if b > threshold >= a:
            return t0 + (threshold - a) / (b - a) * (t1 - t0)
    return None


def value_at(times, values, t):
    """The sampled value at time t, linearly interpolated (t within the
    samples' times)."""
    if not times or t < times[0] - 1e-12 or t > times[-1] + 1e-12:
        raise ValueError("time %g outside the samples [%g, %g]"
                         % (t, times[0] if times else 0,
                            times[-1] if times else 0))
    for (t0, a), (t1, b) in zip(zip(times, values),
                                zip(times[1:], values[1:])):
        if t0 - 1e-12 <= t <= t1 + 1e-12:
            if t1 == t0:
                return b
            return a + (t - t0) / (t1 - t0) * (b - a)
    return values[-1]


def station_metrics(rows):
    """The SCEC measures of a fault station's rows (t, h-slip, h-slip-rate,
    ...): the rupture time (the slip rate first above 1 mm/s, interpolated),
    the peak slip rate and the final slip, by magnitude."""
    times = [r[0] for r in rows]
    rates = [r[2] for r in rows]
    return {"rupture": crossing_time(times, rates, 1e-3),
            "peak": max(abs(v) for v in rates) if rows else None,
            "slip": abs(rows[-1][1]) if rows else None}
