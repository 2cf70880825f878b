"""Parameter sweeps (contrib/sweep): the sweep file, its cases and the
case parameter files; the helpers the other sweep modules share."""

import difflib
import json
import math
import os
import random
import re
import subprocess

TOP = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

KEYS = {"base", "output", "ranks", "jobs", "sample", "seed", "nucleation size",
        "fault size", "whole fault fraction", "shear wave speed", "title",
        "reference",
        "slurm partition", "slurm time", "slurm nodes", "slurm account",
        "slurm cases per task"}

OUTCOMES = ["ruptured the whole fault", "stopped by itself",
            "died at nucleation", "earthquake cycles", "aborted", "failed",
            "interrupted", "not run"]


class SweepError(Exception):
    pass


# ------------------------------------------------------------ sweep files

def entry_paths(rupture):
    """Every entry path ('Section/Sub/Entry') that rupture declares."""
    try:
        text = subprocess.run([rupture, "--print-parameters", "prm"],
                              capture_output=True, text=True,
                              check=True).stdout
    except (OSError, subprocess.CalledProcessError) as e:
        raise SweepError(f"cannot run '{rupture} --print-parameters': {e}. "
                         "Build it first (contrib/build Release) or give "
                         "--rupture PATH.")
    paths, stack = set(), []
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if line.startswith("subsection "):
            stack.append(line[len("subsection "):].strip())
        elif line == "end":
            stack.pop()
        elif line.startswith("set "):
            name = line[4:].split("=", 1)[0].strip()
            paths.add("/".join(stack + [name]))
    return paths


def parse_number(text, where):
    try:
        value = float(text)
    except ValueError:
        raise SweepError(f"{where}: '{text}' is not a number")
    if not math.isfinite(value):
        raise SweepError(f"{where}: '{text}' is not a finite number")
    return value


def parse_values(text, where):
    """A value specification: a list 'a, b, c' (or 'a | b | c'), 'range A B N' (N evenly
    spaced values from A to B), 'log A B N' (N values evenly spaced in
    log), 'uniform A B' or 'loguniform A B' (random and latin samples)."""
    words = text.split()
    if not words:
        raise SweepError(f"{where}: no values given")
    kind = words[0]
    if kind in ("range", "log"):
        if len(words) != 4:
            raise SweepError(f"{where}: '{kind}' takes three numbers, "
                             f"'{kind} FIRST LAST COUNT', not '{text}'")
        a, b = (parse_number(w, where) for w in words[1:3])
        try:
            n = int(words[3])
        except ValueError:
            n = 0
        if n < 1:
            raise SweepError(f"{where}: the count of '{text}' must be an "
                             "integer >= 1")
        if kind == "log" and (a <= 0 or b <= 0):
            raise SweepError(f"{where}: 'log' needs positive ends, not "
                             f"'{text}'")
        if n == 1:
            return {"list": [a]}
        if kind == "range":
            return {"list": [a + (b - a) * i / (n - 1) for i in range(n)]}
        return {"list": [a * (b / a) ** (i / (n - 1)) for i in range(n)]}
    if kind in ("uniform", "loguniform"):
        if len(words) != 3:
            raise SweepError(f"{where}: '{kind}' takes two numbers, "
                             f"'{kind} LOW HIGH', not '{text}'")
        a, b = (parse_number(w, where) for w in words[1:])
        if not a < b:
            raise SweepError(f"{where}: the range '{text}' is empty (LOW "
                             "must be below HIGH)")
        if kind == "loguniform" and a <= 0:
            raise SweepError(f"{where}: 'loguniform' needs LOW > 0")
        return {kind: (a, b)}
    # Items are separated by commas, or by '|' when an item holds commas
    # (a function expression).
    items = [v.strip() for v in text.split("|" if "|" in text else ",")]
    if any(not v for v in items):
        raise SweepError(f"{where}: the list '{text}' has an empty item")
    return {"list": items}


def format_value(v):
    if isinstance(v, float):
        return "%.10g" % v
    return str(v)


