#!/usr/bin/env python3
"""Run quat_accuracy (full sample counts) and put its table into docs/accuracy.md.

Usage: update_docs.py <path to quat_accuracy> <path to docs/accuracy.md>
Replaces only the text between <!-- accuracy-table --> and <!-- /accuracy-table -->, which sit in
docs/accuracy.md's section "Against GLM and Eigen". The table is written even when a target is
missed (the program then exits 1 and lists the misses on stderr, which are echoed here).
"""
import re
import subprocess
import sys


def main() -> int:
    program, document = sys.argv[1], sys.argv[2]
    run = subprocess.run([program], capture_output=True, text=True, check=False)
    if run.returncode not in (0, 1):
        sys.stderr.write(run.stderr)
        return run.returncode
    sys.stderr.write(run.stderr)
    with open(document, encoding="utf-8") as f:
        text = f.read()
    begin, end = "<!-- accuracy-table -->", "<!-- /accuracy-table -->"
    pattern = re.compile(re.escape(begin) + r".*?" + re.escape(end), re.S)
    if not pattern.search(text):
        sys.stderr.write(f"{document}: markers {begin} ... {end} not found\n")
        return 2
    block = begin + "\n" + run.stdout.strip() + "\n" + end
    text = pattern.sub(lambda _: block, text, count=1)
    with open(document, "w", encoding="utf-8") as f:
        f.write(text)
    print(f"wrote the accuracy table into {document}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
