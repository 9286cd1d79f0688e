#!/usr/bin/env python3
"""Write docs/accuracy.md from quat_accuracy's output and the template accuracy.md.in.

Usage:
  render.py --tool <build>/tools/accuracy/quat_accuracy [--build-dir <build>] [-o docs/accuracy.md]
      runs quat_accuracy four times (the main table, --scipy, --rigid, --trajectory; about 5
      minutes) and writes the document;
  render.py --main main.txt --scipy scipy.txt --rigid rigid.txt --trajectory trajectory.txt
            [--build-dir <build>] [-o ...]
      uses saved outputs of those four runs instead.
The machine line names the CPU (/proc/cpuinfo's model name, or --cpu), the compiler (--version of
the build directory's compiler, or --compiler) and the flags quat_accuracy was compiled with (from
the build directory's compile_commands.json, or --flags).

Template placeholders (the prose around the tables lives in accuracy.md.in):
  {{machine}}                  CPU, compiler and flags
  {{footer}}                   the main table's last line (reference, seed, sample counts)
  {{table GROUP}}              the main table's rows of one group (see GROUPS)
  {{missed}}                   a list of the rows that missed their target, with MISSED_REASONS
  {{scipy}} / {{rigid}}        the output of quat_accuracy --scipy / --rigid
  {{trajectory}}               the output of quat_accuracy --trajectory
  {{max LIB TYPE "OPERATION" ["INPUTS"]}}  the largest maximum of LIB (quat, GLM, Eigen) over the
                               rows of that operation and type whose inputs contain INPUTS
  {{rms ...}}                  the largest RMS of those rows
Python 3 standard library only.
"""
import argparse
import json
import os
import re
import shlex
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# Rows of the main table by what they measure: group name -> operation prefixes.
GROUPS = {
    "conversions": ("q → matrix → q", "Euler → q → Euler"),
    "slerp": ("slerp:",),
    "normalize-exp-log": ("normalize", "exp:", "log:"),
    "rotate": ("rotate:",),
    "directions": ("rotation_between", "look_rotation"),
    "registration": ("align_points", "hand_eye"),
    "lie": ("so3", "se3"),
}

# Why a row misses its target, keyed by operation prefix: (main.cpp's `accepted_*` ceiling, reason).
MISSED_REASONS = {
    "Euler → q → Euler": ("4.5",
        "each angle is taken from one `atan2` of a complex product (no sums of "
        "angles, no wrapping), so what remains is rounding the three stored angles, each up to π "
        "in size: half an ulp of π is 1 eps in float."),
    "slerp: angle to reference": ("6.5",
        "outside [0, 1] quat turns `a` by `t` times the relative rotation `a* b` "
        "instead of adding two cancelling weighted terms (the weighted sum reaches 2.7 eps in "
        "|r| − 1 there), but the result turns by up to 2π, and an angle that large rounds to 4 eps "
        "by itself. GLM and Eigen miss it too."),
    "normalize": ("1.5",
        "one correct rounding each in the sum of squares, the square root and the "
        "division; no overflow or underflow anywhere in the range, where GLM and Eigen overflow "
        "to zero or return the input (errors of 1/eps)."),
}

HEADER_LINES = 2  # the table's header and separator


def run_tool(tool, *args):
    run = subprocess.run([tool, *args], capture_output=True, text=True, check=False)
    sys.stderr.write(run.stderr)
    if run.returncode not in (0, 1):  # 1: a target missed beyond its ceiling; still a table
        sys.exit(f"{tool} {' '.join(args)} exited with {run.returncode}")
    return run.stdout


def split_cells(line):
    cells, cell, i = [], "", 1
    while i < len(line.rstrip()) - 1:
        if line[i] == "\\" and line[i + 1] == "|":
            cell += "\\|"
            i += 2
            continue
        if line[i] == "|":
            cells.append(cell.strip())
            cell = ""
        else:
            cell += line[i]
        i += 1
    cells.append(cell.strip())
    return cells


def parse_main(text):
    lines = [l for l in text.splitlines() if l.strip()]
    table = [l for l in lines if l.startswith("|")]
    footer = [l for l in lines if not l.startswith("|")]
    header, rows = table[:HEADER_LINES], table[HEADER_LINES:]
    return header, rows, " ".join(footer)


def column(header_line, name):
    names = split_cells(header_line)
    for i, n in enumerate(names):
        if n.lower().startswith(name.lower()):
            return i
    sys.exit(f"no column {name!r} in {header_line!r}")


def unescape(s):
    return s.replace("\\|", "|")


def cell_value(cell, which):
    """max or rms of a 'max / rms' cell, as printed."""
    parts = [p.strip() for p in cell.split("/")]
    if len(parts) != 2:
        return None
    return parts[0] if which == "max" else parts[1]


def render_lookup(args, header, rows):
    which, lib, scalar, operation = args[0], args[1], args[2], args[3]
    inputs = args[4] if len(args) > 4 else ""
    col = column(header[0], lib + " max")
    best, best_text = None, None
    for r in rows:
        c = split_cells(r)
        if unescape(c[0]) != operation or c[2] != scalar or inputs not in unescape(c[1]):
            continue
        text = cell_value(c[col], which)
        if text is None:
            continue
        value = float(text)
        if best is None or value > best:
            best, best_text = value, text
    if best_text is None:
        sys.exit(f"no row for {{{{{' '.join(args)}}}}}")
    return best_text


def group_rows(rows, group):
    prefixes = GROUPS[group]
    return [r for r in rows if any(unescape(split_cells(r)[0]).startswith(p) for p in prefixes)]


