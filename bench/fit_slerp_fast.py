#!/usr/bin/env python3
"""Fits the one free constant of quat::slerp_fast (include/quat/fast_slerp.hpp).

sin(s*h)/sin(h) = sum_i b_i(s) (c - 1)^i with c = cos(h), b_0 = s and
b_i = b_{i-1} (s^2 - i^2) / (i (2i + 1))  (Eberly 2011's recurrence, derived from the Chebyshev ODE
(1 - c^2) f'' - 3 c f' + (s^2 - 1) f = 0). slerp_fast halves the angle first, so h <= pi/4 and
c - 1 is in [-0.293, 0]; the series is cut after N terms and the last coefficient is scaled by
(1 + mu) to stand in for the dropped tail. This script finds the mu that minimizes the largest
error over a grid of h and s, in double precision. Usage: python3 bench/fit_slerp_fast.py [N]
"""
import math
import sys


def weight(c, s, n, mu):
    y, acc = c - 1.0, 1.0
    for i in range(n, 0, -1):
        k = (s * s - i * i) / (i * (2 * i + 1))
        if i == n:
            k *= 1.0 + mu
        acc = 1.0 + k * y * acc
    return s * acc


def max_error(n, mu, steps=200):
    worst = 0.0
    for a in range(1, steps + 1):
        h = a / steps * math.pi / 4
        c, sh = math.cos(h), math.sin(h)
        for b in range(steps + 1):
            s = b / steps
            worst = max(worst, abs(weight(c, s, n, mu) - math.sin(s * h) / sh))
    return worst


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 6
    low, high = 0.0, 0.5
    for _ in range(40):  # golden-section search; the max error is unimodal in mu here
        m1, m2 = low + (high - low) * 0.382, low + (high - low) * 0.618
        if max_error(n, m1, 60) < max_error(n, m2, 60):
            high = m2
        else:
            low = m1
    mu = (low + high) / 2
    print(f"N = {n}: mu = {mu:.10f}, max error {max_error(n, mu):.3e} (without mu {max_error(n, 0.0):.3e})")


if __name__ == "__main__":
    main()
