#!/usr/bin/python3
"""Writes tests/data/scipy_reference.hpp: SciPy's Rotation.align_vectors and Rotation.mean on
seeded inputs, so the tests compare quat against SciPy without needing SciPy themselves.

    /usr/bin/python3 tools/scipy_reference.py        (from the repository root; needs SciPy, NumPy)

Fixed seeds: running it again with the same SciPy and NumPy rewrites the same file. Numbers are
written as Python's repr of a double (the shortest string that reads back to the same double).
The file is passed through clang-format when it is on the PATH, as CI checks formatting.

Conventions: SciPy's as_quat() is scalar last (x, y, z, w); the file holds (w, x, y, z) with
w >= 0, quat's order. align_vectors(a, b) finds R with a ~ R b, so a = targets, b = sources.
"""

import os
import shutil
import subprocess

import numpy as np
import scipy
from scipy.spatial.transform import Rotation

OUTPUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data",
                      "scipy_reference.hpp")


def wxyz(rotation):
    x, y, z, w = rotation.as_quat()
    q = np.array([w, x, y, z])
    return -q if q[0] < 0 else q


def number(x):
    x = float(x)
    if not np.isfinite(x):
        raise ValueError("non-finite reference value")
    return repr(x)


def align_cases():
    rng = np.random.default_rng(20190501)
    cases = []

    def add(name, targets, sources, weights=None):
        n = len(sources)
        w = np.ones(n) if weights is None else np.asarray(weights, dtype=float)
        rotation, rssd, sensitivity = Rotation.align_vectors(targets, sources, w,
                                                             return_sensitivity=True)
        # SciPy's own test of a well-defined optimum (its warning is s1 + s2 < 1e-16 s0); every
        # case here must pass a far stricter one, so comparing rotations is meaningful.
        u, s, vh = np.linalg.svd((w[:, None] * targets).T @ sources)
        if np.linalg.det(u @ vh) < 0:
            s[-1] = -s[-1]
        assert s[1] + s[2] > 1e-6 * s[0], name
        cases.append(dict(name=name, targets=np.asarray(targets, dtype=float),
                          sources=np.asarray(sources, dtype=float), weights=w,
                          rotation=wxyz(rotation), rssd=rssd, sensitivity=sensitivity))

    for n in (2, 3, 5, 16, 100):
        r = Rotation.random(random_state=rng.integers(1 << 31))
        sources = rng.normal(size=(n, 3))
        add("exact, n = %d" % n, r.apply(sources), sources)
    for n in (5, 16, 100):
        r = Rotation.random(random_state=rng.integers(1 << 31))
        sources = rng.normal(size=(n, 3))
        add("noisy, n = %d" % n, r.apply(sources) + 0.05 * rng.normal(size=(n, 3)), sources)
    r = Rotation.random(random_state=rng.integers(1 << 31))
    sources = rng.normal(size=(12, 3))
    weights = rng.uniform(0.1, 3.0, size=12)
    weights[[1, 4, 5, 10]] = 0.0
    add("weighted, four zero weights, n = 12",
        r.apply(sources) + 0.05 * rng.normal(size=(12, 3)), sources, weights)
    r = Rotation.random(random_state=rng.integers(1 << 31))
    sources = rng.normal(size=(20, 3)) * rng.uniform(1e-3, 1e3, size=(20, 1))
    add("lengths from 1e-3 to 1e3, weighted, n = 20",
        r.apply(sources) * (1 + 1e-3 * rng.normal(size=(20, 1))), sources,
        rng.uniform(0.5, 2.0, size=20))
    r = Rotation.random(random_state=rng.integers(1 << 31))
    sources = rng.normal(size=(6, 3))
    sources[:, 2] = 0.0
    add("coplanar sources, n = 6", r.apply(sources) + 0.01 * rng.normal(size=(6, 3)), sources)
    add("antiparallel pairs: x -> -x, y -> -y", np.array([[-1.0, 0, 0], [0, -2.0, 0]]),
        np.array([[1.0, 0, 0], [0, 1.0, 0]]))
    sources = rng.normal(size=(5, 3))
    add("point reflection: targets = -sources, n = 5", -sources, sources)
    r = Rotation.random(random_state=rng.integers(1 << 31))
    sources = rng.normal(size=(6, 3))
    targets = r.apply(sources) + 0.02 * rng.normal(size=(6, 3))
    targets[0] = -sources[0]
    add("one antiparallel pair among noisy ones, n = 6", targets, sources)
    r = Rotation.random(random_state=rng.integers(1 << 31))
    sources = rng.normal(size=(8, 3))
    add("reflected targets (Kabsch's det < 0 case), n = 8",
        r.apply(sources) * np.array([1.0, 1.0, -1.0]) + 0.01 * rng.normal(size=(8, 3)), sources)
    return cases


