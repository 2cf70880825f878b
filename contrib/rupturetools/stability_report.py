"""The stability study (contrib/stability-study): the Markdown report."""

import datetime
import os
import platform
import re
import subprocess

from .stability_cases import BASES, FAMILIES, SCHEME_LABEL, fmt

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

# ---------------------------------------------------------------------------
# The report.

def cell_energy(r):
    if r["rel_energy"] is None:
        return "-"
    text = "%.1e" % r["rel_energy"]
    if r["own_verdict"] == "no":
        text += " (!)"
    return text


def cell_slip(r):
    if r["max_slip"] is None:
        return "-"
    text = fmt(r["max_slip"], 4)
    if r["analytic"]:
        text += " (%+.2g %%)" % (100 * (r["max_slip"] - r["analytic"]) / r["analytic"])
    return text


def cell_result(r):
    text = r["result"]
    if r["nonfinite"]:
        text += ", NOT FINITE in statistics"
    return text


def table(cases, results):
    lines = ["| case | value | scheme | result | steps | steps cut | max Newton its | "
             "rel. energy-balance error | max slip at the end (vs 1-D analytic) | diagnosis |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for c, r in zip(cases, results):
        name = c.base + (", " + c.name if c.name else "")
        steps = "-" if r["steps"] is None else str(r["steps"])
        m = re.search(r"[Aa]t step (\d+)|in step (\d+)", r["error"])
        if r["steps"] is None and m:
            steps = "stopped in %s" % (m.group(1) or m.group(2))
        if r["dt"] is not None:
            steps += " x %s s" % fmt(r["dt"])
        newton = "-" if c.scheme == "explicit" or r["max_newton"] is None else str(r["max_newton"])
        diagnosis = r["diagnosis"]
        if r["timeout"]:
            diagnosis = "no diagnosis: stopped by the study's time limit of %d s%s" % (
                r["wall"], (", at t = %s s of %s s" % (fmt(r["last_t"]), fmt(r["end"])))
                if r["last_t"] is not None else "")
        lines.append("| %s | %s | %s | %s | %s | %d | %s | %s | %s | %s |" % (
            name, c.value, SCHEME_LABEL[c.scheme], cell_result(r), steps, r["cuts"],
            newton, cell_energy(r), cell_slip(r), diagnosis))
    return "\n".join(lines) + "\n"


def listing(items, limit=8):
    items = list(items)
    if len(items) > limit:
        return ", ".join(items[:limit]) + " and %d more" % (len(items) - limit)
    return ", ".join(items)


def describe(c):
    return "%s %s (%s%s)" % (c.base, c.value, c.scheme, ", " + c.name if c.name else "")


def summary(family, cases, results):
    """Sentences computed from the measured results only."""
    out = []
    pairs = list(zip(cases, results))
    n = len(pairs)
    ran = [(c, r) for c, r in pairs if r["result"] in ("ok", "ran, balance off")]
    ok = [(c, r) for c, r in pairs if r["result"] == "ok"]
    failed = [(c, r) for c, r in pairs if r["result"].startswith("failed")]
    other = [(c, r) for c, r in pairs if not r["result"].startswith("failed") and (c, r) not in ran]
    refused = [c for c, r in failed if r["refused"]]
    out.append("%d case%s: %d ran to the end%s, %d stopped with a diagnosis%s%s."
               % (n, "s" if n != 1 else "", len(ran),
                  " (%s within the program's own energy tolerance)"
                  % ("all" if len(ok) == len(ran) else "%d of them" % len(ok)) if ran else "",
                  len(failed),
                  " (%d of them refused by the input checks)" % len(refused) if refused else "",
                  (", %d timed out or crashed (%s)" % (len(other), listing(describe(c) for c, _ in other)))
                  if other else ""))
    cut = [(c, r) for c, r in pairs if r["cuts"]]
    if cut:
        out.append("Steps were cut in %s." % listing("%s: %d" % (describe(c), r["cuts"]) for c, r in cut))
    elif any(c.scheme != "explicit" for c, _ in pairs):
        out.append("No step was cut.")
    newton = [(c, r) for c, r in ran if c.scheme != "explicit" and r["max_newton"] is not None]
    if newton:
        lo = min(r["max_newton"] for _, r in newton)
        hi = max(r["max_newton"] for _, r in newton)
        worst = [describe(c) for c, r in newton if r["max_newton"] == hi]
        if lo == hi:
            out.append("The most Newton iterations in a step were %d in every implicit run that "
                       "finished." % hi)
        else:
            out.append("The most Newton iterations in a step of the implicit runs that finished "
                       "ranged from %d to %d (%d in %s)."
                       % (lo, hi, hi, listing(worst, 4)))
    for label, schemes in (("implicit", ("implicit", "implicit-gmres")), ("explicit", ("explicit",))):
        e = [(c, r) for c, r in ran if c.scheme in schemes and r["rel_energy"] is not None]
        if e:
            lo = min(r["rel_energy"] for _, r in e)
            hi = max(r["rel_energy"] for _, r in e)
            c_hi = [describe(c) for c, r in e if r["rel_energy"] == hi][0]
            if len(e) == 1 or "%.1e" % lo == "%.1e" % hi:
                out.append("Relative energy-balance error of the %s run%s: %.1e."
                           % (label, "s" if len(e) > 1 else "", hi))
            else:
                out.append("Relative energy-balance error of the %s runs that finished: %.1e to %.1e "
                           "(largest: %s)." % (label, lo, hi, c_hi))
    off = [(c, r) for c, r in ran if r["own_verdict"] == "no"]
    if off:
        out.append("Ran to the end with an energy balance above the program's own tolerance "
                   "(marked (!)): %s." % listing(describe(c) for c, _ in off))
    a = [(c, r) for c, r in ok if r["analytic"]]
    if a:
        errs = [(abs(r["max_slip"] - r["analytic"]) / r["analytic"], c) for c, r in a]
        errs.sort(key=lambda x: x[0])
        if len(errs) == 1 or "%.2g" % errs[0][0] == "%.2g" % errs[-1][0]:
            out.append("Slip against the 1-D analytic solution: %.2g %% off." % (100 * errs[-1][0]))
        else:
            out.append("Slip against the 1-D analytic solution (runs within the energy tolerance): "
                       "%.2g %% to %.2g %% off (largest: %s)."
                       % (100 * errs[0][0], 100 * errs[-1][0], describe(errs[-1][1])))
    for c, r in failed:
        out.append("%s stopped: %s" % (describe(c)[0].upper() + describe(c)[1:],
                                       r["diagnosis"] if r["diagnosis"].endswith(".") else r["diagnosis"] + "."))
    # Family-specific observations, from the numbers.
    # In-plane implicit runs next to the explicit run of the same case (an
    # implicit variant such as "c_p = ..., dt = 0.005 s" pairs with "c_p = ...").
    both = []
    apart = []
    explicit = {(c.value, c.name): r for c, r in pairs
                if c.base == "inplane" and c.scheme == "explicit"}
    for c, r in pairs:
        if (c.base != "inplane" or c.scheme != "implicit" or r["max_slip"] is None
                or r["result"] not in ("ok", "ran, balance off")):
            continue
        plain, _, variant = c.name.partition(", ")
        r2 = (explicit.get((c.value, c.name)) or explicit.get((c.value, plain))
              or explicit.get((c.value, "")))
        if r2 and r2["max_slip"] is not None and r2["result"] in ("ok", "ran, balance off"):
            label = c.value + (", " + c.name if c.name else "")
            both.append("%s: %s / %s" % (label, fmt(r["max_slip"]), fmt(r2["max_slip"])))
            a, b = r["max_slip"], r2["max_slip"]
            if abs(a - b) > 0.25 * max(abs(a), abs(b)):
                apart.append(label)
    if both:
        out.append("In-plane, the largest slip at the end, implicit (direct solver) / explicit: %s."
                   % "; ".join(both))
    if apart:
        out.append("**The two methods disagree** (by more than 25 %% in the slip) in: %s; see "
                   "the family's introduction." % listing(apart))
    if family == "opening":
        out.append("The most fault nodes open at any step: %s." % "; ".join(
            "%s: %s" % (describe(c), "-" if r["max_open"] is None else "%d" % r["max_open"])
            for c, r in pairs))
    if family == "time step":
        for base in ("column", "inplane"):
            ex = [(c, r) for c, r in pairs if c.base == base and c.scheme == "explicit"
                  and "Allow unstable time step=true" in c.sets]
            if ex:
                fine = [c.dt_factor for c, r in ex if r["result"] == "ok" and r["own_verdict"] == "yes"]
                bad = [c.dt_factor for c, r in ex if not (r["result"] == "ok" and r["own_verdict"] == "yes")]
                text = "Explicit, %s base: " % base
                text += ("the largest step that ran to the end within the energy tolerance was %g dt_c"
                         % max(fine)) if fine else "no step ran within the energy tolerance"
                text += ("; the smallest that did not, %g dt_c." % min(bad)) if bad else "; every step did."
                out.append(text)
    if family in ("penalty", "slip-weakening distance", "strength drop"):
        weak = []
        for c, r in pairs:
            if c.scheme == "explicit":
                continue
            b = BASES[c.base]
            value = {"Tangential penalty": b["penalty"], "Dynamic friction coefficient": b["mu_d"],
                     "Slip-weakening distance": b["dc"]}
            for entry in c.sets:
                key, _, v = entry.rpartition("=")
                key = key.split("/")[-1]
                if key in value:
                    value[key] = float(v)
            if value["Slip-weakening distance"] <= 0 or r["refused"]:
                continue
            slope = b["sigma"] * (b["mu_s"] - value["Dynamic friction coefficient"]) \
                / value["Slip-weakening distance"]
            if value["Tangential penalty"] < slope:
                weak.append("%s (%s)" % (describe(c), r["result"]))
        if weak:
            out.append("Penalty below the slip-weakening slope (mu_0 - mu_d) |T_n| / L_d, "
                       "below which the return mapping drops a node's traction to its "
                       "residual strength within one step (manual, choosing the "
                       "penalties): %s." % listing(weak))
    bugs = [(c, r) for c, r in pairs if r["bug"]]
    if bugs:
        out.append("**Possible bugs**: %s." % listing(
            "%s: %s" % (describe(c), cell_result(r)) for c, r in bugs))
    return " ".join(out)


def machine():
    cpu = ""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return "%s, %d cores%s" % (platform.node() or "unknown host", os.cpu_count() or 0,
                                " (%s)" % cpu if cpu else "")


def measurement(args, wall, stable, runs):
    """What the report says about the run itself."""
    try:
        commit = subprocess.run(["git", "-C", TOP, "rev-parse", "--short", "HEAD"],
                                capture_output=True, text=True).stdout.strip()
    except OSError:
        commit = ""
    return dict(date=datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), machine=machine(),
                jobs=args.jobs, timeout=args.timeout, quick=args.quick, wall=wall,
                stable=stable, runs=runs, commit=commit,
                rupture=os.path.relpath(args.rupture, TOP)
                if args.rupture.startswith(TOP + os.sep) else args.rupture)


