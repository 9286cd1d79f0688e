#!/usr/bin/env python3
"""Fits the coefficients of quat::corrected_nlerp (include/quat/paths/slerp_fast.hpp).

nlerp at parameter tau moves along the slerp arc, but not at constant speed; slerp's point at t is
nlerp's point at

    tau*(t) = 1/2 + tan((t - 1/2) theta) / (2 tan(theta / 2)),

theta the angle between the two unit quaternions in 4D (cos theta = d = |a . b|, theta <= pi/2),
since (1 - tau) a + tau b points at slerp(a, b, t) when tau / (1 - tau) = sin(t theta) / sin((1 - t)
theta). corrected_nlerp replaces t by

    tau = t + t (t - 1/2) (t - 1) k(d, w),   w = t (1 - t) = 1/4 - (t - 1/2)^2,

the form of zeux (Arseny Kapoulkine), "Approximating slerp" (2015): tau = 0 at t = 0 and tau = 1 at
t = 1 whatever k is, and tau(1 - t) = 1 - tau(t). k is a polynomial with the monomials in
MONOMIALS (powers of d, powers of w); this script finds the coefficients that minimize the largest
rotation-angle error (twice the 4D angle) over a grid of theta in (0, pi/2] and t in [0, 1/2] (the
error is odd about t = 1/2): Lawson's iteratively reweighted least squares for the minimax of the
error linearized in the coefficients, relinearized a few times. numpy only.
Usage: python3 bench/fit_corrected_nlerp.py
"""
import numpy as np

# k(d, w) = sum of c_ij d^i w^j over these (i, j): a polynomial of degree 2 in d whose coefficients
# are linear in w (six terms; five without d^2 w give 9.2e-4 rad, nine with w^2 4.0e-4 rad).
MONOMIALS = [(0, 0), (0, 1), (1, 0), (1, 1), (2, 0), (2, 1)]


def grid(n_theta, n_t):
    theta = np.linspace(0.0, np.pi / 2, n_theta + 1)[1:]
    t = np.linspace(0.0, 0.5, n_t + 1)[1:-1]  # the ends are exact by construction
    return np.meshgrid(theta, t, indexing="ij")


def tau(c, theta, t):
    d, w = np.cos(theta), t * (1 - t)
    k = sum(ci * d**i * w**j for ci, (i, j) in zip(c, MONOMIALS))
    return t - (t - 0.5) * w * k


def angle_error(tau_value, theta, t):
    """Rotation-angle error (rad) of nlerp at tau_value against slerp at t."""
    phi = np.arctan2(tau_value * np.sin(theta), 1 - tau_value + tau_value * np.cos(theta))
    return 2 * (phi - t * theta)


def lawson(a, b, iterations=3000):
    """Approximately minimizes max |a c - b| (Lawson's algorithm)."""
    v = np.full(len(b), 1.0 / len(b))
    c = None
    for _ in range(iterations):
        s = np.sqrt(v)
        c = np.linalg.lstsq(a * s[:, None], b * s, rcond=None)[0]
        r = np.abs(a @ c - b)
        v = v * r + 1e-300
        v /= v.sum()
    return c


def fit(theta, t):
    c = np.zeros(len(MONOMIALS))
    d, w = np.cos(theta), t * (1 - t)
    for _ in range(4):
        tv = tau(c, theta, t)
        n2 = 1 - 2 * tv * (1 - tv) * (1 - d)
        slope = 2 * np.sin(theta) / n2  # d(rotation angle) / d tau
        columns = [(slope * -(t - 0.5) * w * d**i * w**j).ravel() for i, j in MONOMIALS]
        step = lawson(np.stack(columns, 1), -angle_error(tv, theta, t).ravel())
        c = c + step
    return c


def main():
    theta, t = grid(160, 80)
    c = fit(theta, t)
    fine_theta, fine_t = grid(2000, 1000)
    worst = np.abs(angle_error(tau(c, fine_theta, fine_t), fine_theta, fine_t)).max()
    plain = np.abs(angle_error(fine_t, fine_theta, fine_t)).max()
    print(f"k = sum c_ij d^i w^j, w = t (1 - t); largest rotation-angle error {worst:.3e} rad "
          f"(fit grid {np.abs(angle_error(tau(c, theta, t), theta, t)).max():.3e}; "
          f"plain nlerp {plain:.3e})")
    for ci, (i, j) in zip(c, MONOMIALS):
        print(f"  d^{i} w^{j}: {ci!r}")


if __name__ == "__main__":
    main()
