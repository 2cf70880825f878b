"""Parameter sweeps (contrib/sweep): the summary of the cases (summary.csv,
summary.md) and its plots."""

import csv
import math
import os
import re

from . import cycles, fault_snapshots, files
from .sweep_files import (OUTCOMES, case_name, derived, format_value, read_json,
                          shown, write_atomically)

# ------------------------------------------------------------------ summary

def read_table(path):
    """Rows of numbers of a table with '#' comments and a name line."""
    rows = []
    try:
        with open(path) as f:
            for line in f:
                if line.startswith("#"):
                    continue
                try:
                    rows.append([float(x) for x in line.split()])
                except ValueError:
                    continue
    except OSError:
        pass
    return rows


def shear_wave_speed(sweep, directory):
    if "shear wave speed" in sweep:
        return sweep["shear wave speed"]
    try:
        with open(os.path.join(directory, "parameters.prm")) as f:
            text = f.read()
    except OSError:
        return None
    m = re.search(r"set S-wave speed\s*=\s*([^\n#]*)", text)
    if not m:
        return None
    try:
        return float(m.group(1).split(",")[0])
    except ValueError:
        return None


def rupture_front(directory, nucleation, cs, dim):
    """Mean rupture speed (1 / mean slowness) and the supershear fraction
    over the ruptured nodes outside the nucleation zone, from
    rupture_time.dat."""
    import numpy as np
    rows = read_table(os.path.join(directory, "rupture_time.dat"))
    if not rows:
        return None, None
    a = np.array(rows)
    j, k, t = a[:, 0], a[:, 1], a[:, 2]
    ruptured = t < 1e8
    if ruptured.sum() < 3:
        return None, None
    uj, uk = np.unique(j), np.unique(k)
    if uj.size * uk.size != t.size:
        return None, None  # not a grid: no gradient
    order = np.lexsort((j, k))
    grid = t[order].reshape(uk.size, uj.size)
    mask = grid < 1e8
    grid = np.where(mask, grid, np.nan)
    slowness = np.zeros_like(grid)
    parts = []
    for axis, coords in ((1, uj), (0, uk)):
        if coords.size < 2:
            continue
        g = np.gradient(grid, coords, axis=axis)
        parts.append(g * g)
    slowness = np.sqrt(sum(parts))
    # The nucleation zone: around the first node to rupture.
    first = np.unravel_index(np.nanargmin(grid), grid.shape)
    jj, kk = np.meshgrid(uj, uk)
    radius = np.hypot(jj - jj[first], kk - kk[first])
    half = 0.5 * nucleation if dim == 2 else math.sqrt(nucleation / math.pi)
    use = mask & np.isfinite(slowness) & (radius > (half or 0)) & \
        (slowness > 0)
    if use.sum() == 0:
        return None, None
    s = slowness[use]
    speed = 1 / s.mean()
    fraction = float((1 / s > cs).mean()) if cs else None
    return speed, fraction


def final_slip(directory):
    """Along-fault coordinates (km) and final slip (m) from the last fault
    snapshot, or None."""
    try:
        entries = fault_snapshots.read_collection(directory)
        snap = fault_snapshots.read_snapshot(entries[-1], ["slip"])
    except Exception:
        return None
    slip = snap.arrays["slip"]
    if slip.ndim > 1:
        slip = (slip ** 2).sum(axis=1) ** 0.5
    dim = 2 if snap.cells.shape[1] == 2 else 3
    frame = fault_snapshots.FaultFrame(snap.points, dim)
    if dim == 2:
        x = frame.along_fault(snap.points)[0]
        return {"dim": 2, "x": x, "slip": slip}
    return {"dim": 3, "x": frame.along_strike(snap.points),
            "y": frame.down_dip(snap.points), "slip": slip}


CYCLE_KEYS = ("events", "recurrence", "event peak slip rate", "event slip")


