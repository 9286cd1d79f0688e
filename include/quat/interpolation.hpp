// Interpolation between rotations: slerp (constant angular velocity) and nlerp (cheap, normalized).
#pragma once

#include <limits>

#include "detail/math.hpp"
#include "quaternion.hpp"
#include "vec3.hpp"

namespace quat {

namespace detail {

// sin(t * angle) / sin(angle) for angle in [0, pi/2]; a series where both sines are tiny, so
// nearly equal rotations never divide by a small sine.
template <class T>
[[nodiscard]] constexpr T sine_ratio(T t, T angle, T sin_angle) noexcept {
    const T a2 = angle * angle;
    if (a2 * a2 < std::numeric_limits<T>::epsilon()) {
        // sin(tx)/sin(x) = t (1 - (t^2 - 1) x^2 / 6 + ...), next term below epsilon^1.5
        const T t2 = t * t;
        return t * (T(1) - (t2 - T(1)) * a2 / T(6) +
                    (T(3) * t2 * t2 - T(10) * t2 + T(7)) * a2 * a2 / T(360));
    }
    return sin(t * angle) / sin_angle;
}

}  // namespace detail

/// Spherical linear interpolation from unit a (t = 0) to unit b (t = 1) along the shorter arc, at
/// constant angular velocity; t outside [0, 1] extrapolates along the same great circle. Returns
/// a at t = 0 and b, or -b when -b is nearer a, at t = 1, exactly. The angle comes from the chord
/// |a - b|, accurate for nearly equal and nearly opposite inputs. Precondition: unit a and b.
template <class T>
[[nodiscard]] constexpr quaternion<T> slerp(const quaternion<T>& a, const quaternion<T>& b,
                                            T t) noexcept {
    const quaternion<T> near = dot(a, b) < T(0) ? -b : b;
    if (t == T(0)) return a;
    if (t == T(1)) return near;
    if (t < T(0) || t > T(1)) {
        // Beyond the ends the two weights below grow and cancel; turning a by t times the relative
        // rotation a* near, whose w = dot(a, near) >= 0, keeps the error at the level of one product.
        const quaternion<T> relative = conjugate(a) * near;
        const vec3<T> u{relative.x, relative.y, relative.z};
        const T s = norm(u);
        if (!(s > T(0))) return a;
        const T half_turn = t * detail::atan2(s, relative.w);
        const vec3<T> v = u / s * detail::sin(half_turn);
        return a * quaternion<T>{detail::cos(half_turn), v.x, v.y, v.z};
    }
    // |a - near| = 2 sin(angle/2) <= sqrt(2) since dot(a, near) >= 0; asin is well conditioned
    // there (slope <= sqrt(2)), and the chord is accurate for nearly equal inputs, unlike acos(dot).
    const T chord = detail::sqrt(squared_norm(a - near));
    const T angle = T(2) * detail::asin(chord / T(2));  // between a and near, in [0, pi/2]
    const T sin_angle = detail::sin(angle);  // the sine the numerators use: |result| - 1 < 2 eps
    return a * detail::sine_ratio(T(1) - t, angle, sin_angle) +
           near * detail::sine_ratio(t, angle, sin_angle);
}

/// Normalized linear interpolation along the shorter arc: the slerp path at non-uniform speed,
/// cheaper. Precondition: unit a and b; the sign flip keeps the sum non-zero for t in [0, 1].
template <class T>
[[nodiscard]] constexpr quaternion<T> nlerp(const quaternion<T>& a, const quaternion<T>& b,
                                            T t) noexcept {
    const quaternion<T> near = dot(a, b) < T(0) ? -b : b;
    return normalize(a + (near - a) * t);
}

}  // namespace quat
