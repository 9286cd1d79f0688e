// Approximate slerp without trigonometry: a short polynomial in cos(angle), after Eberly 2011,
// "A fast and accurate algorithm for computing SLERP" (J. Graphics, GPU, and Game Tools 15(3)).
#ifndef QUAT_FAST_SLERP_HPP_INCLUDED
#define QUAT_FAST_SLERP_HPP_INCLUDED

#include "detail/math.hpp"
#include "quaternion.hpp"

namespace quat {

namespace detail {

// sin(s h) / sin(h) as a polynomial in y = cos(h) - 1, for h in [0, pi/4] and s in [0, 1].
// The power series sum_i b_i(s) y^i has b_0 = s and b_i = b_{i-1} (s^2 - i^2) / (i (2i + 1)): put
// f = sum b_i y^i into the ODE (1 - c^2) f'' - 3 c f' + (s^2 - 1) f = 0 that sin(s h) / sin(h)
// satisfies as a function of c = cos(h) (the Chebyshev U equation), and match powers of y.
// Six terms are kept; the sixth coefficient is scaled by 1 + mu to stand in for the dropped tail
// (mu fitted by bench/fit_slerp_fast.py: largest error 8.3e-9 against 1.8e-7 without it).
template <class T>
[[nodiscard]] constexpr T slerp_weight(T y, T s) noexcept {
    // b_i / b_{i-1} = s^2 u_i - v_i with u_i = 1 / (i (2i + 1)), v_i = i / (2i + 1), as constants
    // (a division by a literal is not turned into a multiplication without -ffast-math).
    // const, not constexpr: a user scalar need not be a literal type.
    const T mu = T(0.1502107483);
    const T u1 = T(1) / T(3), v1 = T(1) / T(3), u2 = T(1) / T(10), v2 = T(2) / T(5);
    const T u3 = T(1) / T(21), v3 = T(3) / T(7), u4 = T(1) / T(36), v4 = T(4) / T(9);
    const T u5 = T(1) / T(55), v5 = T(5) / T(11);
    const T u6 = (T(1) + mu) / T(78), v6 = (T(1) + mu) * T(6) / T(13);
    const T s2 = s * s;
    // Horner from the innermost term: acc_i = 1 + (b_i / b_{i-1}) y acc_{i+1}.
    T acc = T(1) + (s2 * u6 - v6) * y;
    acc = T(1) + (s2 * u5 - v5) * y * acc;
    acc = T(1) + (s2 * u4 - v4) * y * acc;
    acc = T(1) + (s2 * u3 - v3) * y * acc;
    acc = T(1) + (s2 * u2 - v2) * y * acc;
    acc = T(1) + (s2 * u1 - v1) * y * acc;
    return s * acc;
}

}  // namespace detail

/// Slerp from unit a (t = 0) to unit b (t = 1) along the shorter arc, approximated without
/// trigonometry: rotation-angle error below 1e-6 rad in float (tests/test_fast_slerp.cpp), exact
/// at t = 0 and t = 1. Precondition: unit a, b and t in [0, 1] (outside it the error grows quickly).
template <class T>
[[nodiscard]] constexpr quaternion<T> slerp_fast(const quaternion<T>& a, const quaternion<T>& b,
                                                 detail::type_identity_t<T> t) noexcept {
    const T d = dot(a, b);
    // Selections by arithmetic on 0/1 instead of branches: with random inputs a branch on the sign
    // or on t < 1/2 is mispredicted half the time, which costs more than the whole polynomial.
    const T negative = T(d < T(0));
    const T sign = T(1) - negative - negative;
    const T x = d * sign;  // cos(angle) between a and the nearer of b, -b: angle in [0, pi/2]
    // Halve the angle (so the series converges 2^6 times faster): the midpoint m = (a + b) / (2 c),
    // c = cos(angle / 2); the first half of the arc runs from a to m, the second from m to b.
    const T c = detail::sqrt((T(1) + x) * T(0.5));
    const T half_scale = T(1) / (c + c);
    const T upper = T(t >= T(0.5));
    const T s = t + t - upper;
    const T from = detail::slerp_weight(c - T(1), T(1) - s);
    const T to = detail::slerp_weight(c - T(1), s);
    // lower half: a from + m to;  upper half: m from + b to;  m = (a + b) half_scale.
    const T weight_m = half_scale * (to + upper * (from - to));
    const T weight_a = (T(1) - upper) * from + weight_m;
    const T weight_b = upper * to + weight_m;
    return a * weight_a + b * (sign * weight_b);
}

}  // namespace quat

#endif  // QUAT_FAST_SLERP_HPP_INCLUDED
