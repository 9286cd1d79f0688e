// Quaternions w + xi + yj + zk (scalar first, Hamilton's ij = k) and their algebra.
#ifndef QUAT_QUATERNION_HPP_INCLUDED
#define QUAT_QUATERNION_HPP_INCLUDED

#include <limits>
#include <optional>
#include <type_traits>

#include "config.hpp"
#include "detail/math.hpp"
#include "rotation_matrix.hpp"
#include "vec3.hpp"

namespace quat {

#include "detail/isa_namespace.inc"
namespace detail {

/// The debug check of a unit quaternion or axis v: |v|^2 within 1/4096 of 1, which a forgotten
/// normalization misses and accumulated rounding does not. NaN and infinities pass: they propagate
/// to the result instead (NaN in, NaN out). Only float, double and long double are checked, so a
/// user scalar (a counting or automatic-differentiation type) needs nothing more in debug builds.
template <class V>
[[nodiscard]] constexpr bool is_near_unit(const V& v) noexcept {
    using T = decltype(squared_norm(v));
    if constexpr (std::is_floating_point_v<T>) {
        // v * 0 is zero exactly when every component is finite; an |v|^2 that overflows from finite
        // components is then caught by the comparison, not let through as "not finite".
        if (!(squared_norm(v * T(0)) == T(0))) return true;
        return abs(squared_norm(v) - T(1)) <= T(1) / T(4096);
    } else {
        return true;
    }
}

}  // namespace detail
}  // inline namespace isa_...

/// Quaternion w + xi + yj + zk, scalar first, Hamilton product (ij = k, jk = i, ki = j).
/// A unit quaternion represents the active rotation v -> q v q*; q and -q are the same rotation.
template <class T>
struct quaternion {
    /// Scalar part w, vector part (x, y, z).
    /// @{
    T w, x, y, z;
    /// @}

    /// Components left uninitialized, as in a plain struct; quaternion<T>{} is zero.
    quaternion() = default;
    /// The quaternion w + xi + yj + zk.
    [[gnu::always_inline]] constexpr quaternion(T w_value, T x_value, T y_value, T z_value) noexcept
        : w(w_value), x(x_value), y(y_value), z(z_value) {}
    /// Conversion from another precision, component by component: quatd{qf}.
    template <class U>
    [[gnu::always_inline]] constexpr explicit quaternion(const quaternion<U>& q) noexcept
        : w(static_cast<T>(q.w)),
          x(static_cast<T>(q.x)),
          y(static_cast<T>(q.y)),
          z(static_cast<T>(q.z)) {}

    /// The rotation by zero angle, 1 + 0i + 0j + 0k.
    [[nodiscard]] [[gnu::always_inline]] static constexpr quaternion identity() noexcept {
        return {T(1), T(0), T(0), T(0)};
    }
};

using quatf = quaternion<float>;   ///< Single-precision quaternion.
using quatd = quaternion<double>;  ///< Double-precision quaternion.