def read_sweep_file(path, rupture):
    """The sweep as a dict; every error names the line."""
    if not os.path.isfile(path):
        raise SweepError(f"the sweep file {path} does not exist")
    here = os.path.dirname(os.path.abspath(path))
    sweep = {"file": os.path.abspath(path), "keys": {}, "set": [],
             "vary": [], "derive": []}
    with open(path) as f:
        lines = f.readlines()
    for number, raw in enumerate(lines, 1):
        where = f"{path}, line {number}"
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        word = line.split(None, 1)[0]
        if word in ("set", "vary", "derive"):
            rest = line[len(word):].strip()
            if "=" not in rest:
                raise SweepError(f"{where}: '{word}' needs 'ENTRY = VALUE', "
                                 f"not '{line}'")
            name, value = (s.strip() for s in rest.split("=", 1))
            alias = None
            if word != "derive" and ":" in name:
                alias, name = (s.strip() for s in name.split(":", 1))
                if not re.fullmatch(r"[A-Za-z_][A-Za-z_0-9]*", alias):
                    raise SweepError(f"{where}: the short name '{alias}' "
                                     "must be a letter or '_' followed by "
                                     "letters, digits or '_'")
            # (A 'set' may give an empty value, as a .prm file may.)
            if not name or (not value and word != "set"):
                raise SweepError(f"{where}: '{word}' needs 'ENTRY = VALUE', "
                                 f"not '{line}'")
            if word == "set":
                sweep["set"].append((name, value, where))
            elif word == "vary":
                sweep["vary"].append({"entry": name, "alias": alias,
                                      "values": parse_values(value, where),
                                      "where": where})
            else:
                if not re.fullmatch(r"[A-Za-z_][A-Za-z_0-9 ]*", name):
                    raise SweepError(f"{where}: the derived column name "
                                     f"'{name}' must be letters, digits, "
                                     "'_' and spaces")
                sweep["derive"].append((name, value, where))
            continue
        if "=" not in line:
            raise SweepError(f"{where}: expected 'KEY = VALUE', 'set ENTRY "
                             f"= VALUE', 'vary ENTRY = VALUES' or 'derive "
                             f"NAME = EXPRESSION', not '{line}'")
        key, value = (s.strip() for s in line.split("=", 1))
        if key not in KEYS:
            close = difflib.get_close_matches(key, KEYS, 1)
            raise SweepError(f"{where}: unknown key '{key}'" +
                             (f" (did you mean '{close[0]}'?)" if close
                              else "") +
                             ". Known keys: " + ", ".join(sorted(KEYS)) +
                             "; and set/vary/derive lines")
        sweep["keys"][key] = (value, where)

    keys = sweep["keys"]
    if "base" not in keys:
        raise SweepError(f"{path}: no 'base = FILE.prm' line: the sweep "
                         "needs the parameter file its cases start from")
    base = os.path.join(here, keys["base"][0])
    if not os.path.isfile(base):
        raise SweepError(f"{keys['base'][1]}: the base file {base} does not "
                         "exist")
    sweep["base"] = os.path.abspath(base)
    # Like rupture's <Output directory>: relative to the working directory.
    sweep["output"] = os.path.abspath(keys.get("output",
                                               ("output-sweep", ""))[0])
    sweep["title"] = keys.get("title", (os.path.basename(path), ""))[0]
    for key, default in (("ranks", 1), ("jobs", 1), ("seed", 1)):
        value, where = keys.get(key, (str(default), path))
        try:
            sweep[key] = int(value)
        except ValueError:
            sweep[key] = -1
        if sweep[key] < (0 if key == "seed" else 1):
            raise SweepError(f"{where}: '{key}' must be an integer >= "
                             f"{0 if key == 'seed' else 1}, not '{value}'")
    for key in ("nucleation size", "fault size", "shear wave speed"):
        if key in keys:
            sweep[key] = parse_number(keys[key][0], keys[key][1])
            if sweep[key] <= 0:
                raise SweepError(f"{keys[key][1]}: '{key}' must be > 0")
    if "reference" in keys:
        ref = os.path.join(here, keys["reference"][0])
        if not os.path.isdir(ref) or not any(
                f.endswith(".dat") for f in os.listdir(ref)):
            raise SweepError(f"{keys['reference'][1]}: the reference {ref} "
                             "is not a directory of station files (*.dat)")
        sweep["reference"] = os.path.abspath(ref)
    sweep["whole fault fraction"] = 0.95
    if "whole fault fraction" in keys:
        v = parse_number(*keys["whole fault fraction"])
        if not 0 < v <= 1:
            raise SweepError(f"{keys['whole fault fraction'][1]}: 'whole "
                             "fault fraction' must be in (0, 1]")
        sweep["whole fault fraction"] = v

    sample, where = keys.get("sample", ("grid", path))
    words = sample.split()
    if words and words[0] == "grid" and len(words) == 1:
        sweep["sample"] = ("grid", 0)
    elif len(words) == 2 and words[0] in ("random", "latin"):
        try:
            n = int(words[1])
        except ValueError:
            n = 0
        if n < 1:
            raise SweepError(f"{where}: '{words[0]} N' needs a count N >= 1")
        sweep["sample"] = (words[0], n)
    else:
        raise SweepError(f"{where}: 'sample' must be 'grid', 'random N' or "
                         f"'latin N', not '{sample}'")

    # Entry paths: each must be one rupture declares.
    paths = entry_paths(rupture)
    seen = {}
    for name, where in ([(s[0], s[2]) for s in sweep["set"]] +
                        [(v["entry"], v["where"]) for v in sweep["vary"]]):
        if name not in paths:
            close = difflib.get_close_matches(name, sorted(paths), 3, 0.6)
            raise SweepError(f"{where}: '{name}' is not an entry of rupture's "
                             "parameters" +
                             (" (close: " + "; ".join(close) + ")" if close
                              else "") +
                             ". Entries are 'Section/Subsection/Entry' as in "
                             "doc/parameters.md")
        if name == "Output directory":
            raise SweepError(f"{where}: the sweep sets each case's <Output "
                             "directory> itself")
        if name in seen:
            raise SweepError(f"{where}: '{name}' is set twice (also at "
                             f"{seen[name]})")
        seen[name] = where
    if not sweep["vary"]:
        raise SweepError(f"{path}: no 'vary ENTRY = VALUES' line: a sweep "
                         "varies at least one entry")
    aliases = set()
    for v in sweep["vary"]:
        if v["alias"] is None:
            v["alias"] = re.sub(r"\W+", "_", v["entry"].split("/")[-1]
                                ).strip("_").lower()
        if v["alias"] in aliases:
            raise SweepError(f"{v['where']}: the short name '{v['alias']}' is "
                             "used twice; give one with 'vary NAME: ENTRY = "
                             "...'")
        aliases.add(v["alias"])
        if sweep["sample"][0] == "grid" and "list" not in v["values"]:
            raise SweepError(f"{v['where']}: a grid sample needs lists or "
                             "'range'/'log' values; 'uniform' and "
                             "'loguniform' are for 'sample = random N' or "
                             "'latin N'")
    for name, expression, where in sweep["derive"]:
        try:
            compile(expression, where, "eval")
        except SyntaxError as e:
            raise SweepError(f"{where}: the expression '{expression}' is not "
                             f"valid ({e.msg})")
    return sweep