def mean_cases():
    rng = np.random.default_rng(20070701)
    cases = []

    def add(name, rotations, weights=None):
        n = len(rotations)
        w = np.ones(n) if weights is None else np.asarray(weights, dtype=float)
        quaternions = np.array([wxyz(r) for r in rotations])
        flips = rng.random(n) < 0.5  # q and -q are one rotation; the mean must not care
        quaternions[flips] = -quaternions[flips]
        mean = Rotation.from_quat(quaternions[:, [1, 2, 3, 0]]).mean(w)
        k = (w[:, None] * quaternions).T @ quaternions
        values = np.linalg.eigvalsh(k)
        assert values[-1] - values[-2] > 1e-6 * np.sum(w), name
        cases.append(dict(name=name, rotations=quaternions, weights=w, mean=wxyz(mean)))

    def cluster(n, spread):
        center = Rotation.random(random_state=rng.integers(1 << 31))
        return [center * Rotation.from_rotvec(spread * rng.normal(size=3)) for _ in range(n)]

    add("cluster, spread 0.1 rad, n = 10", cluster(10, 0.1))
    add("cluster, spread 0.5 rad, n = 100", cluster(100, 0.5))
    add("weighted cluster with zero weights, n = 20", cluster(20, 0.3),
        np.where(rng.random(20) < 0.25, 0.0, rng.uniform(0.1, 5.0, size=20)))
    add("uniformly random, n = 50",
        [Rotation.random(random_state=rng.integers(1 << 31)) for _ in range(50)])
    add("two rotations, unequal weights", cluster(2, 1.0), [1.0, 3.0])
    return cases


def rows(values, per_row):
    values = [number(v) for v in np.ravel(values)]
    return ", ".join("{" + ", ".join(values[i:i + per_row]) + "}"
                     for i in range(0, len(values), per_row))


def flat(values):
    return ", ".join(number(v) for v in np.ravel(values))


def write():
    out = []
    out.append("// generated by tools/scipy_reference.py; do not edit.")
    out.append("// SciPy %s, NumPy %s: Rotation.align_vectors(a = targets, b = sources, weights,"
               % (scipy.__version__, np.__version__))
    out.append("// return_sensitivity=True) and Rotation.mean(weights) on seeded inputs.")
    out.append("// Quaternions are (w, x, y, z) with w >= 0.")
    out.append("#pragma once")
    out.append("")
    out.append("#include <cstddef>")
    out.append("")
    out.append("namespace quat::test::scipy {")
    out.append("")
    out.append("/// One align_vectors input and SciPy's answer.")
    out.append("struct align_case {")
    out.append("    const char* name;")
    out.append("    std::size_t count;")
    out.append("    const double (*targets)[3];")
    out.append("    const double (*sources)[3];")
    out.append("    const double* weights;")
    out.append("    double rotation[4];  // (w, x, y, z), w >= 0")
    out.append("    double rssd;         // SciPy's: sqrt of sum w (|a|^2 + |b|^2) - 2 (s0 + s1 + s2)")
    out.append("    double sensitivity[3][3];")
    out.append("};")
    out.append("")
    out.append("/// One mean input (some quaternions negated) and SciPy's answer.")
    out.append("struct mean_case {")
    out.append("    const char* name;")
    out.append("    std::size_t count;")
    out.append("    const double (*rotations)[4];  // (w, x, y, z)")
    out.append("    const double* weights;")
    out.append("    double mean[4];  // (w, x, y, z), w >= 0")
    out.append("};")
    out.append("")
    entries = []
    for i, c in enumerate(align_cases()):
        out.append("inline constexpr double align_targets_%d[][3] = {%s};" % (i, rows(c["targets"], 3)))
        out.append("inline constexpr double align_sources_%d[][3] = {%s};" % (i, rows(c["sources"], 3)))
        out.append("inline constexpr double align_weights_%d[] = {%s};" % (i, flat(c["weights"])))
        entries.append("{\"%s\", %d, align_targets_%d, align_sources_%d, align_weights_%d, {%s}, %s, {%s}}"
                       % (c["name"], len(c["sources"]), i, i, i, flat(c["rotation"]),
                          number(c["rssd"]), rows(c["sensitivity"], 3)))
    out.append("")
    out.append("inline constexpr align_case align_cases[] = {%s};" % ", ".join(entries))
    out.append("")
    entries = []
    for i, c in enumerate(mean_cases()):
        out.append("inline constexpr double mean_rotations_%d[][4] = {%s};" % (i, rows(c["rotations"], 4)))
        out.append("inline constexpr double mean_weights_%d[] = {%s};" % (i, flat(c["weights"])))
        entries.append("{\"%s\", %d, mean_rotations_%d, mean_weights_%d, {%s}}"
                       % (c["name"], len(c["rotations"]), i, i, flat(c["mean"])))
    out.append("")
    out.append("inline constexpr mean_case mean_cases[] = {%s};" % ", ".join(entries))
    out.append("")
    out.append("}  // namespace quat::test::scipy")
    os.makedirs(os.path.dirname(OUTPUT), exist_ok=True)
    with open(OUTPUT, "w") as f:
        f.write("\n".join(out) + "\n")
    formatter = shutil.which("clang-format") or shutil.which("clang-format-14")
    if formatter:
        subprocess.run([formatter, "-i", OUTPUT], check=True,
                       cwd=os.path.dirname(os.path.dirname(OUTPUT)))
    print("wrote", os.path.normpath(OUTPUT))


if __name__ == "__main__":
    write()
