// Conversions among quaternions, rotation matrices, axis-angle pairs, rotation vectors and modified
// Rodrigues parameters.
// Euler-angle conversions live in euler.hpp.
#ifndef QUAT_CONVERSIONS_HPP_INCLUDED
#define QUAT_CONVERSIONS_HPP_INCLUDED

#include <limits>
#include <optional>
#include <type_traits>

#include "axis_angle.hpp"
#include "config.hpp"
#include "detail/math.hpp"
#include "quaternion.hpp"
#include "rotation_matrix.hpp"
#include "vec3.hpp"

namespace quat {

#include "detail/isa_namespace.inc"
/// Rotation matrix of the unit quaternion q, so rotate(to_matrix(q), v) == rotate(q, v).
/// Precondition: |q| = 1 (a non-unit q gives a matrix that is not a rotation).
template <class T>
[[nodiscard]] constexpr rotation_matrix<T> to_matrix(const quaternion<T>& q) noexcept {
    QUAT_ASSERT(detail::is_near_unit(q), "quat::to_matrix: q is not a unit quaternion");
    return detail::scaled_matrix(q, q.x + q.x, q.y + q.y, q.z + q.z);
}

/// Unit quaternion with w >= 0 of the rotation matrix m, exact for every rotation including 180°
/// turns: Shepperd's method (J. Guidance and Control 1(3), 1978) builds q from the largest of
/// 1 + trace and the diagonal, so it never divides by a small number.
/// Precondition: m is a rotation; for other matrices use try_to_quaternion or nearest_rotation.
template <class T>
[[nodiscard]] constexpr quaternion<T> to_quaternion(const rotation_matrix<T>& m) noexcept {
    // Each branch forms 4 |c| q, where c is the largest component (4 w^2 = 1 + trace,
    // 4 x^2 = 1 + m00 - m11 - m22, ...), from sums of entries alone; normalize then removes the
    // factor, so the square root and the division that recover |c| are never needed.
    const T trace = m(0, 0) + m(1, 1) + m(2, 2);
    quaternion<T> q{};
    if (trace >= m(0, 0) && trace >= m(1, 1) && trace >= m(2, 2)) {
        q = {T(1) + trace, m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1)};
    } else if (m(0, 0) >= m(1, 1) && m(0, 0) >= m(2, 2)) {
        q = {m(2, 1) - m(1, 2), T(1) + m(0, 0) - m(1, 1) - m(2, 2), m(0, 1) + m(1, 0),
             m(0, 2) + m(2, 0)};
    } else if (m(1, 1) >= m(2, 2)) {
        q = {m(0, 2) - m(2, 0), m(0, 1) + m(1, 0), T(1) - m(0, 0) + m(1, 1) - m(2, 2),
             m(1, 2) + m(2, 1)};
    } else {
        q = {m(1, 0) - m(0, 1), m(0, 2) + m(2, 0), m(1, 2) + m(2, 1),
             T(1) - m(0, 0) - m(1, 1) + m(2, 2)};
    }
    // For a rotation |4 |c| q|^2 = 16 c^2 is in [4, 16] (c^2 >= 1/4 as the largest of four
    // squares summing to 1), so one division and four multiplications scale it, rather than
    // normalize's four divisions, which bounded a loop of conversions (to_quaternion_each). Off
    // the precondition, where |q|^2 leaves the normal range, normalize rescales.
    const quaternion<T> w_nonnegative = q.w < T(0) ? -q : q;
    const T s = squared_norm(w_nonnegative);
    if (!detail::in_normal_range(s)) return normalize(w_nonnegative);
    return w_nonnegative * (T(1) / detail::sqrt(s));
}

/// Default tolerance of try_to_quaternion: sqrt(epsilon), about 3e-4 for float and 1.5e-8 for
/// double.
template <class T>
[[nodiscard]] constexpr T default_orthogonality_tolerance() noexcept {
    return detail::sqrt(detail::epsilon<T>());
}

/// to_quaternion(m), or std::nullopt when m has a non-finite element, det(m) <= 0 (a reflection),
/// or orthogonality_error(m) > tolerance. Use nearest_rotation to repair a matrix first.
template <class T>
[[nodiscard]] constexpr std::optional<quaternion<T>> try_to_quaternion(
    const rotation_matrix<T>& m,
    detail::type_identity_t<T> tolerance = default_orthogonality_tolerance<T>()) noexcept {
    const T error = orthogonality_error(m);
    // An infinite element makes the error infinite or NaN, rejected even for an infinite tolerance.
    if (!detail::is_finite(error) || !(error <= tolerance) || !(determinant(m) > T(0)))
        return std::nullopt;
    return to_quaternion(m);
}

