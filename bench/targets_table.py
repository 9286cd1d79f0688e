#!/usr/bin/env python3
"""Prints docs/performance.md's speed-target table from the text `quat_bench --table` prints.

Usage: python3 bench/targets_table.py LEVEL=run1.txt,run2.txt,run3.txt [LEVEL=...]
  each run from: quat_bench --table [--benchmark_filter=...] > runN.txt
One column per level: the median of the runs' ratios, the runs in parentheses, and the verdict of
the median against that level's goal (named in the cell where it differs from the goal column's;
a goal set for AVX2 and AVX-512 only is marked so in a build without AVX2, not missed). A floor
is the fastest copy of each run, whichever it was. A target a run did not measure (filtered out)
is left out of that column; a target no level measured is left out of the table. Python 3
standard library only.
"""
import re
import statistics
import sys

# "  rotate_batch 1024 quaternion: quat / floor (memcpy)   1.48  (goal <= 1.20)  MISSED"
LINE = re.compile(r"^  (?P<name>.+?)\s+(?P<ratio>\d+\.\d+)\s+\(goal (?P<op>[<>]=) (?P<goal>\d+\.\d+)\)"
                  r"\s*(?P<verdict>.*)$")
# The verdict a build without AVX2 prints for a goal set for AVX2 and AVX-512 only.
WIDE_ONLY = "(AVX2/AVX-512 goal)"


def read_targets(path):
    targets = {}
    with open(path, encoding="utf-8") as text:
        for line in text:
            match = LINE.match(line)
            if match:
                # A run names the copy that was fastest in it: "floor (memcpy)", "floor (stream)".
                name = re.sub(r"floor \([a-z_]+\)", "floor", match["name"])
                targets[name] = (float(match["ratio"]), match["op"], match["goal"],
                                 match["verdict"].strip() == WIDE_ONLY)
    return targets


def main():
    if len(sys.argv) < 2 or any("=" not in argument for argument in sys.argv[1:]):
        sys.exit(__doc__)
    levels = []
    for argument in sys.argv[1:]:
        level, paths = argument.split("=", 1)
        levels.append((level, [read_targets(path) for path in paths.split(",")]))
    names = []
    for _, runs in levels:
        for run in runs:
            names.extend(name for name in run if name not in names)
    print("| target | goal | " + " | ".join(f"{level}: median (runs) | verdict" for level, _ in levels)
          + " |")
    print("|---|---|" + "---|---|" * len(levels))
    for name in names:
        goal = next(run[name] for _, runs in levels for run in runs if name in run)
        cells = []
        for _, runs in levels:
            ratios = [run[name][0] for run in runs if name in run]
            if not ratios:
                cells += ["", ""]
                continue
            median = statistics.median(ratios)
            own = next(run[name] for run in runs if name in run)  # this level's goal
            met = median <= float(own[2]) if own[1] == "<=" else median >= float(own[2])
            verdict = "met" if met else WIDE_ONLY if own[3] else "missed"
            if own[1:3] != goal[1:3]:
                verdict += f" (goal {'≤' if own[1] == '<=' else '≥'} {own[2]})"
            runs_text = ", ".join(f"{r:.2f}" for r in ratios)
            cells += [f"{median:.2f} ({runs_text})", verdict]
        symbol = "≤" if goal[1] == "<=" else "≥"
        print(f"| {name} | {symbol} {goal[2]} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
