#!/usr/bin/env python3
"""Prints docs/performance.md's tables: the median over several quat_bench runs of each cell.

Usage: python3 bench/median_table.py run1.json run2.json run3.json
       python3 bench/median_table.py --levels x86-64=a1.json,a2.json x86-64-v3=b1.json native=c1.json
  each run from: quat_bench --table --benchmark_out=runN.json --benchmark_out_format=json
With --levels, a comment line per column names its CPU (quat_bench's context, from /proc/cpuinfo),
compiler, flags and the commit measured (git describe when quat_bench was built): a column whose
commit is not the current code's is to be measured again or removed.
Cells are ns per item (point, product, call or value) from items_per_second, as `--table` prints
them, the median over every repetition in every file (`--table` writes 7 repetitions per run);
"copy floor" rows are the fastest of the copies' medians (memcpy, plain loop, streaming copy);
ratio = other / quat (> 1: quat faster). With --levels, one column per build (instruction-set
level), each cell "quat ns (GLM / quat, Eigen / quat)". Python 3 standard library only.
"""
import json
import statistics
import sys

# (row label, benchmark name with {lib} for the library); float unless the label says double.
ROWS = [
    ("rotate_point, quaternion (latency)", "rotate_point/{lib}/quaternion/float"),
    ("rotate_point, matrix (latency)", "rotate_point/{lib}/matrix/float"),
    ("rotate_pairs, each point its own quaternion, n = 1024",
     "rotate_pairs/{lib}/quaternion/float/1024"),
    ("rotate_pairs, double, n = 1024", "rotate_pairs/{lib}/quaternion/double/1024"),
    ("transform_point, motion (latency; quat and GLM: dual quaternion, Eigen: quaternion and "
     "translation)", "transform_point/{lib}/motion/float"),
    ("transform_pairs, each point its own motion, n = 1024",
     "transform_pairs/{lib}/motion/float/1024"),
    ("transform_pairs, each point its own motion, double, n = 1024",
     "transform_pairs/{lib}/motion/double/1024"),
    ("transform_pairs, each point its own 4x4 matrix (Eigen: Isometry3f), n = 1024",
     "transform_pairs/{lib}/matrix/float/1024"),
    ("rotate_batch, quaternion, n = 64", "rotate_batch/{lib}/quaternion/float/64"),
    ("rotate_batch, matrix, n = 64", "rotate_batch/{lib}/matrix/float/64"),
    ("rotate_batch, quaternion via its matrix (GLM: mat3_cast, Eigen: toRotationMatrix, then the "
     "matrix loop), n = 64", "rotate_batch/{lib}/quaternion_via_matrix/float/64"),
    ("rotate_batch, quaternion, n = 1024", "rotate_batch/{lib}/quaternion/float/1024"),
    ("rotate_batch, matrix, n = 1024", "rotate_batch/{lib}/matrix/float/1024"),
    ("rotate_batch, quaternion via its matrix, n = 1024",
     "rotate_batch/{lib}/quaternion_via_matrix/float/1024"),
    ("rotate_batch, quaternion, struct of arrays, n = 1024",
     "rotate_batch/{lib}/quaternion_soa/float/1024"),
    ("rotate_batch, quaternion, n = 4194304", "rotate_batch/{lib}/quaternion/float/4194304"),
    ("rotate_batch, matrix, n = 4194304", "rotate_batch/{lib}/matrix/float/4194304"),
    ("rotate_batch, quaternion, struct of arrays, n = 4194304",
     "rotate_batch/{lib}/quaternion_soa/float/4194304"),
    ("memcpy of the same bytes, n = 1024", "rotate_batch/memcpy/bytes/float/1024"),
    ("plain copy loop of the same bytes, n = 1024", "rotate_batch/copy_loop/bytes/float/1024"),
    ("copy floor (fastest copy), n = 1024", "floor:rotate_batch/1024"),
    ("memcpy of the same bytes, n = 4194304", "rotate_batch/memcpy/bytes/float/4194304"),
    ("plain copy loop of the same bytes, n = 4194304",
     "rotate_batch/copy_loop/bytes/float/4194304"),
    ("streaming copy of the same bytes, n = 4194304", "rotate_batch/stream/bytes/float/4194304"),
    ("copy floor (fastest copy), n = 4194304", "floor:rotate_batch/4194304"),
    ("rotate_each, point i by quaternion i, n = 64", "rotate_each/{lib}/quaternion/float/64"),
    ("rotate_each, struct of arrays, n = 64", "rotate_each/{lib}/quaternion_soa/float/64"),
    ("rotate_each, point i by quaternion i, n = 1024", "rotate_each/{lib}/quaternion/float/1024"),
    ("rotate_each, struct of arrays, n = 1024", "rotate_each/{lib}/quaternion_soa/float/1024"),
    ("rotate_each, n = 4194304", "rotate_each/{lib}/quaternion/float/4194304"),
    ("rotate_each, struct of arrays, n = 4194304",
     "rotate_each/{lib}/quaternion_soa/float/4194304"),
    ("memcpy of rotate_each's bytes, n = 1024", "rotate_each/memcpy/bytes/float/1024"),
    ("copy floor of rotate_each's bytes, n = 1024", "floor:rotate_each/1024"),
    ("memcpy of rotate_each's bytes, n = 4194304", "rotate_each/memcpy/bytes/float/4194304"),
    ("copy floor of rotate_each's bytes, n = 4194304", "floor:rotate_each/4194304"),
    ("compose_each, a[i] * b[i], n = 64", "compose_each/{lib}/quaternion/float/64"),
    ("compose_each, a[i] * b[i], n = 1024", "compose_each/{lib}/quaternion/float/1024"),
    ("compose_each, a[i] * b[i], n = 4194304", "compose_each/{lib}/quaternion/float/4194304"),
    ("copy floor of compose_each's bytes, n = 4194304", "floor:compose_each/4194304"),
    ("to_matrix over an array, n = 64", "to_matrix_each/{lib}/quaternion/float/64"),
    ("to_matrix over an array, n = 1024", "to_matrix_each/{lib}/quaternion/float/1024"),
    ("to_matrix over an array, n = 4194304", "to_matrix_each/{lib}/quaternion/float/4194304"),
    ("to_quaternion over an array, n = 64", "to_quaternion_each/{lib}/matrix/float/64"),
    ("to_quaternion over an array, n = 1024", "to_quaternion_each/{lib}/matrix/float/1024"),
    ("to_quaternion over an array, n = 4194304",
     "to_quaternion_each/{lib}/matrix/float/4194304"),
    ("compose, quaternion", "compose/{lib}/quaternion/float"),
    ("compose, matrix", "compose/{lib}/matrix/float"),
    ("chain k = 8, quaternion", "chain/{lib}/quaternion/float/8"),
    ("chain k = 1024, quaternion (quat: `compose(span)`)", "chain/{lib}/quaternion/float/1024"),
    ("chain k = 1024, quaternion, quat's left-to-right loop",
     "chain_sequential/{lib}/quaternion/float/1024"),
    ("chain k = 1024, matrix", "chain/{lib}/matrix/float/1024"),
    ("chain k = 1024, quaternion, double (`compose(span)`)", "chain/{lib}/quaternion/double/1024"),
    ("drift: 1024 products", "drift/{lib}/quaternion/float/1024"),
    ("drift: 1024 products, renormalized each step", "drift_normalized/{lib}/quaternion/float/1024"),
    ("convert euler → quaternion", "convert/{lib}/euler_to_quaternion/float"),
    ("convert euler → matrix", "convert/{lib}/euler_to_matrix/float"),
    ("convert axis-angle → quaternion", "convert/{lib}/axis_angle_to_quaternion/float"),
    ("convert quaternion → matrix", "convert/{lib}/quaternion_to_matrix/float"),
    ("convert matrix → quaternion", "convert/{lib}/matrix_to_quaternion/float"),
    ("convert quaternion → euler", "convert/{lib}/quaternion_to_euler/float"),
    ("convert quaternion → axis-angle", "convert/{lib}/quaternion_to_axis_angle/float"),
    ("slerp (one call)", "slerp/{lib}/quaternion/float"),
    ("slerp (one call), double", "slerp/{lib}/quaternion/double"),
    ("slerp_batch, 64 t values (per value; GLM/Eigen: per-call loop)",
     "slerp_batch/{lib}/quaternion/float/64"),
    ("slerp_batch, 1024 t values (per value; GLM/Eigen: per-call loop)",
     "slerp_batch/{lib}/quaternion/float/1024"),
    ("slerp_batch, 4194304 t values (per value; GLM/Eigen: per-call loop)",
     "slerp_batch/{lib}/quaternion/float/4194304"),
    ("slerp_fast family: nlerp (one call)", "slerp_fast/quat/nlerp/float"),
    ("slerp_fast family: corrected_nlerp (one call)", "slerp_fast/quat/corrected_nlerp/float"),
    ("slerp_fast family: eberly, `slerp_fast` (one call)", "slerp_fast/quat/eberly/float"),
    ("slerp_fast family: exact `slerp` (one call)", "slerp_fast/quat/slerp/float"),
    ("nlerp", "nlerp/{lib}/quaternion/float"),
    ("normalize", "normalize/{lib}/quaternion/float"),
    ("transform_batch, dual quaternion (GLM: dualquat * p), n = 64",
     "transform_batch/{lib}/dual_quaternion/float/64"),
    ("transform_batch, 4x4 matrix (Eigen: Isometry3f), n = 64",
     "transform_batch/{lib}/matrix/float/64"),
    ("transform_batch, dual quaternion (GLM: dualquat * p), n = 1024",
     "transform_batch/{lib}/dual_quaternion/float/1024"),
    ("transform_batch, 4x4 matrix (Eigen: Isometry3f), n = 1024",
     "transform_batch/{lib}/matrix/float/1024"),
    ("transform_batch, dual quaternion, struct of arrays, n = 1024",
     "transform_batch/{lib}/dual_quaternion_soa/float/1024"),
    ("transform_batch, dual quaternion, n = 4194304",
     "transform_batch/{lib}/dual_quaternion/float/4194304"),
    ("transform_batch, 4x4 matrix, n = 4194304", "transform_batch/{lib}/matrix/float/4194304"),
    ("transform_batch, dual quaternion, struct of arrays, n = 4194304",
     "transform_batch/{lib}/dual_quaternion_soa/float/4194304"),
    ("rigid_chain k = 1024, dual quaternion (quat: `compose(span)`)",
     "rigid_chain/{lib}/dual_quaternion/float/1024"),
    ("rigid_chain k = 1024, dual quaternion, quat's left-to-right loop",
     "rigid_chain_sequential/{lib}/dual_quaternion/float/1024"),
    ("rigid_chain k = 1024, 4x4 matrix (Eigen: Isometry3f)", "rigid_chain/{lib}/matrix/float/1024"),
    ("sclerp (one call)", "sclerp/{lib}/dual_quaternion/float"),
    ("blend of 4 (one call)", "blend/{lib}/dual_quaternion/float/4"),
]
LIBRARIES = ("quat", "glm", "eigen")


