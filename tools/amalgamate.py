#!/usr/bin/env python3
"""Generate single_include/quat/quat.hpp and its opt-in companions from include/quat.

quat.hpp: follows the includes of include/quat/quat.hpp depth-first and inlines every quat header
once, at its first inclusion, the way #pragma once would; standard headers stay #include lines.
The opt-in headers that quat.hpp does not include (io.hpp, interop/glm.hpp, interop/eigen.hpp,
interop/fmt.hpp, interop/ceres.hpp, and the estimation families align_points.hpp, hand_eye.hpp,
so3.hpp, se3.hpp and geodesic_mean.hpp) are generated at the same relative paths, so a user's #include <quat/io.hpp> or
<quat/interop/glm.hpp> works with single_include/ as with include/. Each is its own text with
every include of a header that quat.hpp holds replaced by one include of the single quat.hpp
(#include "../quat.hpp" from interop/), every include of a header an earlier opt-in output holds
replaced by one include of that output (interop/fmt.hpp's ../io.hpp), and anything else of quat's
inlined. The output depends only on the input files (no dates, no absolute paths), so the
committed copies can be compared with a fresh generation:

    python3 tools/amalgamate.py           write single_include/quat/quat.hpp and the opt-in headers
    python3 tools/amalgamate.py --check   exit 1 if a committed file is out of date
"""
import argparse
import difflib
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
INCLUDE_DIR = ROOT / "include"
ENTRY = INCLUDE_DIR / "quat" / "quat.hpp"
# The opt-in headers, relative to include/quat, with the title of their generated copy. A header
# that includes another of them comes after it.
OPT_IN = {
    "io.hpp": "printing (operator<<, std::formatter), single-header edition.",
    "interop/glm.hpp": "conversions to and from GLM, single-header edition.",
    "interop/eigen.hpp": "conversions to and from Eigen, single-header edition.",
    "interop/fmt.hpp": "{fmt} formatters, single-header edition.",
    "align_points.hpp": "point-set registration (Kabsch-Umeyama), single-header edition.",
    "hand_eye.hpp": "hand-eye calibration (Daniilidis), single-header edition.",
    "so3.hpp": "SO(3) calculus with Jacobians, single-header edition.",
    "se3.hpp": "SE(3) calculus with Jacobians, single-header edition.",
    "geodesic_mean.hpp": "geodesic (Karcher) means, single-header edition.",
    "interop/ceres.hpp": "Ceres manifolds and parameter blocks, single-header edition.",
}
OUTPUT_DIR = ROOT / "single_include" / "quat"

INCLUDE_RE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
PRAGMA_ONCE_RE = re.compile(r"^\s*#\s*pragma\s+once\b")
VERSION_RE = re.compile(r"^#define QUAT_VERSION_(MAJOR|MINOR|PATCH) (\d+)\s*$", re.M)


def resolve(spelling: str, delimiter: str, including_file: Path):
    """The quat header an include names, or None for a header outside quat (kept as is)."""
    candidates = []
    if delimiter == '"':
        candidates.append(including_file.parent / spelling)
    candidates.append(INCLUDE_DIR / spelling)
    quat_dir = (INCLUDE_DIR / "quat").resolve()
    for candidate in candidates:
        candidate = candidate.resolve()
        if candidate.is_file() and quat_dir in candidate.parents:
            return candidate
    return None


def inline(path: Path, seen: set, out: list, external: dict, emitted: set, markers=True) -> None:
    """Append path's text to out, replacing quat includes by the headers' text (once each).

    external maps a header to the include line that stands for it (a header that an already
    generated file holds); each such line is written once, recorded in emitted. markers wraps the
    text in begin/end comments (not for a generated file's own text)."""
    seen.add(path)
    name = path.relative_to(INCLUDE_DIR).as_posix()
    lines = path.read_text(encoding="utf-8").splitlines()
    while lines and not lines[-1].strip():
        lines.pop()
    if markers:
        out.append(f"// ---- begin {name} ----")
    for line in lines:
        if PRAGMA_ONCE_RE.match(line):
            continue
        match = INCLUDE_RE.match(line)
        target = resolve(match.group(2), match.group(1), path) if match else None
        if target is None:
            out.append(line)
        elif target.suffix == ".inc":
            # A fragment (the instruction-set namespace's opening) each time it is included.
            inline(target, seen, out, external, emitted)
        elif target in external:
            if external[target] not in emitted:
                emitted.add(external[target])
                out.append(external[target])
        elif target not in seen:
            # A header once, as #pragma once would.
            inline(target, seen, out, external, emitted)
        # A quat header already inlined earlier needs nothing here.
    if markers:
        out.append(f"// ---- end {name} ----")


