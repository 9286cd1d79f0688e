#!/usr/bin/env python3
"""Writes the input of examples/pose_graph.cpp: a 3D pose graph in g2o's text format.

A vehicle spirals up a sphere of radius 10 m, from the equator to 70 degrees north in 5 laps of
60 poses (300 poses, 0.4 m to 1.1 m apart), facing along its path with its z axis pointing out of
the sphere (seen from above, the laps are rings of shrinking radius). Edges:
  - odometry i -> i + 1 (299 edges),
  - loop closures i -> i + 60 (the pose one lap further north, 2.4 m away) for every second i
    (120 edges).
Every measurement is the true relative pose Z = X_i^-1 X_j moved by noise on the right,
Z_noisy = Z exp(n), with n a twist (linear part first, in the frame of Z, quat::se3's convention)
drawn from N(0, diag(s_t^2, s_t^2, s_t^2, s_r^2, s_r^2, s_r^2)), s_t = 0.03 m and s_r = 0.75 degree.
The information matrix written with each edge is the inverse of that covariance, for the error
(linear, angular) = log(Z^-1 X_i^-1 X_j) in those same coordinates. (g2o's own EDGE_SE3:QUAT error
uses the quaternion's vector part, half the rotation vector, as its rotation error; Ceres's
pose_graph_3d example, like this one, uses the rotation vector's scale.)

Files (g2o format, quaternion scalar LAST as g2o writes it):
  examples/data/pose_graph.g2o        VERTEX_SE3:QUAT id x y z qx qy qz qw (the initial estimate:
                                      the first true pose, then the noisy odometry chained) and
                                      EDGE_SE3:QUAT i j x y z qx qy qz qw + 21 numbers of the
                                      information matrix's upper triangle, row by row.
  examples/data/pose_graph_truth.g2o  VERTEX_SE3:QUAT lines of the true poses.
Fixed seed: rerunning writes the same files (numpy's PCG64 stream for seed 2026).
Usage: /usr/bin/python3 tools/pose_graph_data.py [output directory, default examples/data]
"""
import math
import os
import sys

import numpy as np

SEED = 2026
LAPS, PER_LAP = 5, 60
RADIUS = 10.0
LATITUDE = 70.0  # degrees climbed over the 5 laps, from the equator
SIGMA_T = 0.03  # m
SIGMA_R = math.radians(0.75)  # rad
CLOSURE_EVERY = 2


def hat(v):
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def so3_exp(w):
    """Rotation matrix of the rotation vector w (Rodrigues)."""
    th = np.linalg.norm(w)
    k = hat(w)
    if th < 1e-12:
        return np.eye(3) + k
    return np.eye(3) + math.sin(th) / th * k + (1 - math.cos(th)) / th**2 * k @ k


def se3_exp(n):
    """(R, t) of the twist n = (rho, omega): R = exp(omega), t = J_l(omega) rho."""
    rho, w = n[:3], n[3:]
    th = np.linalg.norm(w)
    k = hat(w)
    if th < 1e-6:
        v = np.eye(3) + 0.5 * k + k @ k / 6
    else:
        v = np.eye(3) + (1 - math.cos(th)) / th**2 * k + (th - math.sin(th)) / th**3 * k @ k
    return so3_exp(w), v @ rho


def to_quaternion(r):
    """Unit quaternion (w, x, y, z), w >= 0, of the rotation matrix r (Shepperd's method)."""
    tr = np.trace(r)
    d = [tr, r[0, 0], r[1, 1], r[2, 2]]
    i = int(np.argmax(d))
    if i == 0:
        w = math.sqrt(1 + tr) / 2
        q = [w, (r[2, 1] - r[1, 2]) / (4 * w), (r[0, 2] - r[2, 0]) / (4 * w),
             (r[1, 0] - r[0, 1]) / (4 * w)]
    else:
        j, k = (i % 3) + 1, ((i + 1) % 3) + 1
        a, b, c = i - 1, j - 1, k - 1
        s = math.sqrt(1 + r[a, a] - r[b, b] - r[c, c]) * 2
        q = [0.0] * 4
        q[0] = (r[c, b] - r[b, c]) / s
        q[i] = s / 4
        q[j] = (r[b, a] + r[a, b]) / s
        q[k] = (r[c, a] + r[a, c]) / s
    q = np.array(q)
    q /= np.linalg.norm(q)
    return q if q[0] >= 0 else -q


