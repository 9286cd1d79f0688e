#!/usr/bin/env python3
"""Run quat_accuracy (full sample counts) and put its table into README.md.

Usage: update_readme.py <path to quat_accuracy> <path to README.md>
Replaces only the text between <!-- accuracy-table --> and <!-- /accuracy-table -->, which sit
inside the README's accuracy section. The table is written even when a target is missed (the
program then exits 1 and lists the misses on stderr, which are echoed here).
"""
import re
import subprocess
import sys


def main() -> int:
    program, readme = sys.argv[1], sys.argv[2]
    run = subprocess.run([program], capture_output=True, text=True, check=False)
    if run.returncode not in (0, 1):
        sys.stderr.write(run.stderr)
        return run.returncode
    sys.stderr.write(run.stderr)
    with open(readme, encoding="utf-8") as f:
        text = f.read()
    begin, end = "<!-- accuracy-table -->", "<!-- /accuracy-table -->"
    pattern = re.compile(re.escape(begin) + r".*?" + re.escape(end), re.S)
    if not pattern.search(text):
        sys.stderr.write(f"{readme}: markers {begin} ... {end} not found\n")
        return 2
    block = begin + "\n" + run.stdout.strip() + "\n" + end
    text = pattern.sub(lambda _: block, text, count=1)
    with open(readme, "w", encoding="utf-8") as f:
        f.write(text)
    print(f"wrote the accuracy table into {readme}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