#include "detail/isa_namespace.inc"  // NOLINT(readability-duplicate-include): opened again
/// Negation; -q is the same rotation as q.
template <class T>
[[nodiscard]] constexpr quaternion<T> operator-(const quaternion<T>& q) noexcept {
    return {-q.w, -q.x, -q.y, -q.z};
}
/// Component-wise sum.
template <class T>
[[nodiscard]] constexpr quaternion<T> operator+(const quaternion<T>& a,
                                                const quaternion<T>& b) noexcept {
    return {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
}
/// Component-wise difference.
template <class T>
[[nodiscard]] constexpr quaternion<T> operator-(const quaternion<T>& a,
                                                const quaternion<T>& b) noexcept {
    return {a.w - b.w, a.x - b.x, a.y - b.y, a.z - b.z};
}

/// Hamilton product: as rotations, a * b applies b first, then a.
template <class T>
[[nodiscard]] constexpr quaternion<T> operator*(const quaternion<T>& a,
                                                const quaternion<T>& b) noexcept {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
/// Product with a scalar, component-wise; s converts to T (q * 2 for a quatf).
template <class T>
[[nodiscard]] constexpr quaternion<T> operator*(const quaternion<T>& q,
                                                detail::type_identity_t<T> s) noexcept {
    return {q.w * s, q.x * s, q.y * s, q.z * s};
}
/// Product with a scalar, component-wise; s converts to T.
template <class T>
[[nodiscard]] constexpr quaternion<T> operator*(detail::type_identity_t<T> s,
                                                const quaternion<T>& q) noexcept {
    return q * s;
}
/// Component-wise division by s (converted to T); s == 0 gives IEEE infinities or NaN.
template <class T>
[[nodiscard]] constexpr quaternion<T> operator/(const quaternion<T>& q,
                                                detail::type_identity_t<T> s) noexcept {
    return {q.w / s, q.x / s, q.y / s, q.z / s};
}
/// q = q + r.
template <class T>
constexpr quaternion<T>& operator+=(quaternion<T>& q, const quaternion<T>& r) noexcept {
    return q = q + r;
}
/// q = q - r.
template <class T>
constexpr quaternion<T>& operator-=(quaternion<T>& q, const quaternion<T>& r) noexcept {
    return q = q - r;
}
/// q = q * r: as rotations, r is applied first, then the old q.
template <class T>
constexpr quaternion<T>& operator*=(quaternion<T>& q, const quaternion<T>& r) noexcept {
    return q = q * r;
}
/// q = q * s, component-wise.
template <class T>
constexpr quaternion<T>& operator*=(quaternion<T>& q, detail::type_identity_t<T> s) noexcept {
    return q = q * s;
}
/// q = q / s, component-wise.
template <class T>
constexpr quaternion<T>& operator/=(quaternion<T>& q, detail::type_identity_t<T> s) noexcept {
    return q = q / s;
}

/// Exact component-wise equality; q == -q is false although both are one rotation
/// (compare rotations with angle_between).
template <class T>
[[nodiscard]] constexpr bool operator==(const quaternion<T>& a, const quaternion<T>& b) noexcept {
    return a.w == b.w && a.x == b.x && a.y == b.y && a.z == b.z;
}
/// Negation of ==.
template <class T>
[[nodiscard]] constexpr bool operator!=(const quaternion<T>& a, const quaternion<T>& b) noexcept {
    return !(a == b);
}

/// Conjugate w - xi - yj - zk: the inverse rotation for a unit quaternion.
template <class T>
[[nodiscard]] constexpr quaternion<T> conjugate(const quaternion<T>& q) noexcept {
    return {q.w, -q.x, -q.y, -q.z};
}

/// Four-dimensional dot product; for unit quaternions cos of half the angle between the rotations,
/// up to sign.
template <class T>
[[nodiscard]] constexpr T dot(const quaternion<T>& a, const quaternion<T>& b) noexcept {
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}

/// |q|^2 = q q*; overflows for components beyond sqrt(max).
template <class T>
[[nodiscard]] constexpr T squared_norm(const quaternion<T>& q) noexcept {
    return dot(q, q);
}

namespace detail {

/// The largest |component| of q.
template <class T>
[[nodiscard]] constexpr T largest_magnitude(const quaternion<T>& q) noexcept {
    return max(max(abs(q.w), abs(q.x)), max(abs(q.y), abs(q.z)));
}

/// True when every component of q is finite.
template <class T>
[[nodiscard]] constexpr bool is_finite(const quaternion<T>& q) noexcept {
    return is_finite(q.w) && is_finite(q.x) && is_finite(q.y) && is_finite(q.z);
}

/// NaN in every component.
template <class T>
[[nodiscard]] constexpr quaternion<T> nan_quaternion() noexcept {
    const T nan = detail::quiet_nan<T>();
    return {nan, nan, nan, nan};
}

/// q divided by its largest |component| where |q|^2 would over- or underflow (every ratio of
/// components, hence the rotation, kept), q itself otherwise; NaN in every component when q has a
/// NaN or infinite component, and q when it is zero.
template <class T>
[[nodiscard]] constexpr quaternion<T> rescaled(const quaternion<T>& q) noexcept {
    const T s = squared_norm(q);
    if (in_normal_range(s)) return q;
    if (s != s) return nan_quaternion<T>();  // a NaN component, which largest_magnitude may skip
    const T scale = largest_magnitude(q);
    if (!is_finite(scale)) return nan_quaternion<T>();
    return scale > T(0) ? q / scale : q;
}

}  // namespace detail

/// |q|, without overflow or underflow for huge or tiny components (Inf when |q| exceeds max()).
template <class T>
[[nodiscard]] constexpr T norm(const quaternion<T>& q) noexcept {
    const T s = squared_norm(q);
    if (detail::in_normal_range(s)) return detail::sqrt(s);
    const T scale = detail::largest_magnitude(q);
    if (!(scale > T(0)) || !detail::is_finite(scale)) return detail::sqrt(s);  // 0, Inf or NaN
    return scale * detail::sqrt(squared_norm(q / scale));
}

/// q / |q|, for components anywhere from the smallest subnormal to the largest finite value.
/// Precondition: q is non-zero and finite, else NaN in every component; try_normalize checks it.
template <class T>
[[nodiscard]] constexpr quaternion<T> normalize(const quaternion<T>& q) noexcept {
    const T s = squared_norm(q);
    if (detail::in_normal_range(s)) return q / detail::sqrt(s);
    const quaternion<T> scaled = detail::rescaled(q);
    const T scaled_s = squared_norm(scaled);
    if (!(scaled_s > T(0))) return detail::nan_quaternion<T>();  // zero or NaN
    return scaled / detail::sqrt(scaled_s);
}

/// q / |q|, or std::nullopt when q is zero or has a non-finite component.
template <class T>
[[nodiscard]] constexpr std::optional<quaternion<T>> try_normalize(
    const quaternion<T>& q) noexcept {
    if (!detail::is_finite(q)) return std::nullopt;
    if (q.w == T(0) && q.x == T(0) && q.y == T(0) && q.z == T(0)) return std::nullopt;
    return normalize(q);
}

/// Multiplicative inverse q* / |q|^2 (the thesis's q* / |q| is wrong for non-unit q), accurate
/// wherever the inverse is representable: |q| = 1e300 gives 1e-300, a subnormal |q| a huge result
/// (Inf past max()). The zero quaternion and NaN or infinite components give NaN in every
/// component; try_inverse checks.
template <class T>
[[nodiscard]] constexpr quaternion<T> inverse(const quaternion<T>& q) noexcept {
    const T s = squared_norm(q);
    if (detail::in_normal_range(s)) return conjugate(q) / s;
    const T scale = detail::largest_magnitude(q);
    if (!(scale > T(0)) || !detail::is_finite(scale)) return detail::nan_quaternion<T>();
    const quaternion<T> p = q / scale;  // q^-1 = p* / (|p|^2 scale)
    return conjugate(p) / squared_norm(p) / scale;
}

/// inverse(q), or std::nullopt when q is zero or non-finite or the inverse over- or underflows.
template <class T>
[[nodiscard]] constexpr std::optional<quaternion<T>> try_inverse(const quaternion<T>& q) noexcept {
    if (!try_normalize(q)) return std::nullopt;  // zero or not finite
    const quaternion<T> result = inverse(q);
    const T n = norm(result);
    if (!(n > T(0)) || !detail::is_finite(n)) return std::nullopt;  // over- or underflowed
    return result;
}

namespace detail {

/// The matrix of q with the vector part's factor 2 already applied by the caller: entries
/// one - (y ys + z zs), x ys - w zs, ... where (xs, ys, zs) = s (x, y, z). s = 2 gives the rotation
/// matrix of a unit q (to_matrix); rotate passes s = 2 / |q|^2 to first order. one = 1/2 with s
/// halved gives that matrix halved exactly (transform of a dual quaternion). Matrix is the 3x3
/// type to build, rotation_matrix or, for a Jacobian block (so3::adjoint), matrix3: the same
/// entries, built in place.
template <template <class> class Matrix = rotation_matrix, class T>
[[nodiscard]] constexpr Matrix<T> scaled_matrix(const quaternion<T>& q, T xs, T ys, T zs,
                                                T one = T(1)) noexcept {
    const T xx = q.x * xs, yy = q.y * ys, zz = q.z * zs;
    const T xy = q.x * ys, xz = q.x * zs, yz = q.y * zs;
    const T wx = q.w * xs, wy = q.w * ys, wz = q.w * zs;
    return {{{one - (yy + zz), xy - wz, xz + wy},
             {xy + wz, one - (xx + zz), yz - wx},
             {xz - wy, yz + wx, one - (xx + yy)}}};
}

/// rotate(q, v) without its debug check of |q|: for loops that check once per call, or not at all.
template <class T>
[[nodiscard]] constexpr vec3<T> rotate_unchecked(const quaternion<T>& q,
                                                 const vec3<T>& v) noexcept {
    const T n2 = squared_norm(q);
    const T s = T(4) - (n2 + n2);  // exact for n2 >= 1, one rounding below
    return rotate(scaled_matrix(q, q.x * s, q.y * s, q.z * s), v);
}

}  // namespace detail

/// Rotates v by the unit quaternion q: q (0, v) q* / |q|^2, as M v with M built from q and s = 2 (2
/// - |q|^2) in place of 2 (equal to 2 / |q|^2 to first order), so a q from normalize, a few eps off
/// unit, keeps |v| within 4 eps (v + w t + u x t, t = 2 u x v, reaches 5.4 in float and 4.7 in
/// double; quat_accuracy). 25 multiplications, 23 additions (16 and 17 on q alone, beside the work
/// on v). Precondition: |q|^2 = 1 + d with d small; the result is off by at most 2 d^2 |v|.
template <class T>
[[nodiscard]] constexpr vec3<T> rotate(const quaternion<T>& q, const vec3<T>& v) noexcept {
    QUAT_ASSERT(detail::is_near_unit(q), "quat::rotate: q is not a unit quaternion");
    return detail::rotate_unchecked(q, v);
}

/// q * v, as GLM, Eigen and Unity write it: the same as rotate(q, v), debug check included.
template <class T>
[[nodiscard]] constexpr vec3<T> operator*(const quaternion<T>& q, const vec3<T>& v) noexcept {
    return rotate(q, v);
}

/// Angle in [0, pi] of the rotation that takes unit a to unit b, insensitive to the signs of a and
/// b. Uses 4 atan2(|a - b|, |a + b|), accurate for nearly equal and nearly opposite rotations. NaN
/// when a or b has a NaN or infinite component.
template <class T>
[[nodiscard]] constexpr T angle_between(const quaternion<T>& a, const quaternion<T>& b) noexcept {
    const quaternion<T> near = dot(a, b) < T(0) ? -b : b;
    const T chord = norm(a - near), sum = norm(a + near);
    // Two infinite norms would give atan2(inf, inf) = pi/4, a plausible-looking angle of pi.
    if (!detail::is_finite(chord + sum)) return detail::quiet_nan<T>();
    return T(4) * detail::atan2(chord, sum);
}

/// True when unit a and b are the same rotation within angle_tolerance radians: compares the angle
/// between them, so q and -q are equal. False when either holds NaN or an infinity.
template <class T>
[[nodiscard]] constexpr bool approx_equal(const quaternion<T>& a, const quaternion<T>& b,
                                          detail::type_identity_t<T> angle_tolerance) noexcept {
    return angle_between(a, b) <= angle_tolerance;
}

/// True when ||q| - 1| <= tolerance; false for NaN or infinite components, whatever the tolerance.
template <class T>
[[nodiscard]] constexpr bool is_unit(const quaternion<T>& q,
                                     detail::type_identity_t<T> tolerance) noexcept {
    const T n = norm(q);
    return detail::is_finite(n) && detail::abs(n - T(1)) <= tolerance;
}

namespace detail {

/// The scalar type of rotation_x<T>(angle) and its siblings: T when the caller names it (void when
/// not), else that of the angle: double for an integer angle, the angle's type otherwise.
template <class T, class A>
using axis_rotation_scalar_t = std::conditional_t<std::is_void_v<T>, real_t<A>, T>;

// The rotation by angle about coordinate axis Axis (0 = x, 1 = y, 2 = z): (cos(a/2), sin(a/2)
// e_Axis). The angle is converted to T first, explicitly: rotation_x<float>(numbers::pi) is
// rotation_x(numbers::pi_v<float>), without a narrowing warning at the call.
template <int Axis, class T, class A>
[[nodiscard]] constexpr quaternion<T> axis_rotation(A angle) noexcept {
    const T half = static_cast<T>(angle) * T(0.5), s = detail::sin(half);
    return {detail::cos(half), Axis == 0 ? s : T(0), Axis == 1 ? s : T(0), Axis == 2 ? s : T(0)};
}

}  // namespace detail

/// The rotation by angle radians about the x axis: the thesis's R_x, counter-clockwise seen from
/// +x. The precision follows the angle (a float angle gives a quatf, an integer a quatd) unless
/// named: rotation_x<float>(numbers::pi) is a quatf, the angle converted to float first.
template <class T = void, class A>
[[nodiscard]] constexpr quaternion<detail::axis_rotation_scalar_t<T, A>> rotation_x(
    A angle) noexcept {
    return detail::axis_rotation<0, detail::axis_rotation_scalar_t<T, A>>(angle);
}

/// The rotation by angle radians about the y axis (the thesis's R_y), counter-clockwise seen from
/// +y. Precision as rotation_x: rotation_y(0.5f) and rotation_y<float>(numbers::pi) are quatf.
template <class T = void, class A>
[[nodiscard]] constexpr quaternion<detail::axis_rotation_scalar_t<T, A>> rotation_y(
    A angle) noexcept {
    return detail::axis_rotation<1, detail::axis_rotation_scalar_t<T, A>>(angle);
}

/// The rotation by angle radians about the z axis (the thesis's R_z), counter-clockwise seen from
/// +z. Precision as rotation_x.
template <class T = void, class A>
[[nodiscard]] constexpr quaternion<detail::axis_rotation_scalar_t<T, A>> rotation_z(
    A angle) noexcept {
    return detail::axis_rotation<2, detail::axis_rotation_scalar_t<T, A>>(angle);
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_QUATERNION_HPP_INCLUDED