def version() -> str:
    text = (INCLUDE_DIR / "quat" / "config.hpp").read_text(encoding="utf-8")
    parts = dict(VERSION_RE.findall(text))
    try:
        return f"{parts['MAJOR']}.{parts['MINOR']}.{parts['PATCH']}"
    except KeyError as missing:
        sys.exit(f"amalgamate.py: QUAT_VERSION_{missing.args[0]} not found in config.hpp")


def preamble(title: str) -> list:
    """The generated file's first lines: what it is, where it comes from, the license."""
    license_lines = (ROOT / "LICENSE").read_text(encoding="utf-8").rstrip().splitlines()
    out = [
        f"// quat {version()} — {title}",
        "// Generated by tools/amalgamate.py from include/quat; do not edit by hand.",
        "//",
    ]
    return out + [("// " + line).rstrip() for line in license_lines]


def generate() -> tuple:
    """The single quat.hpp, and the set of headers it holds."""
    out = preamble("3D rotations for C++17/20, single-header edition.")
    out += ["", "#pragma once", ""]
    seen = set()
    inline(ENTRY.resolve(), seen, out, {}, set())
    return "\n".join(out) + "\n", seen


def generate_opt_in(name: str, title: str, external: dict) -> tuple:
    """single_include/quat/<name> from include/quat/<name>, and the set of headers it holds.
    external's include lines are relative to single_include/quat."""
    out = preamble(title)
    out += [f"// Opt-in: keep this file at quat/{name} beside the single quat.hpp, which it",
            "// includes.", ""]
    # From interop/, the files of single_include/quat are one directory up.
    up = "../" * name.count("/")
    local = {header: line.replace('#include "', '#include "' + up, 1)
             for header, line in external.items()}
    seen, emitted = set(), set()
    inline((INCLUDE_DIR / "quat" / name).resolve(), seen, out, local, emitted, markers=False)
    if not emitted:
        sys.exit(f"amalgamate.py: include/quat/{name} includes no header of quat.hpp or io.hpp")
    return "\n".join(out) + "\n", seen


def generate_all() -> dict:
    """Every generated file, by its path relative to single_include/quat."""
    text, held = generate()
    outputs = {"quat.hpp": text}
    external = {header: '#include "quat.hpp"' for header in held}
    for name, title in OPT_IN.items():
        text, held = generate_opt_in(name, title, external)
        outputs[name] = text
        for header in held:
            external.setdefault(header, f'#include "{name}"')
    return outputs


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true",
                        help="compare with the committed files instead of writing them")
    parser.add_argument("--output-dir", type=Path, default=OUTPUT_DIR,
                        help="directory of the files to write or check")
    args = parser.parse_args()

    outputs = generate_all()
    if args.check:
        status = 0
        for name, text in outputs.items():
            path = args.output_dir / name
            current = path.read_text(encoding="utf-8") if path.is_file() else ""
            if current == text:
                print(f"{path} is up to date")
                continue
            diff = difflib.unified_diff(current.splitlines(), text.splitlines(),
                                        "committed", "generated", lineterm="", n=1)
            sys.stdout.write("\n".join(list(diff)[:40]) + "\n")
            print(f"{path} is out of date; run: python3 tools/amalgamate.py", file=sys.stderr)
            status = 1
        return status
    args.output_dir.mkdir(parents=True, exist_ok=True)
    for name, text in outputs.items():
        (args.output_dir / name).parent.mkdir(parents=True, exist_ok=True)
        (args.output_dir / name).write_text(text, encoding="utf-8", newline="\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
