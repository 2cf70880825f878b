"""Parameter sweeps (contrib/sweep): running the cases, here (--jobs at a
time, resuming finished ones) or as a Slurm job array."""

import json
import os
import re
import shlex
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

from . import runs
from .sweep_files import (TOP, SweepError, case_name, case_prm, format_value, read_json,
                          shown, write_atomically)

# ------------------------------------------------------------------ running

def sweep_record(sweep, cases):
    """What DIR/sweep.json holds: enough to run any case by its index."""
    return {"sweep file": sweep["file"], "base": sweep["base"],
            "ranks": sweep["ranks"],
            "entries": [v["entry"] for v in sweep["vary"]],
            "aliases": [v["alias"] for v in sweep["vary"]],
            "cases": [[format_value(c[v["alias"]]) for v in sweep["vary"]]
                      for c in cases],
            "set": [[n, v] for n, v, _ in sweep["set"]]}


def prepare(sweep, cases):
    """Create DIR and DIR/sweep.json; refuse a directory that holds another
    sweep (resuming it would mix cases of two designs)."""
    out = sweep["output"]
    os.makedirs(out, exist_ok=True)
    record = sweep_record(sweep, cases)
    path = os.path.join(out, "sweep.json")
    if os.path.exists(path):
        with open(path) as f:
            try:
                old = json.load(f)
            except ValueError:
                old = None
        # The design: what the cases compute (not where the sweep file is,
        # the short names or the ranks).
        design_keys = ("base", "entries", "cases", "set")
        if old is not None and any(old.get(k) != record[k]
                                   for k in design_keys):
            what = [k for k in design_keys if old.get(k) != record[k]]
            raise SweepError(
                f"{out} holds another sweep (its {', '.join(what)} differ "
                f"from {sweep['file']}'s): resuming would mix the cases of "
                "two designs. Give another 'output' (or --output), or "
                "remove that directory.")
    write_atomically(path, json.dumps(record, indent=1) + "\n")
    for i, c in enumerate(cases):
        d = os.path.join(out, case_name(i))
        os.makedirs(d, exist_ok=True)
        write_atomically(os.path.join(d, "case.prm"), case_prm(sweep, i, c))


def case_done(directory):
    summary = read_json(os.path.join(directory, "summary.json"))
    return bool(summary) and summary.get("status") in ("finished",
                                                       "ended early")


def run_case(out, index, rupture):
    """Run one case (the per-case runner of the local and Slurm modes).
    Returns its exit code."""
    record = read_json(os.path.join(out, "sweep.json"))
    if record is None:
        raise SweepError(f"{out} holds no sweep.json: run 'contrib/sweep "
                         "SWEEP_FILE' first")
    if not 0 <= index < len(record["cases"]):
        raise SweepError(f"case {index} does not exist: {out} has "
                         f"{len(record['cases'])} cases (0 to "
                         f"{len(record['cases']) - 1})")
    d = os.path.join(out, case_name(index))
    if case_done(d):
        # (A resubmitted array task, or a resumed sweep: nothing to do.)
        print(f"{case_name(index)}: finished already, kept")
        return 0
    command = [rupture, os.path.join(d, "case.prm")]
    # An interrupted case with a checkpoint continues from it.
    checkpoints = os.path.join(d, "checkpoint")
    if os.path.isdir(checkpoints) and any(
            os.path.isfile(os.path.join(checkpoints, c, "state"))
            for c in os.listdir(checkpoints) if c.startswith("step-")):
        command.append("--resume")
    command = runs.mpi_prefix(record["ranks"]) + command
    env = runs.mpi_env()
    start = time.time()
    with open(os.path.join(d, "run.txt"), "w") as log:
        log.write("$ " + " ".join(shlex.quote(c) for c in command) + "\n")
        log.flush()
        code = subprocess.run(command, stdout=log, stderr=subprocess.STDOUT,
                              env=env).returncode
    write_atomically(os.path.join(d, "case.json"),
                     json.dumps({"index": index, "exit code": code,
                                 "wall time (s)": time.time() - start,
                                 "command": command}, indent=1) + "\n")
    return code


def run_all(sweep, cases, jobs, rupture):
    out = sweep["output"]
    todo = [i for i in range(len(cases))
            if not case_done(os.path.join(out, case_name(i)))]
    kept = len(cases) - len(todo)
    print(f"{len(cases)} cases in {out}: {kept} done already, {len(todo)} "
          f"to run, {jobs} at a time on {sweep['ranks']} rank(s) each",
          flush=True)
    done = [0]

    def one(i):
        code = run_case(out, i, rupture)
        done[0] += 1
        status = "ok" if code == 0 else f"exit code {code}"
        print(f"  [{done[0]}/{len(todo)}] {case_name(i)}: {status}",
              flush=True)
        return code

    with ThreadPoolExecutor(max_workers=jobs) as pool:
        list(pool.map(one, todo))


