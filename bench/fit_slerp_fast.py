#!/usr/bin/env python3
"""Fits the coefficients of quat::slerp_fast (include/quat/paths/slerp_fast.hpp).

With theta the 4D angle between unit a and the nearer of b, -b (so theta <= pi/2), psi = theta / 2,
c = cos psi = sqrt((1 + |a . b|) / 2) and alpha = 2t - 1, the slerp weights of a and b are E - O and
E + O, where

    E = cos(alpha psi) / (2 c),   O = sin(alpha psi) / (2 sin psi):

sin(t theta) = sin(psi + alpha psi) = sin psi cos(alpha psi) + cos psi sin(alpha psi) and
sin theta = 2 sin psi cos psi. E is even in alpha and O odd, so one evaluation gives both weights.
As power series in y = c - 1 (from the Chebyshev equations that cos(alpha psi) and
sin(alpha psi) / sin psi satisfy as functions of c, the way Eberly 2011, "A fast and accurate
algorithm for computing SLERP", derives his series), with w = t (1 - t) = (1 - alpha^2) / 4:

    E = 1/2 - (w y / c) P(w, y),   P = 2 + (1 - 4w) y / 3 + ...
    O = u - u w y R(w, y),         R = 4/3 - (6 + 8w) y / 15 + ...,   u = t - 1/2.

w = 0 at t = 0 and t = 1, so there E = 1/2 and O = -1/2 or 1/2 exactly: the weights are exactly
(1, 0) and (0, 1) whatever P and R are. y lies in [cos(pi/4) - 1, 0], where the series converge fast;
slerp_fast keeps the monomials y^i w^j listed in P_MONOMIALS and R_MONOMIALS and this script fits
their coefficients to minimize the largest of the rotation-angle error (twice the 4D angle) and the
norm error | |r| - 1 | over a grid of theta in (0, pi/2] and t in [1/2, 1] (the errors at 1 - t
mirror those at t): Lawson's iteratively reweighted least squares for the minimax of the errors
linearized in the coefficients, relinearized a few times. numpy only.
Usage: python3 bench/fit_slerp_fast.py
"""
import numpy as np

# P: degree 3 in y, its y^i coefficient of degree min(i, 2) in w; R: the same without y^3 w^2.
# Dropping y^3 w^2 from P and y^3 w from R as well leaves 1.5e-7 instead of 3.3e-8.
P_MONOMIALS = [(0, 0), (1, 0), (1, 1), (2, 0), (2, 1), (2, 2), (3, 0), (3, 1), (3, 2)]
R_MONOMIALS = [(0, 0), (1, 0), (1, 1), (2, 0), (2, 1), (2, 2), (3, 0), (3, 1)]


class Grid:
    def __init__(self, n_theta, n_t):
        theta = np.linspace(0.0, np.pi / 2, n_theta + 1)[1:]
        t = np.linspace(0.5, 1.0, n_t + 1)[:-1]  # t = 1 is exact by construction
        self.theta, self.t = (a.ravel() for a in np.meshgrid(theta, t, indexing="ij"))
        self.c = np.cos(self.theta / 2)
        self.y = self.c - 1
        self.u = self.t - 0.5
        self.w = self.t * (1 - self.t)

    def weights(self, p, r):
        big_p = sum(pi * self.y**i * self.w**j for pi, (i, j) in zip(p, P_MONOMIALS))
        big_r = sum(ri * self.y**i * self.w**j for ri, (i, j) in zip(r, R_MONOMIALS))
        e = 0.5 - self.w * self.y / self.c * big_p
        o = self.u - self.u * self.w * self.y * big_r
        return e, o

    def errors(self, p, r, with_jacobian=True):
        """Rotation-angle error (rad) and | |r| - 1 | of the weights, and their derivatives."""
        e, o = self.weights(p, r)
        wa, wb = e - o, e + o
        cos_t, sin_t = np.cos(self.theta), np.sin(self.theta)
        n2 = wa * wa + wb * wb + 2 * wa * wb * cos_t
        n = np.sqrt(n2)
        angle = 2 * (np.arctan2(wb * sin_t, wa + wb * cos_t) - self.t * self.theta)
        if not with_jacobian:
            return angle, n - 1, None
        # d angle / dE, d angle / dO; d|r| / dE, d|r| / dO
        angle_e, angle_o = -4 * o * sin_t / n2, 4 * e * sin_t / n2
        norm_e, norm_o = (wa + wb) * (1 + cos_t) / n, (wb - wa) * (1 - cos_t) / n
        de = [-self.w * self.y / self.c * self.y**i * self.w**j for i, j in P_MONOMIALS]
        do = [-self.u * self.w * self.y * self.y**i * self.w**j for i, j in R_MONOMIALS]
        jacobian = np.vstack([
            np.stack([angle_e * x for x in de] + [angle_o * x for x in do], 1),
            np.stack([norm_e * x for x in de] + [norm_o * x for x in do], 1)])
        return angle, n - 1, jacobian


def lawson(a, b, iterations=3000):
    """Approximately minimizes max |a c - b| (Lawson's algorithm)."""
    v = np.full(len(b), 1.0 / len(b))
    c = None
    for _ in range(iterations):
        s = np.sqrt(v)
        c = np.linalg.lstsq(a * s[:, None], b * s, rcond=None)[0]
        v = v * np.abs(a @ c - b) + 1e-300
        v /= v.sum()
    return c


def main():
    grid = Grid(160, 80)
    # Start from the series: P = 2 + y/3 - 4wy/3, R = 4/3 - 2y/5 - 8wy/15.
    p = np.zeros(len(P_MONOMIALS))
    r = np.zeros(len(R_MONOMIALS))
    p[:3] = [2.0, 1.0 / 3, -4.0 / 3]
    r[:3] = [4.0 / 3, -2.0 / 5, -8.0 / 15]
    for _ in range(4):
        angle, norm, jacobian = grid.errors(p, r)
        step = lawson(jacobian, -np.concatenate([angle, norm]))
        p, r = p + step[: len(p)], r + step[len(p):]
    fine = Grid(1600, 800)
    angle, norm, _ = fine.errors(p, r, with_jacobian=False)
    print(f"largest rotation-angle error {np.abs(angle).max():.3e} rad, "
          f"largest | |r| - 1 | {np.abs(norm).max():.3e} (on a 1600 x 800 grid)")
    for name, values, monomials in (("P", p, P_MONOMIALS), ("R", r, R_MONOMIALS)):
        for value, (i, j) in zip(values, monomials):
            print(f"  {name}: y^{i} w^{j}: {value!r}")


if __name__ == "__main__":
    main()
