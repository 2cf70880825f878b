"""The order in time of the split-node fault update, law by law.

The case is the 1-D column of tests/fault/inputs/plane_wave.prm
(non-dimensional: rho = c_s = 1, c_p = 2, cells of 0.05, absorbing ends at
y = -4 and 4) with the traction-at-split-node method of the explicit
scheme, a normal traction of -10 and a shear load that rises from 5 to 9
over t in [0, 1], holds until t = 3 and falls to 1 at t = 4: the fault
nucleates, slips fast, and stops. Each friction law runs with parameters
of its own (LAWS) at time steps dt = END / N for a list of N, with the
time-centred update ('centred') and the former one ('end of step'), and
once at a much smaller step with the centred update: the reference. At
fixed h the errors against it are the time error alone.

Measured per run (all at times that every step divides, so that nothing
is interpolated but the onset): the slip at t = 2, 4 and 6, the shear
traction at t = 2 and 4, the peak slip rate, and the onset (the time the
slip rate first exceeds 1, interpolated between steps).
"""

import json
import math
import os

from rupturetools import files, runs

END = 6.0
TIMES = (2.0, 4.0, 6.0)
ONSET_RATE = 1.0

BASE = [
    "Fault/Model=traction at split nodes",
    "Fault/Initial traction=5; -10",
    "Fault/Traction perturbation/Traction=1; 0",
    "Fault/Traction perturbation/Time function=(t < 1) ? 4 * t : "
    "((t < 3) ? 4 : ((t < 4) ? 4 - 8 * (t - 3) : -4))",
    "Fault/Output/Stations=fault: 0.025, 0",
    "Time integration/Scheme=explicit central difference",
    "Time integration/End time=%g" % END,
    "Output/Screen output interval=1000000",
]


def _law(name, section, values):
    return [name, ["Fault/Friction law=" + name.split(" (")[0]] +
            ["Fault/%s/%s=%s" % (section, k, v) for k, v in values]]


_RS = [("Direct effect", 0.01), ("Evolution effect", 0.014),
       ("Characteristic slip distance", 0.05),
       ("Reference friction coefficient", 0.6),
       ("Reference slip rate", 1e-6), ("Initial slip rate", 1e-16)]

#: name -> the --set entries of the law (section names as in the
#: parameter file).
LAWS = dict([
    _law("rate and state", "Rate and state", _RS),
    ["rate and state (slip law)",
     _law("rate and state", "Rate and state",
          _RS + [("Evolution law", "slip")])[1]],
    _law("slowness law", "Slowness law",
         [("Static friction coefficient", 0.6), ("Direct effect", 0.01),
          ("Evolution effect", 0.014),
          ("Characteristic slip distance", 0.05),
          ("Initial slip rate", 1e-16)]),
    _law("two state variables", "Two state variables",
         [("Static friction coefficient", 0.6), ("Direct effect", 0.01),
          ("Evolution effect 1", 0.007), ("Evolution effect 2", 0.007),
          ("Slip distance 1", 0.05), ("Slip distance 2", 0.2),
          ("Reference slip rate", 1e-6), ("Initial slip rate", 1e-16)]),
    _law("flash heating", "Flash heating",
         [("Direct effect", 0.01), ("Evolution effect", 0.014),
          ("Characteristic slip distance", 0.05),
          ("Reference friction coefficient", 0.6),
          ("Reference slip rate", 1e-6), ("Weakening slip rate", 0.1),
          ("Weakened friction coefficient", 0.2),
          ("Initial slip rate", 1e-16)]),
    _law("chester", "Chester",
         [("Direct effect", 0.01), ("Evolution effect", 0.014),
          ("Characteristic slip distance", 0.05),
          ("Reference friction coefficient", 0.6),
          ("Reference slip rate", 1e-6), ("Heat capacity per area", 0.05),
          ("Initial slip rate", 1e-16)]),
    _law("cochard madariaga", "Cochard Madariaga",
         [("Maximum traction drop", 1), ("Reference slip rate", 4),
          ("Residual strength", 5)]),
])

UPDATES = ("centred", "end of step")


def case_sets(law, update, n):
    """The --set entries of one run."""
    return (BASE + LAWS[law] +
            ["Fault/Split-node friction time=" + update,
             "Time integration/Time step=%r" % (END / n)])


def measure(directory):
    """The measured quantities of a finished run's station file."""
    s = files.read_station(os.path.join(directory, "fault.dat"))
    t = s["t"]
    slip, rate, shear = s["h-slip"], s["h-slip-rate"], s["h-shear-stress"]

    def at(values, time):
        # A row at the time itself (every step divides it).
        i = min(range(len(t)), key=lambda k: abs(t[k] - time))
        if abs(t[i] - time) > 1e-9 * max(1.0, time):
            raise ValueError("%s: no row at t = %g" % (directory, time))
        return values[i]

    m = {"slip %g" % x: at(slip, x) for x in TIMES}
    m.update({"traction %g" % x: at(shear, x) for x in TIMES[:2]})
    m["peak slip rate"] = max(abs(v) for v in rate)
    m["onset"] = files.crossing_time(t, rate, ONSET_RATE)
    return m


#: The errors reported: name -> (quantities, relative?)
ERRORS = {
    "slip": (["slip %g" % x for x in TIMES], True),
    "traction": (["traction %g" % x for x in TIMES[:2]], True),
    "peak slip rate": (["peak slip rate"], True),
    "onset": (["onset"], False),
}


