// The work behind align.hpp's rotation_between and look_rotation: the shortest-arc formulas for
// lengths in range, the float path computed in double, and the camera frame before its fallback.
#ifndef QUAT_DETAIL_SHORTEST_ARC_HPP_INCLUDED
#define QUAT_DETAIL_SHORTEST_ARC_HPP_INCLUDED

#include "../conversions.hpp"
#include "../quaternion.hpp"
#include "../rotation_matrix.hpp"
#include "../vec3.hpp"
#include "math.hpp"
#include "power_of_two.hpp"

namespace quat {

#include "isa_namespace.inc"
namespace detail {

/// The half turn rotation_between picks for exactly opposite directions: about
/// normalize(from x e), e the coordinate axis of from's smallest |component| (the first of x, y,
/// z on ties), so (1, 0, 0) turns about z, (0, 1, 0) about -z and (0, 0, 1) about y.
template <class T>
[[nodiscard]] constexpr quaternion<T> half_turn_perpendicular_to(const vec3<T>& from) noexcept {
    const T ax = abs(from.x), ay = abs(from.y), az = abs(from.z);
    vec3<T> axis{from.y, -from.x, T(0)};                       // from x (0, 0, 1)
    if (ax <= ay && ax <= az) axis = {T(0), from.z, -from.y};  // from x (1, 0, 0)
    else if (ay <= az) axis = {-from.z, T(0), from.x};         // from x (0, 1, 0)
    axis = normalize(axis);
    return {T(0), axis.x, axis.y, axis.z};
}

/// rotation_between_in_range past 150 degrees, given s = |a| |b| - a . b: the axis from the
/// compensated cross product, w = |c|^2 / s.
template <class T>
[[nodiscard]] constexpr quaternion<T> rotation_between_nearly_opposite(const vec3<T>& a,
                                                                       const vec3<T>& b,
                                                                       T s) noexcept {
    const vec3<T> c = accurate_cross(a, b);
    const T cc = dot(c, c);
    if (!(cc >= detail::smallest_normal<T>())) {  // |c|^2 underflows: at most a few ulp from -a
        if (c.x == T(0) && c.y == T(0) && c.z == T(0)) return half_turn_perpendicular_to(a);
        const vec3<T> axis = normalize(c);  // w = |c| / sqrt(|c|^2 + s^2), and s^2 >> |c|^2
        return {norm(c) / s, axis.x, axis.y, axis.z};
    }
    const T w = cc / s;
    const T k = T(1) / sqrt(w * w + cc);
    return {w * k, c.x * k, c.y * k, c.z * k};
}

/// rotation_between for a and b with |a|^2 and |b|^2 in_product_range.
///
/// With m = |a| |b|, d = a . b and c = a x b, the unnormalized quaternion (m + d, c) turns a to b
/// (its half angle has tan = |c| / (m + d) = sin / (1 + cos)), and |(m + d, c)|^2 = (m + d)^2 +
/// |c|^2. Where d >= 0, m + d >= m does not cancel, and an error of the naive c moves the axis by
/// at most its size relative to m times the angle's sine: a few eps. Where d < 0, m + d cancels;
/// it equals |c|^2 / (m - d) (because m^2 = d^2 + |c|^2), and m - d does not cancel. Near opposite,
/// the axis is c itself, small beside the products it comes from: the naive cross product would
/// leave only rounding noise, so it is recomputed with Kahan's compensated determinants.
template <class T>
[[nodiscard]] constexpr quaternion<T> rotation_between_in_range(const vec3<T>& a,
                                                                const vec3<T>& b) noexcept {
    const T mm = dot(a, a) * dot(b, b);
    const T m = sqrt(mm), d = dot(a, b);
    const vec3<T> c = cross(a, b);
    const T cc = dot(c, c);
    // Past 150 degrees (|c| < m / 2 and d < 0) the naive axis error can exceed an eps.
    if (cc < mm * T(0.25) && d < T(0)) return rotation_between_nearly_opposite(a, b, m - d);
    // Both candidates, then a select: random input would mispredict a branch on the sign of d.
    // (m + |d| is m - d where it is used, and never 0, so the unused candidate is finite too.)
    const T near_parallel = m + d, near_opposite = cc / (m + abs(d));
    const T w = d >= T(0) ? near_parallel : near_opposite;
    const T k = T(1) / sqrt(w * w + cc);
    return {w * k, c.x * k, c.y * k, c.z * k};
}

/// rotation_between for float, in double: there a product of two floats is exact, so the cross
/// product keeps its digits also for nearly parallel or opposite inputs, w = |c|^2 / (m - d) avoids
/// the cancellation of m + d, and no float length overflows or underflows (|a|^2 |b|^2 stays
/// within 1e-180 ... 1e155). One formula, no scaling.
[[nodiscard]] constexpr quaternion<float> rotation_between_float(const vec3<float>& from,
                                                                 const vec3<float>& to) noexcept {
    const vec3<double> a{from}, b{to};
    const double m = sqrt(dot(a, a) * dot(b, b)), d = dot(a, b);
    const vec3<double> c = cross(a, b);
    const double cc = dot(c, c);
    if (cc == 0.0 && d < 0.0) return half_turn_perpendicular_to(from);  // exactly opposite
    const double w = d >= 0.0 ? m + d : cc / (m - d);
    // A zero input makes k infinite and every component 0 * inf = NaN; an infinite or NaN one makes
    // m non-finite, and m - m (else 0) then turns every component into NaN too.
    const double k = 1.0 / sqrt(w * w + cc) + (m - m);
    return {static_cast<float>(w * k), static_cast<float>(c.x * k), static_cast<float>(c.y * k),
            static_cast<float>(c.z * k)};
}

/// What look_rotation found: the rotation, or why there is none.
enum class look_status { ok, parallel, invalid };

/// look_rotation's work, with the fallback left to the caller.
template <class T>
struct look_result {
    quaternion<T> rotation;
    look_status status;
};

/// look_rotation for forward and up with |forward|^2 and |up|^2 in_product_range: the rotation
/// matrix with columns right = forward x up / |.|, up' = back x right and back = -forward / |.|
/// (the images of x, y and z), converted by Shepperd's method.
template <class T>
[[nodiscard]] constexpr look_result<T> look_rotation_in_range(const vec3<T>& forward,
                                                              const vec3<T>& up) noexcept {
    const T ff = dot(forward, forward), fu = ff * dot(up, up);
    vec3<T> c = cross(forward, up);
    T cc = dot(c, c);
    // Within 15 degrees of parallel the naive cross product's error grows past an eps.
    if (cc < fu * T(0.0625)) {
        c = accurate_cross(forward, up);
        cc = dot(c, c);
    }
    const T eps = detail::epsilon<T>();
    if (!(cc > eps * eps * fu)) return {quaternion<T>::identity(), look_status::parallel};
    const vec3<T> right = c / sqrt(cc);
    const vec3<T> back = forward / -sqrt(ff);
    const vec3<T> true_up = cross(back, right);
    return {to_quaternion(rotation_matrix<T>::from_columns(right, true_up, back)), look_status::ok};
}

/// look_rotation for any input: scales out of range lengths by powers of two first.
template <class T>
[[nodiscard]] constexpr look_result<T> look_rotation_checked(const vec3<T>& forward,
                                                             const vec3<T>& up) noexcept {
    if (in_product_range(dot(forward, forward)) && in_product_range(dot(up, up)))
        return look_rotation_in_range(forward, up);
    if (!has_direction(forward) || !has_direction(up))
        return {quaternion<T>::identity(), look_status::invalid};
    return look_rotation_in_range(scaled_by_power_of_two(forward), scaled_by_power_of_two(up));
}

}  // namespace detail
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_DETAIL_SHORTEST_ARC_HPP_INCLUDED
