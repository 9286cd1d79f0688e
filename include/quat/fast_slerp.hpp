// Approximate slerp without trigonometry: a short polynomial in cos(angle), after Eberly 2011,
// "A fast and accurate algorithm for computing SLERP" (J. Graphics, GPU, and Game Tools 15(3)).
#pragma once

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
    const T s2 = s * s;
    constexpr T mu = T(0.1502107483);
    // Horner from the innermost term: acc_i = 1 + b_i / b_{i-1} y acc_{i+1}.
    T acc = T(1) + (s2 - T(36)) * (T(1) + mu) / T(78) * y;
    acc = T(1) + (s2 - T(25)) / T(55) * y * acc;
    acc = T(1) + (s2 - T(16)) / T(36) * y * acc;
    acc = T(1) + (s2 - T(9)) / T(21) * y * acc;
    acc = T(1) + (s2 - T(4)) / T(10) * y * acc;
    acc = T(1) + (s2 - T(1)) / T(3) * y * acc;
    return s * acc;
}

}  // namespace detail

/// Slerp from unit a (t = 0) to unit b (t = 1) along the shorter arc, approximated without
/// trigonometry: rotation-angle error below 1e-6 rad in float (tests/test_fast_slerp.cpp), exact
/// at t = 0 and t = 1. Precondition: unit a, b and t in [0, 1] (outside it the error grows quickly).
template <class T>
[[nodiscard]] constexpr quaternion<T> slerp_fast(const quaternion<T>& a, const quaternion<T>& b, T t) noexcept {
    const T d = dot(a, b);
    const T sign = d < T(0) ? T(-1) : T(1);
    const T x = d * sign;  // cos(angle) between a and the nearer of b, -b: angle in [0, pi/2]
    // Halve the angle (so the series converges 2^6 times faster): the midpoint m = (a + b) / (2 c),
    // c = cos(angle / 2); the first half of the arc runs from a to m, the second from m to b.
    const T c = detail::sqrt((T(1) + x) / T(2));
    const T half_scale = T(1) / (c + c);
    const bool upper = t >= T(0.5);
    const T s = upper ? t + t - T(1) : t + t;
    const T from = detail::slerp_weight(c - T(1), T(1) - s);
    const T to = detail::slerp_weight(c - T(1), s);
    // lower half: a from + m to;  upper half: m from + b to;  with m = (a + b) half_scale.
    const T weight_a = upper ? half_scale * from : from + half_scale * to;
    const T weight_b = upper ? half_scale * from + to : half_scale * to;
    return a * weight_a + b * (sign * weight_b);
}

}  // namespace quat