def cycle_columns(directory):
    """The cycle columns of a case from its events.csv (None where it has
    none, or too few events): the number of events, their recurrence
    (years) and the mean peak slip rate and largest slip of the events
    after the first two (those the initial state shapes less)."""
    row = dict.fromkeys(CYCLE_KEYS)
    catalogue = os.path.join(directory, "events.csv")
    if not os.path.exists(catalogue):
        return row
    starts, peaks, slips = cycles.merge_events(
        *cycles.read_catalogue(catalogue))
    row["events"] = len(starts)
    row["recurrence"] = cycles.recurrence(starts)
    if row["recurrence"] is not None:
        row["event peak slip rate"] = sum(peaks[2:]) / len(peaks[2:])
        row["event slip"] = sum(slips[2:]) / len(slips[2:])
    return row


def summarise(sweep, cases):
    out = sweep["output"]
    rows = []
    for i, values in enumerate(cases):
        d = os.path.join(out, case_name(i))
        summary = read_json(os.path.join(d, "summary.json")) or {}
        runner = read_json(os.path.join(d, "case.json")) or {}
        row = {"case": i}
        row.update({k: format_value(v) for k, v in values.items()})
        row.update({k: "%.6g" % v for k, v in derived(sweep, values).items()})
        status = summary.get("status")
        row["end"] = summary.get("end", "")
        row["message"] = ""
        fault = summary.get("fault") or {}
        if status in ("finished", "ended early"):
            row["outcome"] = None
        elif status == "interrupted":
            row["outcome"] = "interrupted"
        elif runner or status == "failed":
            row["outcome"] = "failed"
            row["message"] = error_message(d, summary)
        else:
            row["outcome"] = "not run"
        dim = summary.get("dimension", 3)
        row["dimension"] = dim
        row["M0"] = fault.get("seismic moment")
        row["Mw"] = fault.get("moment magnitude")
        row["ruptured area"] = fault.get("ruptured area")
        row["mean slip"] = fault.get("mean slip")
        row["max slip"] = fault.get("max slip")
        row["peak slip rate"] = fault.get("peak slip rate")
        row["rupture speed"], row["supershear fraction"] = (None, None)
        if row["outcome"] is None:
            cs = shear_wave_speed(sweep, d)
            row["rupture speed"], row["supershear fraction"] = rupture_front(
                d, sweep.get("nucleation size", 0), cs, dim)
        if "reference" in sweep and row["outcome"] is None:
            row.update(reference_errors(sweep["reference"], d))
        # Earthquake cycles (runs with an event catalogue): the events,
        # their recurrence (the mean interval after the first two) and the
        # mean peak slip rate and largest slip of those later events.
        row.update(cycle_columns(d) if row["outcome"] is None else
                   dict.fromkeys(CYCLE_KEYS))
        row["wall time"] = runner.get("wall time (s)")
        row["peak memory"] = summary.get("peak memory, all ranks (B)")
        rows.append(row)

    # Outcomes need the fault size: given, or the largest ruptured area.
    areas = [r["ruptured area"] for r in rows if r["outcome"] is None and
             r["ruptured area"]]
    fault_size = sweep.get("fault size") or (max(areas) if areas else None)
    nucleation = sweep.get("nucleation size")
    for r in rows:
        if r["outcome"] is not None:
            continue
        if r["end"] in ("runaway", "wall-clock limit"):
            r["outcome"] = "aborted"
            r["message"] = r["end"]
        elif r["events"] is not None and r["ruptured area"] is None:
            # (A cycle run without one rupture's area: the boundary-
            # integral method's; its measures are the cycle columns.)
            r["outcome"] = "earthquake cycles"
        elif nucleation and (r["ruptured area"] or 0) <= 1.5 * nucleation:
            r["outcome"] = "died at nucleation"
        elif fault_size and (r["ruptured area"] or 0) >= \
                sweep["whole fault fraction"] * fault_size:
            r["outcome"] = "ruptured the whole fault"
        else:
            r["outcome"] = "stopped by itself"
    return rows, fault_size


def station_metrics(path):
    """Rupture time, peak slip rate and final slip of a SCEC station file,
    as contrib/compare-stations measures them."""
    rows = [r for r in read_table(path) if len(r) >= 3]
    return files.station_metrics(rows) if rows else None


