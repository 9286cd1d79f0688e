#!/usr/bin/python3
"""Writes tests/data/scipy_spline_reference.hpp: SciPy's RotationSpline (rotation, angular velocity
and angular acceleration) and Slerp on seeded keyframes, so the tests compare quat against SciPy
without needing SciPy themselves.

    /usr/bin/python3 tools/scipy_spline_reference.py    (from the repository root; needs SciPy, NumPy)

Fixed seeds: running it again with the same SciPy and NumPy rewrites the same file. Numbers are
written as Python's repr of a double (the shortest string that reads back to the same double).
The file is passed through clang-format when it is on the PATH, as CI checks formatting.

Conventions: SciPy's as_quat() is scalar last (x, y, z, w); the file holds (w, x, y, z). Keyframes
are written as given to SciPy, about half of them negated (q and -q are one rotation); results
have w >= 0.

RotationSpline finds the angular rates at the inner keyframes with a fixed-point iteration (one
banded solve per step) that stops after RotationSpline.MAX_ITER = 10 steps or once a step changes
every rate by less than TOL = 1e-9 relative. Each spline set is therefore evaluated twice: with
SciPy's defaults (what SciPy users get) and with MAX_ITER = 100000, TOL = 1e-14 (the C^2 spline
the iteration approximates, when the iteration converges). The number of steps is found by
counting calls of the module-level solve_banded of scipy.spatial.transform._rotation_spline. A run
met its tolerance iff it took fewer than MAX_ITER steps, or exactly MAX_ITER steps and a rerun with
MAX_ITER + 1 allowed takes MAX_ITER steps as well.
"""

import contextlib
import os
import shutil
import subprocess
import warnings

import numpy as np
import scipy
import scipy.spatial.transform._rotation_spline as rotation_spline_module
from scipy.spatial.transform import Rotation, RotationSpline, Slerp

from scipy_reference import flat, number, rows  # the same number format as the other data

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
OUTPUT = os.path.join(ROOT, "tests", "data", "scipy_spline_reference.hpp")

SEED = 20190601
DEFAULT_MAX_ITER, DEFAULT_TOL = 10, 1e-9
LONG_MAX_ITER, LONG_TOL = 100000, 1e-14
MAX_SAMPLES = 64  # per set; keeps the header small

# Ranges (rad) the random-walk step angles are drawn from.
SMALL, MODERATE, LARGE, HALF_TURN = (0.0, 0.1), (0.0, 1.0), (1.5, 2.5), (2.5, 3.1)


# --- counting SciPy's fixed-point steps -------------------------------------------------------

class SolveCounter:
    def __init__(self, solve):
        self.solve = solve
        self.calls = 0

    def __call__(self, *args, **kwargs):
        self.calls += 1
        return self.solve(*args, **kwargs)


COUNTER = SolveCounter(rotation_spline_module.solve_banded)
rotation_spline_module.solve_banded = COUNTER


@contextlib.contextmanager
def solver(max_iter, tol):
    RotationSpline.MAX_ITER, RotationSpline.TOL = max_iter, tol
    try:
        yield
    finally:
        RotationSpline.MAX_ITER, RotationSpline.TOL = DEFAULT_MAX_ITER, DEFAULT_TOL


def build_spline(times, rotations, max_iter, tol):
    """The spline, the number of fixed-point steps, and whether the run met its tolerance."""
    with solver(max_iter, tol):
        COUNTER.calls = 0
        spline = RotationSpline(times, rotations)
        steps = COUNTER.calls
    converged = steps < max_iter
    if steps == max_iter:
        with solver(max_iter + 1, tol), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            COUNTER.calls = 0
            try:
                RotationSpline(times, rotations)
            except ValueError:  # one more step overflowed: solve_banded refuses inf and NaN
                pass
            converged = COUNTER.calls == max_iter
    return spline, steps, converged


# --- inputs ------------------------------------------------------------------------------------

def unit(v):
    return v / np.linalg.norm(v)


def wxyz(quaternions_xyzw):
    q = np.asarray(quaternions_xyzw, dtype=float).reshape(-1, 4)[:, [3, 0, 1, 2]]
    return np.where(q[:, :1] < 0, -q, q)