COPIES = ("memcpy", "copy_loop", "stream")


def ns_per_item(path):
    """Every repetition of every benchmark in one JSON file, as ns per item."""
    with open(path) as f:
        data = json.load(f)
    out = {}
    for b in data["benchmarks"]:
        if b.get("run_type", "iteration") == "iteration" and b.get("items_per_second", 0) > 0:
            name = b.get("run_name", b["name"])
            out.setdefault(name, []).append(1e9 / b["items_per_second"])
    return data["context"], out


def median_of(runs, name):
    """The median over all repetitions of all runs; "floor:<operation>/<n>" is the fastest of the
    copies' medians (memcpy, plain loop, streaming copy), as `quat_bench --table` takes it."""
    if name.startswith("floor:"):
        operation, _, size = name[len("floor:"):].partition("/")
        copies = [median_of(runs, f"{operation}/{kind}/bytes/float/{size}") for kind in COPIES]
        copies = [c for c in copies if c is not None]
        return min(copies) if copies else None
    values = [v for _, r in runs if name in r for v in r[name]]
    return statistics.median(values) if values else None


def fmt(x, ratio=False):
    if x is None:
        return ""
    if ratio:
        return f"{x:.2f}"
    return f"{x:.0f}" if x >= 100 else f"{x:.1f}" if x >= 10 else f"{x:.2f}" if x >= 1 else f"{x:.3f}"


