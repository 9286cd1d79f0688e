#!/usr/bin/env python3
"""The README's speed headline from quat_bench runs, and the same rows measured here beside it.

Usage:
  python3 bench/headline.py RUN.json [RUN.json ...]                 the README's rows, as Markdown
  python3 bench/headline.py RUN.json [RUN.json ...] --beside README.md
                                                 this machine's rows beside the README's (quat.sh bench)
  RUN.json from: quat_bench --table --benchmark_out=RUN.json --benchmark_out_format=json

Each row is one job. quat's cell is its median ns per item (point, product, call or value) over
every repetition of every run given; GLM's and Eigen's cells are the fastest of their loops for
the same job (a mat3 loop and a quaternion loop for rotating points, say) divided by quat's:
above 1, quat is faster. Python 3 standard library only.
"""
import json
import re
import statistics
import sys

# (job, quat's benchmark, GLM's loops for the job, Eigen's loops for the job, unit)
ROWS = [
    ("rotate 1024 points by one rotation", "rotate_batch/quat/quaternion/float/1024",
     ["rotate_batch/glm/quaternion/float/1024", "rotate_batch/glm/matrix/float/1024"],
     ["rotate_batch/eigen/quaternion/float/1024", "rotate_batch/eigen/matrix/float/1024"],
     "a point"),
    ("move 1024 points by one rigid motion", "transform_batch/quat/dual_quaternion/float/1024",
     ["transform_batch/glm/dual_quaternion/float/1024", "transform_batch/glm/matrix/float/1024"],
     ["transform_batch/eigen/matrix/float/1024"], "a point"),
    ("rotate point i by rotation i, 1024 points", "rotate_each/quat/quaternion/float/1024",
     ["rotate_each/glm/quaternion/float/1024"], ["rotate_each/eigen/quaternion/float/1024"],
     "a point"),
    ("chain of 1024 products, `compose(span)`", "chain/quat/quaternion/float/1024",
     ["chain/glm/quaternion/float/1024", "chain/glm/matrix/float/1024"],
     ["chain/eigen/quaternion/float/1024", "chain/eigen/matrix/float/1024"], "a product"),
    ("slerp, one call", "slerp/quat/quaternion/float", ["slerp/glm/quaternion/float"],
     ["slerp/eigen/quaternion/float"], "a call"),
    ("slerp at 1024 values of t, batch", "slerp_batch/quat/quaternion/float/1024",
     ["slerp_batch/glm/quaternion/float/1024"], ["slerp_batch/eigen/quaternion/float/1024"],
     "a value"),
    ("quaternion → Euler angles", "convert/quat/quaternion_to_euler/float",
     ["convert/glm/quaternion_to_euler/float"], ["convert/eigen/quaternion_to_euler/float"],
     "a call"),
    ("rigid motion fitting 64 point pairs (`align_points`; Eigen: `umeyama`)",
     "align_points/quat/vec3/float/64", [], ["align_points/eigen/vec3/float/64"], "a pair"),
]


def load(paths):
    """Context of the first run, and every repetition of every benchmark as ns per item."""
    context, times = {}, {}
    for path in paths:
        with open(path) as f:
            data = json.load(f)
        context = context or data["context"]
        for b in data["benchmarks"]:
            if b.get("run_type", "iteration") == "iteration" and b.get("items_per_second", 0) > 0:
                times.setdefault(b.get("run_name", b["name"]), []).append(1e9 / b["items_per_second"])
    return context, {name: statistics.median(v) for name, v in times.items()}


def fastest(medians, names):
    values = [medians[n] for n in names if n in medians]
    return min(values) if values else None


def measured_rows(medians):
    """(job, quat ns, GLM / quat, Eigen / quat, unit) for every row quat_bench ran."""
    rows = []
    for job, ours, glm, eigen, unit in ROWS:
        q = medians.get(ours)
        if q is None:
            continue
        g, e = fastest(medians, glm), fastest(medians, eigen)
        rows.append((job, q, g / q if g else None, e / q if e else None, unit))
    return rows


def ratio(x):
    return f"{x:.2f}" if x is not None else ""


def ns(x):
    return f"{x:.3g}" if x < 100 else f"{x:.0f}"


def machine(context):
    return (f"{context.get('quat_cpu', 'unknown CPU')}, {context.get('quat_compiler', '?')} "
            f"`{context.get('quat_compile_flags', '?')}`, commit {context.get('quat_commit', '?')}")


def print_markdown(context, rows):
    print(f"Time relative to quat, float; {machine(context)}; GLM and Eigen: their fastest loop "
          "for the job.\n")
    print("| job | quat | GLM 0.9.9 | Eigen 3.4 |")
    print("|---|---|---|---|")
    for job, q, g, e, unit in rows:
        print(f"| {job} (quat: {ns(q)} ns {unit}) | 1 | {ratio(g)} | {ratio(e)} |")


def readme_rows(path):
    """job -> (GLM / quat, Eigen / quat) from the README's headline table."""
    rows = {}
    with open(path) as f:
        for line in f:
            m = re.match(r"\| (.+?) \(quat: [^|]*\) \| 1 \| ([^|]*) \| ([^|]*) \|", line)
            if m:
                rows[m.group(1)] = (m.group(2).strip(), m.group(3).strip())
    return rows


def print_beside(context, rows, readme):
    theirs = readme_rows(readme)
    print(f"\nheadline: GLM / quat and Eigen / quat (> 1: quat faster), each peer's fastest loop")
    print(f"  here:   {machine(context)}")
    print(f"  README: the machine and flags its table names")
    print(f"  {'job':48s} {'here GLM':>9s} {'Eigen':>7s}   {'README GLM':>10s} {'Eigen':>7s}")
    for job, q, g, e, unit in rows:
        r = theirs.get(job, ("", ""))
        print(f"  {job[:48]:48s} {ratio(g):>9s} {ratio(e):>7s}   {r[0]:>10s} {r[1]:>7s}")


def main(argv):
    beside = None
    if "--beside" in argv:
        i = argv.index("--beside")
        if i + 1 >= len(argv):
            sys.exit(__doc__)
        beside = argv[i + 1]
        argv = argv[:i] + argv[i + 2:]
    if not argv:
        sys.exit(__doc__)
    context, medians = load(argv)
    rows = measured_rows(medians)
    if beside:
        print_beside(context, rows, beside)
    else:
        print_markdown(context, rows)


if __name__ == "__main__":
    main(sys.argv[1:])