def true_poses():
    """(R, t) along the spiral, x axis along the path, z axis out of the sphere."""
    count = LAPS * PER_LAP
    poses = []
    for i in range(count):
        s = i / PER_LAP  # laps
        lon = 2 * math.pi * s
        lat = math.radians(LATITUDE * s / LAPS)
        p = RADIUS * np.array([math.cos(lat) * math.cos(lon), math.cos(lat) * math.sin(lon),
                               math.sin(lat)])
        # The path's direction: d/ds of p.
        dlon, dlat = 2 * math.pi, math.radians(LATITUDE / LAPS)
        d = RADIUS * np.array([
            -math.sin(lat) * dlat * math.cos(lon) - math.cos(lat) * math.sin(lon) * dlon,
            -math.sin(lat) * dlat * math.sin(lon) + math.cos(lat) * math.cos(lon) * dlon,
            math.cos(lat) * dlat])
        up = p / np.linalg.norm(p)
        x = d - np.dot(d, up) * up
        x /= np.linalg.norm(x)
        y = np.cross(up, x)
        poses.append((np.column_stack([x, y, up]), p))
    return poses


def between(a, b):
    ra, ta = a
    rb, tb = b
    return ra.T @ rb, ra.T @ (tb - ta)


def compose(a, b):
    ra, ta = a
    rb, tb = b
    return ra @ rb, ta + ra @ tb


def vertex_line(i, pose):
    r, t = pose
    q = to_quaternion(r)
    return "VERTEX_SE3:QUAT %d %.9f %.9f %.9f %.12f %.12f %.12f %.12f" % (
        i, t[0], t[1], t[2], q[1], q[2], q[3], q[0])


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.normpath(os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "examples", "data"))
    rng = np.random.default_rng(SEED)
    truth = true_poses()
    count = len(truth)
    pairs = [(i, i + 1) for i in range(count - 1)]
    pairs += [(i, i + PER_LAP) for i in range(0, count - PER_LAP, CLOSURE_EVERY)]
    sigma = np.array([SIGMA_T] * 3 + [SIGMA_R] * 3)
    info = np.diag(1 / sigma**2)
    info_text = " ".join("%.10g" % info[r, c] for r in range(6) for c in range(r, 6))
    edges, measured = [], {}
    for i, j in pairs:
        z = compose(between(truth[i], truth[j]), se3_exp(rng.normal(0.0, sigma)))
        measured[(i, j)] = z
        r, t = z
        q = to_quaternion(r)
        edges.append("EDGE_SE3:QUAT %d %d %.9f %.9f %.9f %.12f %.12f %.12f %.12f %s" % (
            i, j, t[0], t[1], t[2], q[1], q[2], q[3], q[0], info_text))
    initial = [truth[0]]
    for i in range(count - 1):
        initial.append(compose(initial[-1], measured[(i, i + 1)]))
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "pose_graph.g2o"), "w") as f:
        for i, pose in enumerate(initial):
            f.write(vertex_line(i, pose) + "\n")
        for line in edges:
            f.write(line + "\n")
    with open(os.path.join(out, "pose_graph_truth.g2o"), "w") as f:
        for i, pose in enumerate(truth):
            f.write(vertex_line(i, pose) + "\n")
    print("wrote %d poses, %d odometry edges, %d loop closures to %s" % (
        count, count - 1, len(pairs) - (count - 1), out))


if __name__ == "__main__":
    main()