def level_cell(runs, pattern):
    if "{lib}" not in pattern:
        return fmt(median_of(runs, pattern))
    cells = {lib: median_of(runs, pattern.format(lib=lib)) for lib in LIBRARIES}
    q = cells["quat"]
    ratios = [fmt(cells[lib] / q, ratio=True) for lib in ("glm", "eigen") if q and cells[lib]]
    return fmt(q) + (f" ({', '.join(ratios)})" if ratios else "")


def print_levels(arguments):
    levels = []
    for argument in arguments:
        level, _, paths = argument.partition("=")
        if not paths:
            sys.exit(__doc__)
        levels.append((level, [ns_per_item(p) for p in paths.split(",")]))
    for level, runs in levels:
        context = runs[0][0]
        commits = sorted({r[0].get("quat_commit", "?") for r in runs})
        print(f"<!-- {level}: {len(runs)} runs; {context.get('quat_cpu', '?')}; "
              f"{context.get('quat_compiler', '?')}, {context.get('quat_compile_flags', '?')}; "
              f"commit {', '.join(commits)} -->")
    print("| benchmark (float unless noted); quat ns (GLM / quat, Eigen / quat) | "
          + " | ".join(level for level, _ in levels) + " |")
    print("|---|" + "---|" * len(levels))
    for label, pattern in ROWS:
        cells = [level_cell(runs, pattern) for _, runs in levels]
        if any(cells):
            print(f"| {label} | " + " | ".join(cells) + " |")


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    if sys.argv[1] == "--levels":
        print_levels(sys.argv[2:])
        return
    runs = [ns_per_item(p) for p in sys.argv[1:]]
    context = runs[0][0]
    print(f"<!-- {len(runs)} runs; {context.get('quat_compiler', '?')}, "
          f"{context.get('quat_compile_flags', '?')} -->")
    print("| benchmark (float unless noted) | quat | GLM | Eigen | GLM / quat | Eigen / quat |")
    print("|---|---|---|---|---|---|")

    def median(name):
        return median_of(runs, name)

    for label, pattern in ROWS:
        if "{lib}" not in pattern:
            print(f"| {label} | {fmt(median(pattern))} | | | | |")
            continue
        cells = {lib: median(pattern.format(lib=lib)) for lib in LIBRARIES}
        q = cells["quat"]
        ratios = [fmt(cells[lib] / q, ratio=True) if q and cells[lib] else "" for lib in ("glm", "eigen")]
        print(f"| {label} | {fmt(q)} | {fmt(cells['glm'])} | {fmt(cells['eigen'])} | "
              f"{ratios[0]} | {ratios[1]} |")


if __name__ == "__main__":
    main()