def reference_errors(reference, directory):
    """The largest errors over the stations that the reference and the case
    share: rupture time (s), peak slip rate and final slip (relative)."""
    errors = {"rupture time error": None, "peak slip rate error": None,
              "final slip error": None}
    for name in sorted(os.listdir(reference)):
        mine = os.path.join(directory, name)
        if not name.endswith(".dat") or not os.path.isfile(mine):
            continue
        r, m = station_metrics(os.path.join(reference, name)), \
            station_metrics(mine)
        if not r or not m:
            continue
        pairs = [("rupture time error",
                  None if r["rupture"] is None or m["rupture"] is None
                  else abs(m["rupture"] - r["rupture"])),
                 ("peak slip rate error",
                  abs(m["peak"] - r["peak"]) / r["peak"] if r["peak"] > 0
                  else None),
                 ("final slip error",
                  abs(m["slip"] - r["slip"]) / r["slip"] if r["slip"] > 0
                  else None)]
        for key, value in pairs:
            if value is not None:
                errors[key] = max(errors[key] or 0, value)
    return errors


def error_message(directory, summary):
    if summary.get("message"):
        return summary["message"].splitlines()[0]
    try:
        with open(os.path.join(directory, "run.txt")) as f:
            text = f.read()
    except OSError:
        return ""
    m = re.search(r"^Error: (.*)$", text, re.M)
    if m:
        return m.group(1)
    lines = [l for l in text.splitlines() if l.strip()]
    return lines[-1] if lines else ""


COLUMNS = [("outcome", "outcome", None), ("end", "end", None),
           ("M0", "M0 (N m; N in 2-D)", "%.4g"), ("Mw", "Mw", "%.3f"),
           ("ruptured area", "ruptured area (m^2; m in 2-D)", "%.4g"),
           ("mean slip", "mean slip (m)", "%.4g"),
           ("max slip", "max slip (m)", "%.4g"),
           ("peak slip rate", "peak slip rate (m/s)", "%.4g"),
           ("rupture speed", "mean rupture speed (m/s)", "%.0f"),
           ("supershear fraction", "supershear fraction", "%.2f"),
           ("events", "events", "%d"),
           ("recurrence", "recurrence (years)", "%.3f"),
           ("event peak slip rate", "event peak slip rate (m/s)", "%.4g"),
           ("event slip", "slip per event (m)", "%.4g"),
           ("wall time", "wall time (s)", "%.1f"),
           ("peak memory", "peak memory (MB)", None),
           ("message", "message", None)]


def cell(row, key, fmt):
    v = row.get(key)
    if v is None:
        return ""
    if key == "peak memory":
        return "%.0f" % (v / 1048576.)
    return fmt % v if fmt else str(v)