# -------------------------------------------------------------------- Slurm

def slurm_options(sweep, args):
    """Partition, time, nodes, account and cases per task: the command
    line's, else the sweep file's."""
    keys = sweep["keys"]
    o = {}
    for name in ("partition", "time", "nodes", "account"):
        value = getattr(args, name)
        if value is None and f"slurm {name}" in keys:
            value = keys[f"slurm {name}"][0]
        o[name] = value
    chunk = args.cases_per_task
    if chunk is None:
        value, where = keys.get("slurm cases per task", ("1", "default"))
        try:
            chunk = int(value)
        except ValueError:
            chunk = 0
        if chunk < 1:
            raise SweepError(f"{where}: 'slurm cases per task' must be an "
                             f"integer >= 1, not '{value}'")
    if chunk < 1:
        raise SweepError("--cases-per-task must be at least 1")
    o["chunk"] = chunk
    if o["time"] is not None and not re.fullmatch(
            r"(\d+-)?\d+(:\d+){0,2}", o["time"]):
        raise SweepError(f"the Slurm time limit '{o['time']}' is not one "
                         "Slurm reads (MINUTES, HH:MM:SS or D-HH:MM:SS)")
    if o["nodes"] is not None and not re.fullmatch(r"\d+(-\d+)?",
                                                   o["nodes"]):
        raise SweepError(f"the node count '{o['nodes']}' is not one Slurm "
                         "reads (N or MIN-MAX)")
    return o


def slurm_script(sweep, cases, rupture, options, todo):
    """The batch script of a job array: task t runs the cases
    todo[t*chunk : (t+1)*chunk] through the per-case runner."""
    out = sweep["output"]
    chunk = options["chunk"]
    n_tasks = (len(todo) + chunk - 1) // chunk
    lines = ["#!/bin/bash",
             f"# The Slurm job array of the sweep {sweep['file']},",
             "# written by contrib/sweep --slurm. Each task runs its cases",
             "# through 'contrib/sweep --run-case'; once all are done,",
             f"#   contrib/sweep {shown(sweep['file'])} --summary-only",
             "# makes the summary.",
             "#SBATCH --job-name=rupture-sweep",
             f"#SBATCH --array=0-{n_tasks - 1}",
             f"#SBATCH --ntasks={sweep['ranks']}",
             f"#SBATCH --output={out}/slurm/task-%a.out"]
    for name in ("partition", "time", "nodes", "account"):
        if options[name]:
            lines.append(f"#SBATCH --{name}={options[name]}")
    lines += ["set -u",
              "cases=(" + " ".join(str(i) for i in todo) + ")",
              f"chunk={chunk}",
              "status=0",
              "first=$((SLURM_ARRAY_TASK_ID * chunk))",
              "for ((k = first; k < first + chunk && k < ${#cases[@]}; "
              "++k)); do",
              f"  {sys.executable} {os.path.join(TOP, 'contrib', 'sweep')} --rupture "
              f"{rupture} --run-case {out} \"${{cases[k]}}\" || status=1",
              "done",
              "exit $status"]
    return "\n".join(lines) + "\n", n_tasks


def submit(sweep, cases, rupture, options, wait):
    out = sweep["output"]
    todo = [i for i in range(len(cases))
            if not case_done(os.path.join(out, case_name(i)))]
    if not todo:
        print(f"All {len(cases)} cases in {out} are finished: nothing to "
              "submit.")
        return None
    os.makedirs(os.path.join(out, "slurm"), exist_ok=True)
    text, n_tasks = slurm_script(sweep, cases, rupture, options, todo)
    path = os.path.join(out, "slurm", "sweep.sbatch")
    write_atomically(path, text)
    command = ["sbatch", "--parsable"] + (["--wait"] if wait else []) + \
        [path]
    try:
        result = subprocess.run(command, capture_output=True, text=True)
    except OSError as e:
        raise SweepError(f"cannot run sbatch ({e.strerror}): --slurm needs "
                         "Slurm's commands on this machine. The batch "
                         f"script is {path}.")
    job = result.stdout.strip().split(";")[0]
    if not job:
        raise SweepError("sbatch refused the job array: " +
                         (result.stderr.strip() or "no job id") +
                         f". The batch script is {path}.")
    print(f"Submitted job array {job}: {len(todo)} cases in {n_tasks} "
          f"task(s) of up to {options['chunk']}, {sweep['ranks']} rank(s) "
          f"each ({path})")
    if not wait:
        print(f"When it is done: contrib/sweep {shown(sweep['file'])} "
              "--summary-only" +
              (f" --output {out}" if out != os.path.abspath(
                  sweep["keys"].get("output", ("output-sweep", ""))[0])
               else ""))
    elif result.returncode != 0:
        print(f"Some array tasks failed (sbatch --wait: exit code "
              f"{result.returncode}); see {out}/slurm/task-*.out",
              file=sys.stderr)
    return job