/// Quaternion (cos(angle/2), sin(angle/2) axis) — the half angle, which the thesis's (2.26) omits.
/// Precondition: unit axis; try_to_quaternion(axis_angle) normalizes and checks untrusted input.
template <class T>
[[nodiscard]] constexpr quaternion<T> to_quaternion(const axis_angle<T>& rotation) noexcept {
    QUAT_ASSERT(detail::is_near_unit(rotation.axis),
                "quat::to_quaternion: the axis of an axis_angle is not a unit vector");
    const T half = rotation.angle * T(0.5), s = detail::sin(half);
    return {detail::cos(half), rotation.axis.x * s, rotation.axis.y * s, rotation.axis.z * s};
}

/// to_quaternion of the rotation about normalize(axis), or std::nullopt when the axis is zero or
/// any input is non-finite.
template <class T>
[[nodiscard]] constexpr std::optional<quaternion<T>> try_to_quaternion(
    const axis_angle<T>& rotation) noexcept {
    const std::optional<vec3<T>> axis = try_normalize(rotation.axis);
    if (!axis || !detail::is_finite(rotation.angle)) return std::nullopt;
    return to_quaternion(axis_angle<T>{*axis, rotation.angle});
}

/// Axis and angle in [0, pi] of the rotation q (q and -q give the same result). The identity gives
/// axis (1, 0, 0) and angle 0. Any non-zero scale of q gives the same result; the zero quaternion
/// and NaN or infinite components give NaN.
template <class T>
[[nodiscard]] constexpr axis_angle<T> to_axis_angle(const quaternion<T>& q) noexcept {
    const quaternion<T> r = detail::rescaled(q);
    const quaternion<T> p = r.w < T(0) ? -r : r;
    const vec3<T> u{p.x, p.y, p.z};
    const T s = norm(u);
    if (s == T(0) && p.w > T(0)) return {{T(1), T(0), T(0)}, T(0)};
    // normalize, not u / s: for subnormal x, y, z, s keeps only a few bits and u / s is not unit.
    return {normalize(u), T(2) * detail::atan2(s, p.w)};
}

/// The angle in [0, pi] of the rotation q: to_axis_angle(q).angle, q and -q alike, 0 for the
/// identity, any non-zero scale of q giving the same; NaN for NaN or infinite components, 0 for the
/// zero quaternion (whose axis is NaN). Eigen's AngleAxis(q).angle() agrees; glm::angle, 2 acos(w)
/// in [0, 2 pi], returns 2 pi minus it for -cos(1/2) <= w < 0 (and this angle for w below that,
/// where it switches to 2 asin(|v|)).
template <class T>
[[nodiscard]] constexpr T angle(const quaternion<T>& q) noexcept {
    return to_axis_angle(q).angle;
}

/// The unit axis of the rotation q: to_axis_angle(q).axis, the axis about which q turns by
/// angle(q) in [0, pi] counter-clockwise, so q and -q agree; (1, 0, 0) for the identity (as Eigen's
/// AngleAxis); any non-zero scale of q gives the same; NaN for the zero quaternion or NaN or
/// infinite components. glm::axis keeps q's sign (the opposite axis for w < 0) and gives
/// (0, 0, 1) for the identity.
template <class T>
[[nodiscard]] constexpr vec3<T> axis(const quaternion<T>& q) noexcept {
    return to_axis_angle(q).axis;
}

/// Axis and angle in [0, pi] of the rotation matrix m, exact at 180° (through the quaternion).
template <class T>
[[nodiscard]] constexpr axis_angle<T> to_axis_angle(const rotation_matrix<T>& m) noexcept {
    return to_axis_angle(to_quaternion(m));
}

/// Rodrigues' formula R = cos(angle) I + sin(angle) [axis]x + (1 - cos(angle)) axis axis^T.
/// Precondition: unit axis (checked in debug builds; a zero axis would give cos(angle) I).
template <class T>
[[nodiscard]] constexpr rotation_matrix<T> to_matrix(const axis_angle<T>& rotation) noexcept {
    QUAT_ASSERT(detail::is_near_unit(rotation.axis),
                "quat::to_matrix: the axis of an axis_angle is not a unit vector");
    const T c = detail::cos(rotation.angle), s = detail::sin(rotation.angle), k = T(1) - c;
    const vec3<T>& a = rotation.axis;
    const T xk = a.x * k, yk = a.y * k, zk = a.z * k;
    const T xs = a.x * s, ys = a.y * s, zs = a.z * s;
    const T xy = a.x * yk, xz = a.x * zk, yz = a.y * zk;
    return {{{c + a.x * xk, xy - zs, xz + ys},
             {xy + zs, c + a.y * yk, yz - xs},
             {xz - ys, yz + xs, c + a.z * zk}}};
}