def write_tables(sweep, rows, fault_size):
    out = sweep["output"]
    params = [v["alias"] for v in sweep["vary"]] + \
        [n for n, _, _ in sweep["derive"]]
    columns = list(COLUMNS)
    if "reference" in sweep:
        # Before the message: the errors against the reference stations.
        columns[-1:-1] = [("rupture time error", "rupture time error (s)",
                           "%.4f"),
                          ("peak slip rate error", "peak slip rate error",
                           "%.2e"),
                          ("final slip error", "final slip error", "%.2e")]
    header = ["case"] + params + [c[1] for c in columns]
    table = [[str(r["case"])] + [str(r.get(p, "")) for p in params] +
             [cell(r, k, f) for k, _, f in columns] for r in rows]
    tmp = os.path.join(out, "summary.csv.tmp")
    with open(tmp, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(table)
    os.replace(tmp, os.path.join(out, "summary.csv"))

    counts = {o: sum(r["outcome"] == o for r in rows) for o in OUTCOMES}
    lines = [f"# {sweep['title']}", "",
             f"{len(rows)} cases of `{shown(sweep['file'])}` "
             f"(base `{shown(sweep['base'])}`): " +
             ", ".join(f"{n} {o}" for o, n in counts.items() if n) + ".", "",
             "Varied: " + "; ".join(f"`{v['alias']}` = {v['entry']}"
                                    for v in sweep["vary"]) + ".", ""]
    if fault_size:
        lines += [f"Outcomes: 'ruptured the whole fault' when the ruptured "
                  f"area is at least {sweep['whole fault fraction']:g} of "
                  f"{fault_size:.6g} ("
                  + ("the sweep file's 'fault size'" if "fault size" in sweep
                     else "the largest ruptured area of the sweep") + ")" +
                  (f"; 'died at nucleation' when it is at most 1.5 times "
                   f"the nucleation size {sweep['nucleation size']:g}"
                   if "nucleation size" in sweep else "") + ".", ""]
    lines += ["| " + " | ".join(header) + " |",
              "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(c.replace("|", "/") for c in r) + " |"
              for r in table]
    write_atomically(os.path.join(out, "summary.md"), "\n".join(lines) + "\n")


MARKERS = {"ruptured the whole fault": "o", "stopped by itself": "s",
           "died at nucleation": "v", "earthquake cycles": "D",
           "aborted": "X", "failed": "x",
           "interrupted": "+", "not run": "."}


def magnitude_of(row):
    """Mw in 3-D, log10 M0 in 2-D (per m of fault)."""
    if row.get("Mw") is not None:
        return row["Mw"]
    if row.get("M0"):
        return math.log10(row["M0"])
    return None


def plot(sweep, rows, map_axes, panels_option=None):
    """Draw the sweep's pictures; returns their file names."""
    cycle_runs = any(r.get("events") is not None for r in rows)
    if cycle_runs and not any(r.get("M0") for r in rows):
        # Cycles of the boundary-integral method: no single rupture's size
        # or slip to draw.
        plot_cycles(sweep, rows)
        return ["cycles.png"]
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    out = sweep["output"]
    aliases = [v["alias"] for v in sweep["vary"]] + \
        [n for n, _, _ in sweep["derive"]]
    dim = next((r["dimension"] for r in rows if r.get("M0") is not None), 3)
    mlabel = "Mw" if dim == 3 else "log10 M0 (M0 in N, per m of fault)"
    values = [magnitude_of(r) for r in rows]
    finite = [v for v in values if v is not None]
    vmin, vmax = (min(finite), max(finite)) if finite else (0, 1)
    if vmax <= vmin:
        vmax = vmin + 1

    def number(r, a):
        try:
            return float(r[a])
        except (TypeError, ValueError, KeyError):
            return float("nan")

    # The outcome map: two parameters, panels by a third.
    x, y = map_axes if map_axes else (aliases + aliases)[:2]
    rest = [v["alias"] for v in sweep["vary"] if v["alias"] not in (x, y)]
    panel_key = rest[0] if rest else None
    if panels_option is not None:
        panel_key = None if panels_option == "none" else panels_option
    panels = sorted({r[panel_key] for r in rows}, key=lambda s: float(s)) \
        if panel_key else [None]
    if len(panels) > 6:
        panels, panel_key = [None], None
    fig, axes = plt.subplots(1, len(panels),
                             figsize=(max(4.4 * len(panels) + 1.5, 8), 4.4),
                             squeeze=False)
    for ax, p in zip(axes[0], panels):
        sub = [r for r in rows if panel_key is None or r[panel_key] == p]
        for outcome, marker in MARKERS.items():
            pts = [r for r in sub if r["outcome"] == outcome]
            if not pts:
                continue
            c = [magnitude_of(r) for r in pts]
            kw = dict(marker=marker, s=90, edgecolors="k", label=outcome)
            if all(v is not None for v in c) and marker not in "x+.":
                ax.scatter([number(r, x) for r in pts],
                           [number(r, y) for r in pts], c=c,
                           cmap="viridis", vmin=vmin, vmax=vmax, **kw)
            else:
                kw.pop("edgecolors")
                ax.scatter([number(r, x) for r in pts],
                           [number(r, y) for r in pts], c="grey", **kw)
        ax.set_xlabel(x)
        ax.set_ylabel(y)
        if panel_key:
            ax.set_title(f"{panel_key} = {p}")
        ax.grid(alpha=0.3)
    handles = {}
    for ax in axes[0]:
        for h, l in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(l, h)
    fig.legend(handles.values(), handles.keys(), loc="lower center",
               ncol=len(handles), fontsize=8, frameon=False)
    fig.suptitle(sweep["title"] + "\noutcome (marker) and size (colour)",
                 fontsize=11)
    fig.subplots_adjust(bottom=0.25, top=0.82,
                        left=0.07 if len(panels) > 1 else 0.1, right=0.86,
                        wspace=0.3)
    if finite:
        cb = fig.colorbar(matplotlib.cm.ScalarMappable(
            norm=matplotlib.colors.Normalize(vmin, vmax), cmap="viridis"),
            cax=fig.add_axes([0.89, 0.25, 0.015, 0.6]))
        cb.set_label(mlabel)
    fig.savefig(os.path.join(out, "outcome-map.png"), dpi=110)
    plt.close(fig)

    # Magnitude against each parameter.
    fig, axes = plt.subplots(1, len(aliases), figsize=(3.6 * len(aliases),
                                                       3.4), squeeze=False)
    for ax, a in zip(axes[0], aliases):
        for outcome, marker in MARKERS.items():
            pts = [r for r in rows if r["outcome"] == outcome and
                   magnitude_of(r) is not None]
            if pts:
                ax.scatter([number(r, a) for r in pts],
                           [magnitude_of(r) for r in pts], marker=marker,
                           label=outcome)
        ax.set_xlabel(a)
        ax.set_ylabel(mlabel)
        ax.grid(alpha=0.3)
    if axes[0][0].get_legend_handles_labels()[0]:
        axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "magnitude.png"), dpi=110)
    plt.close(fig)

    # A gallery of the final slip, one small panel per case.
    n = len(rows)
    columns = min(9, max(1, n))
    lines_ = (n + columns - 1) // columns
    fig, axes = plt.subplots(lines_, columns, figsize=(1.9 * columns,
                                                       1.6 * lines_),
                             squeeze=False, sharex=True, sharey=(dim == 2))
    for ax in axes.flat:
        ax.set_axis_off()
    for ax, r in zip(axes.flat, rows):
        ax.set_axis_on()
        ax.tick_params(labelsize=6)
        ax.set_title(f"{r['case']}: " + ", ".join(
            str(r[v["alias"]]) for v in sweep["vary"]), fontsize=6)
        s = final_slip(os.path.join(out, case_name(r["case"])))
        if s is None:
            ax.text(0.5, 0.5, r["outcome"], ha="center", va="center",
                    fontsize=6, transform=ax.transAxes)
            continue
        if s["dim"] == 2:
            order = np.argsort(s["x"])
            ax.plot(s["x"][order], s["slip"][order], lw=1,
                    color="C%d" % OUTCOMES.index(r["outcome"]))
        else:
            ax.tricontourf(s["x"], s["y"], s["slip"], 20, cmap="viridis")
            ax.invert_yaxis()
    fig.suptitle("Final slip (m) along the fault (km); case: " +
                 ", ".join(v["alias"] for v in sweep["vary"]), fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "final-slip.png"), dpi=110)
    plt.close(fig)

    if cycle_runs:
        plot_cycles(sweep, rows)
        return ["outcome-map.png", "magnitude.png", "final-slip.png",
                "cycles.png"]
    return ["outcome-map.png", "magnitude.png", "final-slip.png"]


