"""Running rupture from the studies: one run, or many at once, each in an
output directory of its own, reusing runs that finished before."""

import json
import os
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def find_rupture(path=None):
    """The rupture executable: @p path, else the Release build, else the
    Debug build of this tree."""
    for candidate in ([path] if path else
                      [os.path.join(TOP, "build-release", "rupture"),
                       os.path.join(TOP, "build-debug", "rupture")]):
        if candidate and os.access(candidate, os.X_OK):
            return os.path.abspath(candidate)
    sys.exit("no rupture executable: build it with contrib/build Release, "
             "or give --rupture PATH")


def summary(directory):
    """A run's summary.json, or None."""
    try:
        with open(os.path.join(directory, "summary.json")) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def facts(directory):
    """{"dofs", "steps", "memory"} of a run from its summary.json (memory:
    the peak resident memory of the largest rank, GB); exits with a message
    naming the directory when the file or an entry is missing. The studies
    read these numbers from the file the program writes, not from its
    screen output."""
    s = summary(directory)
    if s is None:
        sys.exit("no readable summary.json in %s: did the run start?" % directory)
    try:
        return {"dofs": int(s["dofs"]), "steps": int(s["steps"]),
                "memory": float(s["peak memory, largest rank (B)"]) / 1e9}
    except (KeyError, TypeError, ValueError) as e:
        sys.exit("%s/summary.json: entry %s missing or not a number" % (directory, e))


def finished(directory):
    s = summary(directory)
    return s is not None and s.get("status") in ("finished", "ended early")


def wall_time(directory):
    """The wall time (s) of a finished run's time loop and set-up, from its
    summary.json."""
    s = summary(directory)
    return s.get("wall time") if s else None


def mpi_prefix(ranks):
    """The command that starts @p ranks MPI processes (none for one)."""
    return ["mpirun", "--oversubscribe", "-np", str(ranks)] if ranks > 1 else []


def mpi_env():
    """The environment for mpirun: Open MPI refuses to run as root unless
    told (containers and CI machines run as root)."""
    return dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def run(rupture, prm, directory, sets, ranks=1):
    """Run rupture on @p prm with the --set entries @p sets into
    @p directory (made absolute); returns (exit code, seconds). The screen
    output goes to directory/run.txt."""
    directory = os.path.abspath(directory)
    os.makedirs(os.path.dirname(directory) or ".", exist_ok=True)
    command = [rupture, prm]
    for s in list(sets) + ["Output directory=" + directory,
                           "Test mode=false"]:
        command += ["--set", s]
    command = mpi_prefix(ranks) + command
    env = mpi_env()
    start = time.time()
    with open(directory + ".run.txt", "w") as out:
        code = subprocess.call(command, stdout=out, stderr=subprocess.STDOUT,
                               env=env)
    return code, time.time() - start


def run_many(rupture, prm, cases, jobs=1, ranks=1):
    """Run the cases [(directory, sets)] that have not finished before,
    @p jobs at a time; exits with the failures' messages if any failed."""
    todo = [(d, s) for d, s in cases if not finished(d)]
    if todo:
        print("running %d of %d cases (%d at a time)" %
              (len(todo), len(cases), jobs), flush=True)
    with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        codes = list(pool.map(lambda c: run(rupture, prm, c[0], c[1], ranks),
                              todo))
    failed = [(d, code) for (d, _), (code, _) in zip(todo, codes) if code]
    if failed:
        for d, code in failed:
            print("failed (exit code %d): %s, see %s.run.txt" % (code, d, d),
                  file=sys.stderr)
        sys.exit(1)