def walk(rng, count, angles, start=None):
    """Keyframes q_{i+1} = q_i exp(step_i), step angles drawn from the range `angles`."""
    r = Rotation.random(random_state=rng.integers(1 << 31)) if start is None else start
    keys = [r]
    for _ in range(count - 1):
        angle = rng.uniform(*angles)
        r = r * Rotation.from_rotvec(angle * unit(rng.normal(size=3)))
        keys.append(r)
    return keys


def stored(rng, keys):
    """(w, x, y, z) with w >= 0, then about half of them negated, as written and given to SciPy."""
    q = wxyz(np.array([k.as_quat() for k in keys]))
    flip = np.zeros(len(q), dtype=bool)
    flip[rng.permutation(len(q))[:len(q) // 2 + rng.integers(0, 2) * (len(q) % 2)]] = True
    q[flip] = -q[flip]
    return q


def scipy_rotations(q_wxyz):
    return Rotation.from_quat(q_wxyz[:, [1, 2, 3, 0]])


def uneven_times(rng, count, t0=0.0, steps="uniform"):
    if steps == "uniform":
        dt = rng.uniform(0.05, 2.0, size=count - 1)
    else:  # steps over a factor of 100, both ends present
        u = rng.uniform(0.0, 1.0, size=count - 1)
        u[:2] = (0.0, 1.0)
        dt = 0.02 * 100.0 ** rng.permutation(u)
    return t0 + np.concatenate([[0.0], np.cumsum(dt)])


def sample_times(rng, times, budget, outside):
    """Every keyframe time, points inside the segments (2 or 3 each, or as many as the budget
    leaves but at least (n - 1) // 3, spread evenly), and, when `outside`, 2 points before and 2
    after within 10% of the span."""
    n = len(times)
    extra = 4 if outside else 0
    segments = n - 1
    interior = max(budget - n - extra, segments // 3)  # at least one in every third segment
    per = np.full(segments, 2)
    per[rng.random(segments) < 0.5] = 3
    if per.sum() > interior:  # many segments: interior // segments each, one more in some
        per[:] = interior // segments
        per[rng.permutation(segments)[:interior % segments]] += 1
    samples = list(times)
    for i in range(segments):
        f = np.sort(rng.uniform(0.05, 0.95, size=per[i]))
        samples.extend(times[i] + f * (times[i + 1] - times[i]))
    if outside:
        span = times[-1] - times[0]
        f = np.sort(rng.uniform(0.02, 1.0, size=2))
        samples.extend(times[0] - 0.1 * span * f)
        samples.extend(times[-1] + 0.1 * span * f)
    samples = np.array(sorted(samples))
    assert all(t in samples for t in times)
    return samples


# --- RotationSpline ----------------------------------------------------------------------------

def spline_set(name, k, count, angles=MODERATE, kind="walk", t0=0.0, steps="uniform"):
    rng = np.random.default_rng((SEED, k))
    if kind == "walk":
        keys = walk(rng, count, angles)
    elif kind == "uniform":
        keys = [Rotation.random(random_state=rng.integers(1 << 31)) for _ in range(count)]
    elif kind == "repeat":
        keys = walk(rng, count - 1, angles)
        i = count // 2
        keys.insert(i, keys[i - 1])  # keys[i] == keys[i - 1]: one step of zero angle
    elif kind == "axes":
        keys = [Rotation.random(random_state=rng.integers(1 << 31))]
        for axis in rng.integers(0, 3, size=count - 1):
            keys.append(keys[-1] * Rotation.from_rotvec(np.pi / 2 * np.eye(3)[axis]))
    else:
        raise ValueError(kind)
    return dict(name=name, times=uneven_times(rng, count, t0, steps), keys=stored(rng, keys),
                rng=rng)


SPLINE_SETS = [
    dict(name="2 keyframes, moderate step", k=0, count=2),
    dict(name="2 keyframes, step near a half turn", k=1, count=2, angles=HALF_TURN),
    dict(name="3 keyframes, small steps", k=2, count=3, angles=SMALL),
    dict(name="4 keyframes, moderate steps", k=3, count=4),
    dict(name="5 keyframes, large steps", k=4, count=5, angles=LARGE),
    dict(name="7 keyframes, moderate steps", k=5, count=7),
    dict(name="10 keyframes, small steps", k=6, count=10, angles=SMALL),
    dict(name="10 keyframes, large steps", k=7, count=10, angles=LARGE),
    dict(name="16 keyframes, moderate steps", k=8, count=16),
    dict(name="16 keyframes, steps near half turns", k=9, count=16, angles=HALF_TURN),
    dict(name="25 keyframes, large steps", k=11, count=25, angles=LARGE),
    dict(name="50 keyframes, moderate steps", k=13, count=50),
    dict(name="50 keyframes, large steps", k=14, count=50, angles=LARGE),
    dict(name="random count, small steps", k=15, angles=SMALL),
    dict(name="random count, moderate steps", k=16),
    dict(name="random count, large steps", k=17, angles=LARGE),
    dict(name="random count, steps near half turns", k=18, angles=HALF_TURN),
    dict(name="12 uniformly random keyframes", k=19, count=12, kind="uniform"),
    dict(name="8 keyframes, two consecutive equal (zero step)", k=20, count=8, kind="repeat"),
    dict(name="6 keyframes, steps of pi/2 about coordinate axes", k=21, count=6, kind="axes"),
    dict(name="20 keyframes, time steps from 0.02 to 2", k=22, count=20, steps="factor100"),
    dict(name="12 keyframes, t0 = 1000", k=23, count=12, t0=1000.0),
    # k = 125 is the first of k = 100, 101, ... whose long run neither converges nor overflows
    # (the iteration wanders on); reference_converged is false. Of k = 100..159, 18 overflow within
    # about 60 steps (SciPy then raises in solve_banded, so they cannot be written) and 4 wander.
    dict(name="25 keyframes, near half turns, long run wanders", k=125, count=25,
         angles=HALF_TURN),
]


def evaluate(spline, samples):
    rotation = wxyz(spline(samples).as_quat())
    return rotation, spline(samples, 1), spline(samples, 2)


def relative(a, b):
    return np.max(np.linalg.norm(a - b, axis=1) / (1 + np.linalg.norm(b, axis=1)))


def spline_cases():
    cases = []
    for spec in SPLINE_SETS:
        spec = dict(spec)
        if "count" not in spec:
            spec["count"] = int(np.random.default_rng((SEED, spec["k"], 1)).integers(2, 51))
            spec["name"] = spec["name"].replace("random count", "%d keyframes" % spec["count"])
        c = spline_set(**spec)
        rotations = scipy_rotations(c["keys"])
        samples = sample_times(c["rng"], c["times"], MAX_SAMPLES, outside=True)
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # an overflow in the iteration must not pass silently
            spline, steps, converged = build_spline(c["times"], rotations, DEFAULT_MAX_ITER,
                                                    DEFAULT_TOL)
            long_spline, long_steps, long_converged = build_spline(c["times"], rotations,
                                                                   LONG_MAX_ITER, LONG_TOL)
        if len(c["times"]) == 2:
            assert steps == 0 and long_steps == 0
        c.update(samples=samples, scipy_iterations=steps, scipy_converged=converged,
                 reference_iterations=long_steps, reference_converged=long_converged)
        c["rotation"], c["angular_velocity"], c["angular_acceleration"] = evaluate(spline, samples)
        (c["converged_rotation"], c["converged_angular_velocity"],
         c["converged_angular_acceleration"]) = evaluate(long_spline, samples)
        c["angle"] = np.max((spline(samples).inv() * long_spline(samples)).magnitude())
        c["velocity"] = relative(c["angular_velocity"], c["converged_angular_velocity"])
        c["acceleration"] = relative(c["angular_acceleration"],
                                     c["converged_angular_acceleration"])
        cases.append(c)
    # What the sets are for: SciPy's default run both meeting and missing its tolerance.
    assert sum(c["scipy_converged"] for c in cases) >= 3
    assert sum(not c["scipy_converged"] for c in cases) >= 3
    return cases


def table(cases):
    lines = ["%-48s %2s %4s %6s %4s %7s %7s %7s"
             % ("set (n keyframes)", "it", "conv", "long", "conv", "angle", "vel", "acc")]
    for c in cases:
        lines.append("%-48s %2d %4s %6d %4s %7.1e %7.1e %7.1e"
                     % (c["name"], c["scipy_iterations"],
                        "yes" if c["scipy_converged"] else "no", c["reference_iterations"],
                        "yes" if c["reference_converged"] else "no", c["angle"], c["velocity"],
                        c["acceleration"]))
    ok = [c for c in cases if c["reference_converged"]]
    lines.append("max where the long run converged: angle %.1e rad, velocity %.1e, "
                 "acceleration %.1e" % (max(c["angle"] for c in ok), max(c["velocity"] for c in ok),
                                        max(c["acceleration"] for c in ok)))
    lines.append("max over all sets: angle %.1e rad, velocity %.1e, acceleration %.1e"
                 % (max(c["angle"] for c in cases), max(c["velocity"] for c in cases),
                    max(c["acceleration"] for c in cases)))
    return lines


# --- Slerp -------------------------------------------------------------------------------------

SLERP_SETS = [
    dict(name="2 keyframes, moderate step", k=1000, count=2, angles=MODERATE),
    dict(name="2 keyframes, step near a half turn", k=1001, count=2, angles=(3.0, 3.14)),
    dict(name="3 keyframes, small steps", k=1002, count=3, angles=SMALL),
    dict(name="5 keyframes, large steps", k=1003, count=5, angles=LARGE),
    dict(name="10 keyframes, steps near half turns", k=1004, count=10, angles=(2.8, 3.14)),
    dict(name="17 keyframes, moderate steps", k=1005, count=17, angles=MODERATE),
    dict(name="30 keyframes, steps up to near a half turn", k=1006, count=30, angles=(0.0, 3.1)),
    dict(name="50 keyframes, moderate steps, t0 = 1000", k=1007, count=50, angles=MODERATE,
         t0=1000.0),
]


def slerp_cases():
    cases = []
    for spec in SLERP_SETS:
        rng = np.random.default_rng((SEED, spec["k"]))
        keys = stored(rng, walk(rng, spec["count"], spec["angles"]))
        times = uneven_times(rng, spec["count"], spec.get("t0", 0.0))
        samples = sample_times(rng, times, MAX_SAMPLES, outside=False)
        rotation = wxyz(Slerp(times, scipy_rotations(keys))(samples).as_quat())
        cases.append(dict(name=spec["name"], times=times, keys=keys, samples=samples,
                          rotation=rotation))
    return cases


# --- output ------------------------------------------------------------------------------------

def boolean(b):
    return "true" if b else "false"


SPLINE_STRUCT = """\
/// RotationSpline(times, rotations) at sample times, as SciPy 1.10 computes it (MAX_ITER = 10,
/// TOL = 1e-9 in its fixed-point solver), and the same spline with that solver run to convergence.
struct spline_case {
    const char* name;
    std::size_t count;    // keyframes, >= 2
    const double* times;  // strictly increasing, uneven steps
    // (w, x, y, z); about half the keyframes negated (w < 0): q and -q are one rotation
    const double (*rotations)[4];
    std::size_t samples;
    // Includes every keyframe time exactly, points inside segments, and a few points up to 10% of
    // the span outside [t0, tN] (SciPy extrapolates the end cubics).
    const double* sample_times;
    const double (*rotation)[4];              // spline(t) from default SciPy, (w, x, y, z), w >= 0
    const double (*angular_velocity)[3];      // spline(t, 1), rad/s
    const double (*angular_acceleration)[3];  // spline(t, 2), rad/s^2
    // Fixed-point iterations the default run used (counted solve_banded calls; 0 for 2 keyframes).
    int scipy_iterations;
    bool scipy_converged;      // whether the default run met its own tolerance within its 10 iterations
    bool reference_converged;  // whether the long run below met its tolerance
    int reference_iterations;
    // Same samples, solver run with MAX_ITER = 100000, TOL = 1e-14 (set as the class attributes
    // RotationSpline.MAX_ITER / TOL). For 2 keyframes there is no iteration: same arrays as above.
    const double (*converged_rotation)[4];
    const double (*converged_angular_velocity)[3];
    const double (*converged_angular_acceleration)[3];
};"""

SLERP_STRUCT = """\
/// Slerp(times, rotations)(t) for t inside [t0, tN] (SciPy raises outside), including every
/// keyframe time.
struct slerp_case {
    const char* name;
    std::size_t count;
    const double* times;
    const double (*rotations)[4];  // (w, x, y, z), about half negated
    std::size_t samples;
    const double* sample_times;
    const double (*rotation)[4];  // (w, x, y, z), w >= 0
};"""


def write():
    splines = spline_cases()
    summary = table(splines)
    for line in summary:
        print(line)
    slerps = slerp_cases()

    out = []
    out.append("// generated by tools/scipy_spline_reference.py; do not edit.")
    out.append("// SciPy %s, NumPy %s: RotationSpline(times, rotations) evaluated with order 0, 1, 2,"
               % (scipy.__version__, np.__version__))
    out.append("// with the default solver and with MAX_ITER = %d, TOL = %g; Slerp(times, rotations)."
               % (LONG_MAX_ITER, LONG_TOL))
    out.append("// Quaternions are (w, x, y, z).")
    out.append("//")
    out.append("// Default run vs long run: iterations, whether each met its tolerance, the largest angle")
    out.append("// (rad) between their rotations, and the largest |a - b| / (1 + |b|) (vector norms) of")
    out.append("// their angular velocities and accelerations, b the long run's, over the samples:")
    out.append("//")
    out.extend("// " + line for line in summary)
    out.append("#pragma once")
    out.append("")
    out.append("#include <cstddef>")
    out.append("")
    out.append("namespace quat::test::scipy {")
    out.append("")
    out.append(SPLINE_STRUCT)
    out.append("")
    out.append(SLERP_STRUCT)
    out.append("")
    entries = []
    for i, c in enumerate(splines):
        p = "spline_%d_" % i
        out.append("inline constexpr double %stimes[] = {%s};" % (p, flat(c["times"])))
        out.append("inline constexpr double %srotations[][4] = {%s};" % (p, rows(c["keys"], 4)))
        out.append("inline constexpr double %ssample_times[] = {%s};" % (p, flat(c["samples"])))
        names = {}
        for field, width in (("rotation", 4), ("angular_velocity", 3),
                             ("angular_acceleration", 3)):
            out.append("inline constexpr double %s%s[][%d] = {%s};"
                       % (p, field, width, rows(c[field], width)))
            names[field] = p + field
            long_field = "converged_" + field
            if np.array_equal(c[field], c[long_field]):  # 2 keyframes: no iteration at all
                names[long_field] = p + field
            else:
                out.append("inline constexpr double %s%s[][%d] = {%s};"
                           % (p, long_field, width, rows(c[long_field], width)))
                names[long_field] = p + long_field
        entries.append(
            "{\"%s\", %d, %stimes, %srotations, %d, %ssample_times, %s, %s, %s, %d, %s, %s, %d, "
            "%s, %s, %s}"
            % (c["name"], len(c["times"]), p, p, len(c["samples"]), p, names["rotation"],
               names["angular_velocity"], names["angular_acceleration"], c["scipy_iterations"],
               boolean(c["scipy_converged"]), boolean(c["reference_converged"]),
               c["reference_iterations"], names["converged_rotation"],
               names["converged_angular_velocity"], names["converged_angular_acceleration"]))
    out.append("")
    out.append("inline constexpr spline_case spline_cases[] = {%s};" % ", ".join(entries))
    out.append("")
    entries = []
    for i, c in enumerate(slerps):
        p = "slerp_%d_" % i
        out.append("inline constexpr double %stimes[] = {%s};" % (p, flat(c["times"])))
        out.append("inline constexpr double %srotations[][4] = {%s};" % (p, rows(c["keys"], 4)))
        out.append("inline constexpr double %ssample_times[] = {%s};" % (p, flat(c["samples"])))
        out.append("inline constexpr double %srotation[][4] = {%s};" % (p, rows(c["rotation"], 4)))
        entries.append("{\"%s\", %d, %stimes, %srotations, %d, %ssample_times, %srotation}"
                       % (c["name"], len(c["times"]), p, p, len(c["samples"]), p, p))
    out.append("")
    out.append("inline constexpr slerp_case slerp_cases[] = {%s};" % ", ".join(entries))
    out.append("")
    out.append("}  // namespace quat::test::scipy")
    os.makedirs(os.path.dirname(OUTPUT), exist_ok=True)
    with open(OUTPUT, "w") as f:
        f.write("\n".join(out) + "\n")
    formatter = shutil.which("clang-format") or shutil.which("clang-format-14")
    if formatter:
        subprocess.run([formatter, "-i", OUTPUT], check=True, cwd=ROOT)
    print("wrote", os.path.relpath(OUTPUT, ROOT), "(%d bytes)" % os.path.getsize(OUTPUT))


if __name__ == "__main__":
    write()
