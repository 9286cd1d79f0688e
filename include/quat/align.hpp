// Rotations that align one direction with another: rotation_between (shortest arc) and
// look_rotation (a camera's orientation from where it looks and which way is up).
#ifndef QUAT_ALIGN_HPP_INCLUDED
#define QUAT_ALIGN_HPP_INCLUDED

#include <optional>

#include "conversions.hpp"
#include "detail/math.hpp"
#include "detail/power_of_two.hpp"
#include "quaternion.hpp"
#include "rotation_matrix.hpp"
#include "vec3.hpp"

namespace quat {

#include "detail/isa_namespace.inc"

// The work behind rotation_between and look_rotation: the shortest-arc formulas for lengths in
// range, the float path computed in double, and the camera frame before its fallback.
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

/// The shortest-arc unit quaternion turning the direction of `from` into the direction of `to`:
/// the rotation by the angle between them about from x to. Any non-zero finite lengths (scaled by
/// powers of two, exactly, where the products would overflow or underflow; float is computed in
/// double, where none does); within 4 eps of the exact rotation also where the two are nearly
/// parallel or opposite. Exactly opposite directions give the half turn about normalize(from x e),
/// e the coordinate axis of from's smallest |component| (first of x, y, z on ties): (1, 0, 0) to
/// (-1, 0, 0) turns about z. A zero or non-finite input gives NaN in every component;
/// try_rotation_between checks instead.
template <class T>
[[nodiscard]] constexpr quaternion<T> rotation_between(const vec3<T>& from,
                                                       const vec3<T>& to) noexcept {
    if constexpr (std::is_same_v<T, float>) {
        return detail::rotation_between_float(from, to);
    } else {
        if (detail::in_product_range(dot(from, from)) && detail::in_product_range(dot(to, to)))
            return detail::rotation_between_in_range(from, to);
        if (!detail::has_direction(from) || !detail::has_direction(to)) {
            const T nan = detail::quiet_nan<T>();
            return {nan, nan, nan, nan};
        }
        return detail::rotation_between_in_range(detail::scaled_by_power_of_two(from),
                                                 detail::scaled_by_power_of_two(to));
    }
}

/// rotation_between(from, to), or std::nullopt when either vector is zero or has a NaN or
/// infinite component.
template <class T>
[[nodiscard]] constexpr std::optional<quaternion<T>> try_rotation_between(
    const vec3<T>& from, const vec3<T>& to) noexcept {
    if (!detail::has_direction(from) || !detail::has_direction(to)) return std::nullopt;
    return rotation_between(from, to);
}

/// The orientation of a camera looking along `forward` with `up` above it, in OpenGL's convention
/// (the camera looks down its -z axis, y up, x right): the unit quaternion R with R (0, 0, -1)
/// along forward, R (0, 1, 0) in the half-plane of up beside forward, R (1, 0, 0) along
/// forward x up; glm::quatLookAtRH(normalize(forward), up) is the same rotation. Any non-zero
/// finite lengths. Where up is parallel to forward (|forward x up| <= eps |forward| |up|, angle
/// below eps) the result is rotation_between((0, 0, -1), forward). A zero or non-finite input
/// gives NaN in every component; try_look_rotation checks instead. Other conventions (Unity's
/// +z forward, aerospace x forward and z down) are one fixed product away: docs/conventions.md.
template <class T>
[[nodiscard]] constexpr quaternion<T> look_rotation(const vec3<T>& forward,
                                                    const vec3<T>& up) noexcept {
    const detail::look_result<T> r = detail::look_rotation_checked(forward, up);
    if (r.status == detail::look_status::ok) return r.rotation;
    if (r.status == detail::look_status::parallel)
        return rotation_between(vec3<T>{T(0), T(0), T(-1)}, forward);
    const T nan = detail::quiet_nan<T>();
    return {nan, nan, nan, nan};
}

/// look_rotation(forward, up), or std::nullopt when up is parallel to forward (as look_rotation
/// decides it) or either vector is zero or has a NaN or infinite component.
template <class T>
[[nodiscard]] constexpr std::optional<quaternion<T>> try_look_rotation(const vec3<T>& forward,
                                                                       const vec3<T>& up) noexcept {
    if (!detail::has_direction(forward) || !detail::has_direction(up)) return std::nullopt;
    const detail::look_result<T> r = detail::look_rotation_checked(forward, up);
    if (r.status != detail::look_status::ok) return std::nullopt;
    return r.rotation;
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_ALIGN_HPP_INCLUDED