def report(cases, results, meta):
    stable = meta["stable"]
    t = []
    t.append("# Stability on stiff and extreme cases\n")
    t.append("Generated by `contrib/stability-study`%s; do not edit by hand. "
             "Measured on %s, %d case(s) at a time, on %s, with the binary `%s`%s. "
             "The whole study took %.0f s of wall time (%d cases, %d distinct runs, "
             "a limit of %d s per run).\n"
             % (" --quick" if meta["quick"] else "", meta["date"], meta["jobs"], meta["machine"],
                meta["rupture"], " at commit %s" % meta["commit"] if meta["commit"] else "",
                meta["wall"], len(cases), meta["runs"], meta["timeout"]))
    t.append("""\
Each case is a base parameter file with `--set` overrides, run once; the
families vary the penalty stiffness, the slip-weakening distance, the
strength drop, the time step, Poisson's ratio, the material contrast across
the fault and the normal traction (faults that open), and for the
rate-and-state family a - b, L, the initial slip rate, the time step,
Chester's frictional heating and Cochard-Madariaga weakening. Three bases:

- **column**: the 1-D plane-wave column of `tests/fault/inputs/plane_wave.prm`
  (non-dimensional: rho = c_s = 1, c_p = 2, h = 0.05, so mu = 1 and the
  stiffness of a fault-adjacent element is k_e = mu / h = 20 Pa/m; sigma_n =
  10, tau_0 = 6.1, mu_0 = 0.6, mu_d = 0.5, L_d = 1, penalties 1e5 =
  5000 k_e; dt = 0.01 implicit, 0.5 dt_c explicit; to t = 3). Its slip
  has an analytic solution (below), so the table also shows how far off the
  slip is.
- **inplane**: a coarse 2-D in-plane rupture after TPV205-2D (30 km x 15 km,
  625 m cells, 2652 DoFs, absorbing boundaries, a fault on y = 0 for
  abs(x) <= 9 km, TPV3 material and friction: sigma_n = 120 MPa, tau_0 = 70
  MPa, 81.6 MPa on abs(x) <= 1.5 km, mu_0 = 0.677, mu_d = 0.525, L_d = 0.4
  m; penalties 5e11 Pa/m, about 1e4 k_e; dt = 0.02 s implicit, 0.5 dt_c
  explicit; to t = 3 s). P waves, normal-stress changes and Poisson's ratio
  matter here.
- **rscolumn**: the column with rate-and-state friction instead of slip
  weakening (as `tests/fault/rate_and_state_column.cc`: regularised aging
  law, a = 0.008, b = 0.012, L = 0.1, f0 = 0.6, V0 = 1, theta(0) = 1,
  tau_0 = 6.5, sigma_n = 10; the slip rate rises to the steady state V = 1),
  and the other laws of the family on the same column. No analytic slip
  is shown for it.

Schemes: implicit Newmark (average acceleration) with penalty contact and
the direct solver (MUMPS, as the plane-wave test uses), or with the default
iterative solver (GMRES + AMG) in the penalty family; explicit central
difference with traction at split nodes (no penalty). Stable explicit steps
dt_c reported by the program (summary.json): %s.

Re-run with `contrib/stability-study` (all cases, writes this file; `--jobs
2` on two cores) or `contrib/stability-study --quick` (a handful of cheap
cases checked against their expected outcome, tables to stdout, for the
test suite). `--only REGEX --keep` re-runs single cases and prints their
command lines.

Columns:

- **result**: ok (exit code 0 and the program's own end-of-run energy
  check passed), ran, balance off (exit code 0, but that check failed),
  failed (exit code 1 with an `Error:` message), timeout, or crashed (a
  signal or another exit code).
- **steps**: steps done x the step size (a run that stops still writes
  its `statistics` up to the last step it finished, which the columns
  then show; the diagnosis names the step that failed; "-" where the
  input checks refused the run before its first step).
- **steps cut**: the steps cut in half (the run's summary.json, "step cuts").
- **max Newton its**: the most Newton iterations of a (sub)step that
  converged (implicit only; an attempt that failed and was cut used up
  `Solver/Maximum Newton iterations` = 25).
- **rel. energy-balance error**: the last row's balance error (kinetic +
  strain + dissipated + work done on the fault - work of loads - initial
  energy; the frictional dissipation is part of the work done on the fault)
  divided by the energy scale max(abs(kinetic) + abs(strain), abs(work),
  abs(dissipated), abs(fault work), abs(initial energy)), as the program
  checks it at the end of a run. (!) marks a value above the program's own
  tolerance (1e-8 implicit, 1e-2 explicit).
- **max slip**: the largest slip on the fault at the end; for the shear
  column, in brackets, its deviation from the 1-D analytic slip: with
  eta = 1 / (1/Z+ + 1/Z-) (Z = rho c_s on either side), A = tau_0 -
  sigma_n mu_0 and W = sigma_n (mu_0 - mu_d) / L_d, s = A/W (exp(W t /
  eta) - 1) until s = L_d at t_w = eta / W ln(1 + W L_d / A), then slip
  rate (tau_0 - sigma_n mu_d) / eta.
- **diagnosis**: the cause in the program's `Error:` message (its first
  sentence and the ones naming a cause), shortened.
""" % ", ".join("%s %s s" % (b, fmt(v, 6)) for b, v in sorted(stable.items())))
    for key, title, text in FAMILIES:
        pairs = [(c, r) for c, r in zip(cases, results) if c.family == key]
        if not pairs:
            continue
        cs, rs = zip(*pairs)
        t.append("## %s\n" % title)
        t.append(text + "\n")
        t.append(table(cs, rs))
        t.append(summary(key, cs, rs) + "\n")
    return "\n".join(t)
