"""The stability study (contrib/stability-study): running one case and
reading what it wrote (summary.json, statistics)."""

import math
import os
import re
import subprocess
import sys
import time

from . import runs
from .stability_cases import BASES, SCHEMES, analytic_slip

# ---------------------------------------------------------------------------
# Running one case.

class Runner:
    def __init__(self, binary, workdir, timeout):
        self.binary = binary
        self.workdir = workdir
        self.timeout = timeout
        self.prm = {}
        for name, base in BASES.items():
            path = os.path.join(workdir, name + ".prm")
            with open(path, "w") as f:
                f.write(base["prm"])
            self.prm[name] = path
        self.stable = {}

    def command(self, base, sets, outdir):
        args = [self.binary, self.prm[base]]
        for s in sets + ["Output directory=" + outdir]:
            args += ["--set", s]
        return args

    def stable_step(self, base):
        """The stable explicit step of a base, from a one-step run."""
        if base not in self.stable:
            outdir = os.path.join(self.workdir, "probe-" + base)
            sets = scheme_sets("explicit") + ["Time integration/Time step=0",
                                              "Time integration/End time=1e-9"]
            out = subprocess.run(self.command(base, sets, outdir),
                                 capture_output=True, text=True, timeout=self.timeout)
            summary = runs.summary(outdir) or {}
            if not summary.get("stable time step"):
                sys.exit("could not read the stable explicit time step of base %s from "
                         "%s/summary.json:\n%s" % (base, outdir, out.stderr))
            self.stable[base] = float(summary["stable time step"])
        return self.stable[base]

    def case_sets(self, case):
        b = BASES[case.base]
        sets = scheme_sets(case.scheme)
        end = case.end if case.end is not None else b["end"]
        if case.dt_factor is not None:
            dt = case.dt_factor * self.stable_step(case.base)
            end = max(end, 200 * dt)
            sets.append("Time integration/Time step=%.9g" % dt)
        if case.scheme == "explicit":
            # No Newton iterations to read per step; keep the screen short.
            sets.append("Output/Screen output interval=1000")
        sets.append("Time integration/End time=%.9g" % end)
        return sets + case.sets, end

    def run(self, case, index):
        sets, end = self.case_sets(case)
        outdir = os.path.join(self.workdir, "case-%03d" % index)
        args = self.command(case.base, sets, outdir)
        r = dict(args=args, end=end, timeout=False, rc=None, stdout="", stderr="")
        start = time.time()
        try:
            out = subprocess.run(args, capture_output=True, text=True,
                                 timeout=self.timeout)
            r.update(rc=out.returncode, stdout=out.stdout, stderr=out.stderr)
        except subprocess.TimeoutExpired as e:
            r["timeout"] = True
            r["stdout"] = e.stdout.decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
        r["wall"] = time.time() - start
        analyse(case, r, outdir)
        return r


def scheme_sets(scheme):
    model, integrator, solver = SCHEMES[scheme]
    s = ["Fault/Model=" + model, "Time integration/Scheme=" + integrator]
    if integrator.startswith("explicit"):
        s.append("Time integration/Time step=0")
    if solver:
        s.append("Solver/Linear solver=" + solver)
    return s


def read_statistics(path):
    """Column index by header name, and the rows (as floats; 'nan' and 'inf'
    are kept as such)."""
    columns, rows = {}, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                m = re.match(r"#\s*(\d+):\s*(.*)", line)
                if m:
                    columns[m.group(2).strip()] = int(m.group(1)) - 1
            elif line.strip():
                rows.append([float(x) for x in line.split()])
    return columns, rows


def column(columns, prefix):
    for name, index in columns.items():
        if name.startswith(prefix):
            return index
    raise KeyError("statistics has no column '%s...' (columns: %s)"
                   % (prefix, ", ".join(columns)))