/// Exponential map: the unit quaternion of the rotation by |v| radians about v / |v|.
/// Accurate from the zero vector (identity, via a series, no 0/0) up to any angle, for every finite
/// v: where |v| exceeds max() the half angle |v| / 2 does not, and gives the unit quaternion (an
/// angle that large is known only to within its rounding, many turns, as already from about 1e16
/// rad in double). NaN or infinite components give NaN.
template <class T>
[[nodiscard]] constexpr quaternion<T> from_rotation_vector(
    const vec3<T>& rotation_vector) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        // Only for floating point: a user scalar (an autodiff Jet) would pay for the test with
        // derivatives on every call, for magnitudes no such program reaches.
        if (!(squared_norm(rotation_vector) <= detail::largest<T>())) {
            // |v|^2 overflowed (or is NaN): the half angle from v / 2, whose norm is at most
            // sqrt(3) max() / 2, and the axis from normalize, as sin(h) / h falls below the
            // normal range (losing digits) as h nears max().
            const T half_angle = norm(rotation_vector * T(0.5)), s = detail::sin(half_angle);
            const vec3<T> axis = normalize(rotation_vector);
            return {detail::cos(half_angle), axis.x * s, axis.y * s, axis.z * s};
        }
    }
    // The half angle's square from the squared norm, not from norm, so that a dual-number scalar
    // gets finite derivatives at the zero vector (norm's square root is only read past the series).
    const detail::cos_and_sinc<T> half =
        detail::cos_sinc(squared_norm(rotation_vector) * T(0.25), norm(rotation_vector) * T(0.5));
    const T scale = half.sinc * T(0.5);  // sin(angle / 2) / angle
    return {half.cos, rotation_vector.x * scale, rotation_vector.y * scale,
            rotation_vector.z * scale};
}

/// Logarithm map: the rotation vector angle * axis of q, with angle in [0, pi] (q and -q agree).
/// Accurate from the identity (series, no 0/0) to 180°. Any non-zero scale of q gives the same
/// result.
template <class T>
[[nodiscard]] constexpr vec3<T> to_rotation_vector(const quaternion<T>& q) noexcept {
    const quaternion<T> r = detail::rescaled(q);
    const quaternion<T> p = r.w < T(0) ? -r : r;
    const vec3<T> u{p.x, p.y, p.z};
    // Small angles: r^2 = tan^2(angle / 2) from |u|^2, without norm's square root (whose
    // derivative at the identity is 0/0 for a dual-number scalar); 2 atan(r) / |u| =
    // (2 / w) atan(r) / r.
    const T s2 = squared_norm(u);
    if (detail::atan_series_suffices(s2, p.w))
        return (u / p.w) * (T(2) * detail::atan_ratio_series(s2 / (p.w * p.w)));
    // Dividing u first keeps 1/s from overflowing for a subnormal-scaled q.
    const T s = norm(u);
    return (u / s) * (T(2) * detail::atan2(s, p.w));
}

/// Modified Rodrigues parameters of the rotation q, as scipy's Rotation.as_mrp: axis * tan(angle/4)
/// with angle in [0, pi], so |p| <= 1; p = v / (|q| + w) after taking q's sign with w >= 0, which
/// never cancels. A half turn (w = 0) keeps the sign of q's vector part (|p| = 1, and p and -p are
/// the same rotation). Any non-zero scale of q gives the same result; the zero quaternion and NaN
/// or infinite components give NaN.
template <class T>
[[nodiscard]] constexpr vec3<T> to_mrp(const quaternion<T>& q) noexcept {
    const quaternion<T> r = detail::rescaled(q);
    const quaternion<T> p = r.w < T(0) ? -r : r;
    return vec3<T>{p.x, p.y, p.z} / (norm(p) + p.w);
}

/// The unit quaternion ((1 - |p|^2), 2 p) / (1 + |p|^2) of the modified Rodrigues parameters p, as
/// scipy's Rotation.from_mrp: the rotation by 4 atan(|p|) about p / |p|. Any finite p is valid:
/// |p| > 1 is the same rotation the long way round (p and -p / |p|^2 agree up to the quaternion's
/// sign), and a huge p gives a quaternion near -identity. NaN or infinite components give NaN.
template <class T>
[[nodiscard]] constexpr quaternion<T> from_mrp(const vec3<T>& p) noexcept {
    const T n2 = squared_norm(p);
    if (n2 <= detail::largest<T>()) {
        const T scale = T(2) / (T(1) + n2);
        return {(T(1) - n2) / (T(1) + n2), p.x * scale, p.y * scale, p.z * scale};
    }
    // A NaN or infinite component: NaN in every component (x - x is NaN exactly then).
    const T nan = (p.x - p.x) + (p.y - p.y) + (p.z - p.z);
    if (!(nan == T(0))) return {nan, nan, nan, nan};
    // |p|^2 overflowed: the same formula with numerator and denominator divided by |p|^2, in terms
    // of p / |p| and 1 / |p| (0 when |p| overflows too).
    const T length = norm(p), inverse = T(1) / length, inverse2 = inverse * inverse;
    const vec3<T> v = p / length * (T(2) * inverse / (inverse2 + T(1)));
    return {(inverse2 - T(1)) / (inverse2 + T(1)), v.x, v.y, v.z};
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_CONVERSIONS_HPP_INCLUDED