def missed_list(rows):
    """One item per reason: the target, the ceiling, each missed row's maximum, and the reason."""
    by_key = {}
    for r in rows:
        c = split_cells(r)
        if "**missed**" not in c[4]:
            continue
        operation = unescape(c[0])
        key = next((k for k in MISSED_REASONS if operation.startswith(k)), None)
        if key is None:
            sys.exit(f"a missed row without a reason in MISSED_REASONS: {operation}")
        target = c[4].replace("**missed**", "").replace("≤", "").strip()
        detail = c[0][len(key):].lstrip(" ,:") if c[0].startswith(key) else c[0]
        detail = ", ".join(x for x in (detail, c[1], c[2]) if x)
        by_key.setdefault(key, (target, []))[1].append(f"{cell_value(c[5], 'max')} ({detail})")
    out = []
    for key, (target, measured) in by_key.items():
        ceiling, reason = MISSED_REASONS[key]
        out.append(f"- *{key}* (target {target}, ceiling {ceiling}; measured "
                   f"{'; '.join(measured)}): {reason}")
    return "\n".join(out) if out else "None: every row meets its target."


def build_flags(build_dir):
    path = os.path.join(build_dir, "compile_commands.json")
    if not os.path.exists(path):
        return None
    with open(path, encoding="utf-8") as f:
        for entry in json.load(f):
            if entry["file"].endswith("tools/accuracy/main.cpp"):
                words = entry.get("arguments") or shlex.split(entry["command"])
                kept, skip = [], False
                for w in words[1:]:
                    if skip:
                        skip = False
                    elif w in ("-o", "-c", "-isystem", "-I"):
                        skip = True
                    elif not (w.startswith(("-I", "-W", "-DQUAT_ACCURACY")) or w.endswith(".cpp")):
                        kept.append(w)
                note = "" if any(w.startswith("-march") for w in kept) else " (no -march)"
                return f"`{' '.join(kept)}`{note}"
    return None


def build_compiler(build_dir):
    path = os.path.join(build_dir, "CMakeCache.txt")
    if not os.path.exists(path):
        return None
    with open(path, encoding="utf-8") as f:
        m = re.search(r"^CMAKE_CXX_COMPILER:\w+=(.*)$", f.read(), re.M)
    if not m:
        return None
    try:
        out = subprocess.run([m.group(1), "--version"], capture_output=True, text=True).stdout
        return out.splitlines()[0]
    except OSError:
        return m.group(1)


def cpu_name():
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            m = re.search(r"^model name\s*:\s*(.*)$", f.read(), re.M)
            return m.group(1) if m else None
    except OSError:
        return None


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--tool", help="quat_accuracy to run")
    p.add_argument("--main", help="saved output of quat_accuracy")
    p.add_argument("--scipy", help="saved output of quat_accuracy --scipy")
    p.add_argument("--rigid", help="saved output of quat_accuracy --rigid")
    p.add_argument("--trajectory", help="saved output of quat_accuracy --trajectory")
    p.add_argument("--build-dir", help="the build directory quat_accuracy was built in")
    p.add_argument("--cpu"), p.add_argument("--compiler"), p.add_argument("--flags")
    p.add_argument("--template", default=os.path.join(HERE, "accuracy.md.in"))
    p.add_argument("-o", "--output", default=os.path.join(ROOT, "docs", "accuracy.md"))
    a = p.parse_args()

    def output(saved, *args):
        if saved:
            with open(saved, encoding="utf-8") as f:
                return f.read()
        if not a.tool:
            p.error("give --tool, or --main, --scipy, --rigid and --trajectory")
        return run_tool(a.tool, *args)

    header, rows, footer = parse_main(output(a.main))
    scipy = output(a.scipy, "--scipy").strip()
    rigid = output(a.rigid, "--rigid").strip()
    trajectory = output(a.trajectory, "--trajectory").strip()
    build_dir = a.build_dir or (os.path.dirname(os.path.dirname(os.path.dirname(
        os.path.abspath(a.tool)))) if a.tool else None)
    cpu = a.cpu or cpu_name() or "an unnamed CPU"
    compiler = a.compiler or (build_compiler(build_dir) if build_dir else None) or "unknown"
    flags = (f"`{a.flags}`" if a.flags else None) or (
        build_flags(build_dir) if build_dir else None) or "unknown"
    machine = f"CPU {cpu}; compiler {compiler}; flags {flags}"

    used = set()

    def substitute(m):
        words = shlex.split(m.group(1))
        kind = words[0]
        if kind == "machine":
            return machine
        if kind == "footer":
            return footer
        if kind == "table":
            used.add(words[1])
            return "\n".join(header + group_rows(rows, words[1]))
        if kind == "missed":
            return missed_list(rows)
        if kind == "scipy":
            return scipy
        if kind == "rigid":
            return rigid
        if kind == "trajectory":
            return trajectory
        if kind in ("max", "rms"):
            return render_lookup(words, header, rows)
        sys.exit(f"unknown placeholder {m.group(0)}")

    with open(a.template, encoding="utf-8") as f:
        template = f.read()
    text = re.sub(r"\{\{(.*?)\}\}", substitute, template)
    placed = sum(len(group_rows(rows, g)) for g in used)
    if placed != len(rows):
        sys.exit(f"{len(rows) - placed} rows of the main table belong to no group in the template")
    with open(a.output, "w", encoding="utf-8") as f:
        f.write(text)
    print(f"wrote {a.output}")


if __name__ == "__main__":
    main()