def shorten(message, limit=260):
    """The cause of an Error message: its first sentence and any later one
    that names a cause or the step cuts, not the advice."""
    text = " ".join(message.split())
    sentences = re.split(r"(?<=[.;])\s+(?=[A-Z<(])", text)
    keep = [sentences[0]]
    for s in sentences[1:]:
        if re.search(r"steeper|blew up|cut \d+ times|indefinite|above the stable", s):
            keep.append(s)
    text = " ".join(keep)
    if len(text) > limit:
        text = text[:limit - 3].rstrip() + "..."
    # Markdown: parameter names as code (so <...> is not taken for HTML).
    text = re.sub(r"<([^<>]+)>", r"`\1`", text)
    return text.replace("|", "\\|")


def compare_analytic(case, r):
    """The 1-D analytic slip at the end time, for the cases that have one."""
    r["analytic"] = None
    if case.analytic is not None and r["max_slip"] is not None:
        b = BASES[case.base]
        p = dict(tau0=b["tau0"], sigma=b["sigma"], mu_s=b["mu_s"], mu_d=b["mu_d"],
                 dc=b["dc"], z_plus=b["rho"] * b["cs"], z_minus=b["rho"] * b["cs"])
        p.update(case.analytic)
        r["analytic"] = analytic_slip(r["end"], **p)


def analyse(case, r, outdir):
    # What the run reports in its files: summary.json (written when the
    # output directory was opened, also for a failed run) and statistics.
    summary = runs.summary(outdir)
    facts = summary or {}
    r["cuts"] = int(facts.get("step cuts") or 0)
    r["dt"] = facts.get("time step")
    r["dt_stable"] = facts.get("stable time step")
    balance = facts.get("energy balance")
    r["own_tolerance"] = balance["tolerance"] if balance else None
    r["own_verdict"] = ("yes" if balance["within"] else "no") if balance else None
    r["last_t"] = None
    newton = []
    error = ""
    if "Error:" in r["stderr"]:
        error = r["stderr"][r["stderr"].index("Error:") + len("Error:"):].strip()
    r["error"] = error
    r["diagnosis"] = shorten(error) if error else ""
    # Refused by the input checks: stopped before the output directory (and
    # with it summary.json) was opened.
    r["refused"] = bool(error) and summary is None
    r["nonfinite"] = False
    r["steps"] = None
    r["rel_energy"] = None
    r["max_slip"] = None
    r["max_open"] = None
    stats = os.path.join(outdir, "statistics")
    if os.path.exists(stats):
        columns, rows = read_statistics(stats)
        if rows:
            r["nonfinite"] = any(not math.isfinite(x) for row in rows for x in row)
            first, last = rows[0], rows[-1]
            k, s, w, d, e, fw = (column(columns, p) for p in (
                "Kinetic energy", "Strain energy", "Work of loads",
                "Energy dissipated", "Energy balance error", "Work done on the fault"))
            # The initial energy that the balance subtracts, from row 0.
            initial = first[k] + first[s] + first[d] + first[fw] - first[w] - first[e]
            scale = max(abs(last[k]) + abs(last[s]), abs(last[w]), abs(last[d]),
                        abs(last[fw]), abs(initial), 1e-300)
            r["rel_energy"] = abs(last[e]) / scale
            r["steps"] = int(last[0])
            r["last_t"] = last[column(columns, "Time (s)")]
            newton.append(int(max(row[column(columns, "Newton iterations")] for row in rows)))
            r["max_slip"] = last[column(columns, "Maximum slip")]
            r["max_open"] = max(row[column(columns, "Open fault nodes")] for row in rows)
    r["max_newton"] = max(newton) if newton else None
    compare_analytic(case, r)

    if r["timeout"]:
        r["result"] = "timeout"
    elif r["rc"] is not None and r["rc"] < 0:
        r["result"] = "crashed (signal %d)" % -r["rc"]
    elif r["rc"] not in (0, 1):
        r["result"] = "crashed (exit code %d)" % r["rc"]
    elif r["rc"] == 1:
        r["result"] = "failed" if error else "failed (no message)"
    elif r["own_verdict"] == "no":
        # Ran to the end, but the program's own energy check failed.
        r["result"] = "ran, balance off"
    else:
        r["result"] = "ok"
    r["bug"] = r["result"].startswith("crashed") or r["result"] == "failed (no message)" or r["nonfinite"]