def design(sweep):
    """The cases: a list of {alias: value}."""
    vary = sweep["vary"]
    kind, n = sweep["sample"]
    if kind == "grid":
        cases = [{}]
        for v in vary:
            cases = [dict(c, **{v["alias"]: x}) for c in cases
                     for x in v["values"]["list"]]
        return cases
    rng = random.Random(sweep["seed"])

    def draw(v, u):
        spec = v["values"]
        if "list" in spec:
            items = spec["list"]
            return items[min(int(u * len(items)), len(items) - 1)]
        if "uniform" in spec:
            a, b = spec["uniform"]
            return a + u * (b - a)
        a, b = spec["loguniform"]
        return a * (b / a) ** u

    columns = {}
    for v in vary:
        if kind == "random":
            columns[v["alias"]] = [rng.random() for _ in range(n)]
        else:
            # Latin hypercube: one sample in each of n strata per entry.
            strata = [(i + rng.random()) / n for i in range(n)]
            rng.shuffle(strata)
            columns[v["alias"]] = strata
    return [{v["alias"]: draw(v, columns[v["alias"]][i]) for v in vary}
            for i in range(n)]


def case_name(index):
    return "case-%04d" % index


def case_prm(sweep, index, values):
    """The parameter file of a case: the base included, then its sets."""
    lines = [f"# Case {index} of the sweep {sweep['file']},",
             "# written by contrib/sweep. Run it alone with",
             f"#   rupture {case_name(index)}/case.prm",
             f"include {sweep['base']}"]
    entries = [(name, value) for name, value, _ in sweep["set"]]
    for v in sweep["vary"]:
        entries.append((v["entry"], format_value(values[v["alias"]])))
    entries.append(("Output directory",
                    os.path.join(sweep["output"], case_name(index))))
    for name, value in entries:
        parts = name.split("/")
        for depth, section in enumerate(parts[:-1]):
            lines.append("  " * depth + f"subsection {section}")
        lines.append("  " * (len(parts) - 1) + f"set {parts[-1]} = {value}")
        for depth in reversed(range(len(parts) - 1)):
            lines.append("  " * depth + "end")
    return "\n".join(lines) + "\n"


def derived(sweep, values):
    namespace = {k: getattr(math, k) for k in dir(math)
                 if not k.startswith("_")}
    namespace.update({k: float(v) if re.fullmatch(
        r"[-+0-9.eE]+", str(v)) else v for k, v in values.items()})
    out = {}
    for name, expression, where in sweep["derive"]:
        try:
            out[name] = float(eval(expression, {"__builtins__": {}},
                                   namespace))
        except Exception as e:
            raise SweepError(f"{where}: the expression '{expression}' "
                             f"cannot be evaluated for {values}: {e}")
        namespace[name.replace(" ", "_")] = out[name]
    return out


def write_atomically(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def shown(path):
    """A path as the tables show it: relative to the source tree if in it."""
    relative = os.path.relpath(path, TOP)
    return path if relative.startswith("..") else relative
