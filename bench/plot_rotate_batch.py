#!/usr/bin/env python3
"""Turns quat_bench JSON into an SVG plot of ns per point against n for rotate_batch.

Usage: python3 bench/plot_rotate_batch.py RESULTS.json [RESULTS2.json ...] [OUTPUT.svg]
  RESULTS.json from: quat_bench --benchmark_filter=^rotate_batch/ --benchmark_format=json > RESULTS.json
  (or --benchmark_out=RESULTS.json --benchmark_out_format=json); OUTPUT defaults to
  docs/images/rotate_batch.svg. Plots the float entries rotate_batch/<library>/<representation>/float/<n>,
  ns per point = CPU time per iteration / n, on log-log axes; with several runs, the median of each
  point. Python 3 standard library only.
"""
import json
import math
import statistics
import sys

COLORS = {"quat": "#1f77b4", "glm": "#d62728", "eigen": "#2ca02c", "memcpy": "#7f7f7f"}
DASH = {"quaternion": "", "matrix": "6,4", "quaternion_soa": "2,3", "bytes": "1,3"}


def series(data):
    out = {}
    for b in data["benchmarks"]:
        if b.get("run_type", "iteration") != "iteration":
            continue
        part = b["name"].split("/")
        if len(part) != 5 or part[0] != "rotate_batch" or part[3] != "float":
            continue
        if part[2] not in DASH:  # quaternion_via_matrix: measured in cache only
            continue
        n = int(part[4])
        scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[b.get("time_unit", "ns")]
        out.setdefault((part[1], part[2]), []).append((n, b["cpu_time"] * scale / n))
    return {k: sorted(v) for k, v in out.items()}


def median_series(paths):
    runs = []
    for path in paths:
        with open(path) as f:
            runs.append(series(json.load(f)))
    keys = set().union(*runs)
    out = {}
    for key in keys:
        per_n = {}
        for run in runs:
            for n, t in run.get(key, []):
                per_n.setdefault(n, []).append(t)
        out[key] = sorted((n, statistics.median(ts)) for n, ts in per_n.items())
    return out


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    output = args.pop() if len(args) > 1 and args[-1].endswith(".svg") else "docs/images/rotate_batch.svg"
    lines = median_series(args)
    if not lines:
        sys.exit("no rotate_batch/.../float/<n> entries in " + ", ".join(args))
    ns = [n for v in lines.values() for n, _ in v]
    ts = [t for v in lines.values() for _, t in v]
    x0, x1 = math.log10(min(ns)), math.log10(max(ns))
    y0, y1 = math.floor(math.log10(min(ts)) * 2) / 2, math.ceil(math.log10(max(ts)) * 2) / 2
    w, h, left, right, top, bottom = 760, 440, 70, 200, 30, 50

    def px(n):
        return left + (math.log10(n) - x0) / (x1 - x0) * (w - left - right)

    def py(t):
        return top + (y1 - math.log10(t)) / (y1 - y0) * (h - top - bottom)

    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="12">',
           f'<rect width="{w}" height="{h}" fill="white"/>',
           f'<text x="{left}" y="18" font-size="14">rotate_batch, float: ns per point against n (log-log, CPU time)</text>']
    n = min(ns)
    while n <= max(ns):
        x = px(n)
        svg.append(f'<line x1="{x:.1f}" y1="{top}" x2="{x:.1f}" y2="{h - bottom}" stroke="#ddd"/>')
        label = f"{n // 1048576}M" if n >= 1048576 else (f"{n // 1024}K" if n >= 1024 else str(n))
        svg.append(f'<text x="{x:.1f}" y="{h - bottom + 16}" text-anchor="middle">{label}</text>')
        n *= 4
    e = y0
    while e <= y1 + 1e-9:
        y = py(10 ** e)
        svg.append(f'<line x1="{left}" y1="{y:.1f}" x2="{w - right}" y2="{y:.1f}" stroke="#ddd"/>')
        svg.append(f'<text x="{left - 6}" y="{y + 4:.1f}" text-anchor="end">{10 ** e:.3g}</text>')
        e += 0.5
    svg.append(f'<text x="{(left + w - right) / 2}" y="{h - 10}" text-anchor="middle">points n</text>')
    svg.append(f'<text x="16" y="{(top + h - bottom) / 2}" transform="rotate(-90 16 {(top + h - bottom) / 2})" '
               'text-anchor="middle">ns per point</text>')
    for i, ((lib, rep), pts) in enumerate(sorted(lines.items())):
        color, dash = COLORS.get(lib, "black"), DASH.get(rep, "")
        path = " ".join(f"{px(n):.1f},{py(t):.1f}" for n, t in pts)
        svg.append(f'<polyline points="{path}" fill="none" stroke="{color}" stroke-width="2" stroke-dasharray="{dash}"/>')
        y = top + 10 + 18 * i
        svg.append(f'<line x1="{w - right + 10}" y1="{y}" x2="{w - right + 40}" y2="{y}" stroke="{color}" '
                   f'stroke-width="2" stroke-dasharray="{dash}"/>')
        svg.append(f'<text x="{w - right + 46}" y="{y + 4}">{lib} {rep}</text>')
    svg.append("</svg>")
    with open(output, "w") as f:
        f.write("\n".join(svg) + "\n")
    print("wrote", output)


if __name__ == "__main__":
    main()