def errors(m, ref):
    """The largest error of each kind of m against the reference ref."""
    out = {}
    for kind, (keys, relative) in ERRORS.items():
        e = 0.0
        for k in keys:
            if m[k] is None or ref[k] is None:
                e = float("nan")
                break
            d = abs(m[k] - ref[k])
            e = max(e, d / abs(ref[k]) if relative and ref[k] else d)
        out[kind] = e
    return out


def observed_order(e1, e2, c1, c2):
    """The observed order between error @p e1 at step (or Courant
    fraction) @p c1 and @p e2 at @p c2, log(e1/e2)/log(c1/c2); None where
    an error is zero or not finite."""
    if not (e1 > 0 and e2 > 0 and math.isfinite(e1) and math.isfinite(e2)):
        return None
    return math.log(e1 / e2) / math.log(c1 / c2)


def orders(values):
    """The observed orders of successive errors, the step halving each
    time (nan where one is zero or not finite)."""
    return [float("nan") if q is None else q
            for q in (observed_order(a, b, 2, 1) for a, b in zip(values, values[1:]))]


PRM = os.path.join(runs.TOP, "tests", "fault", "inputs", "plane_wave.prm")


def study(rupture, work, steps, reference_steps, laws, jobs=1):
    """Run every case (reusing finished ones) and return the results:
    {law: {"reference": m, update: {n: (m, errors, seconds)}}}."""
    cases = []
    for law in laws:
        cases.append((law, "centred", reference_steps))
        for update in UPDATES:
            for n in steps:
                cases.append((law, update, n))

    def directory(law, update, n):
        return os.path.join(work, "%s-%s-%d" % (law.replace(" ", "_").replace(
            "(", "").replace(")", ""), update.replace(" ", "_"), n))

    runs.run_many(rupture, PRM,
                  [(directory(*c), case_sets(*c)) for c in cases],
                  jobs=jobs)
    results = {}
    for law in laws:
        ref = measure(directory(law, "centred", reference_steps))
        entry = {"reference": ref}
        for update in UPDATES:
            entry[update] = {}
            for n in steps:
                d = directory(law, update, n)
                m = measure(d)
                entry[update][n] = {"values": m, "errors": errors(m, ref),
                                    "seconds": runs.wall_time(d)}
        results[law] = entry
    return results


def markdown(results, steps):
    """Tables of the errors and observed orders, one row per law and
    update."""
    lines = []
    for kind, (keys, relative) in ERRORS.items():
        lines.append("")
        lines.append("**%s** (%s error against the reference; observed "
                     "order when the step halves in brackets)" %
                     (kind, "relative" if relative else "absolute"))
        lines.append("")
        lines.append("| law | update | " +
                     " | ".join("dt = %.4g" % (END / n) for n in steps) + " |")
        lines.append("|---|---|" + "---|" * len(steps))
        for law, entry in results.items():
            for update in UPDATES:
                e = [entry[update][n]["errors"][kind] for n in steps]
                o = orders(e)
                cells = ["%.2e" % e[0]] + ["%.2e (%.1f)" % (x, p)
                                            for x, p in zip(e[1:], o)]
                lines.append("| %s | %s | %s |" % (law, update,
                                                   " | ".join(cells)))
    return "\n".join(lines) + "\n"


def plot(results, steps, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    kinds = list(ERRORS)
    fig, axes = plt.subplots(1, len(kinds), figsize=(4.2 * len(kinds), 4.2))
    dts = [END / n for n in steps]
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for ax, kind in zip(axes, kinds):
        for i, (law, entry) in enumerate(results.items()):
            for update, style in zip(UPDATES, ("-o", "--x")):
                e = [entry[update][n]["errors"][kind] for n in steps]
                ax.loglog(dts, e, style, color=colours[i % len(colours)],
                          label="%s, %s" % (law, update) if kind == kinds[0]
                          else None, markersize=4)
        x0, x1 = dts[0], dts[-1]
        y0 = max(entry["centred"][steps[0]]["errors"][kind]
                 for entry in results.values())
        if y0 > 0:
            ax.loglog([x0, x1], [y0, y0 * (x1 / x0) ** 2], ":k", lw=1)
            ax.loglog([x0, x1], [y0, y0 * (x1 / x0)], "-.k", lw=1)
        ax.set_xticks(dts)
        ax.set_xticks([], minor=True)
        ax.set_xticklabels(["%.4g" % x for x in dts])
        ax.set_xlabel("time step dt")
        ax.set_title(kind + (" (relative)" if ERRORS[kind][1] else ""))
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("error against the reference")
    fig.legend(loc="lower center", ncol=4, fontsize=7)
    fig.suptitle("Split-node fault update on the 1-D column: solid centred "
                 "(second order), dashed end of step (first order); dotted "
                 "slope 2, dash-dotted slope 1", fontsize=9)
    fig.tight_layout(rect=(0, 0.12, 1, 0.95))
    fig.savefig(path, dpi=110)


def write(results, steps, reference_steps, directory, name):
    os.makedirs(directory, exist_ok=True)
    table = markdown(results, steps)
    with open(os.path.join(directory, name + ".md"), "w") as f:
        f.write("<!-- made by contrib/fault-time-order; do not edit -->\n")
        f.write("Reference: the centred update at dt = %.3g (N = %d).\n"
                % (END / reference_steps, reference_steps))
        f.write(table)
    with open(os.path.join(directory, name + ".json"), "w") as f:
        json.dump({"steps": steps, "reference steps": reference_steps,
                   "results": results}, f, indent=1, default=str)
    plot(results, steps, os.path.join(directory, name + ".png"))
    return table