def plot_cycles(sweep, rows):
    """cycles.png for a sweep over earthquake cycles: the recurrence, the
    slip per event and the events' peak slip rate against the first varied
    entry, one line per value of the second."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    aliases = [v["alias"] for v in sweep["vary"]]
    x = aliases[0]
    group = aliases[1] if len(aliases) > 1 else None
    groups = sorted({r[group] for r in rows}, key=float) if group else [None]
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.6))
    keys = (("recurrence", "recurrence (years)"),
            ("event slip", "slip per event (m)"),
            ("event peak slip rate", "event peak slip rate (m/s)"))
    xs_all = [float(r[x]) for r in rows]
    log_x = min(xs_all) > 0 and max(xs_all) >= 4 * min(xs_all)
    for g in groups:
        sub = sorted((r for r in rows if group is None or r[group] == g),
                     key=lambda r: float(r[x]))
        for ax, (key, label) in zip(axes, keys):
            pts = [(float(r[x]), r[key]) for r in sub
                   if r.get(key) is not None]
            if pts:
                ax.plot(*zip(*pts), "o-",
                        label=f"{group} = {g}" if group else None)
            ax.set_xlabel(x)
            ax.set_ylabel(label)
            ax.grid(alpha=0.3)
            if log_x:
                ax.set_xscale("log")
    axes[2].set_yscale("log")
    if group:
        axes[0].legend(fontsize=8)
    fig.suptitle(sweep["title"] + "\nthe events after the first two",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(sweep["output"], "cycles.png"), dpi=110)
    plt.close(fig)
