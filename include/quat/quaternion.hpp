// Quaternions w + xi + yj + zk (scalar first, Hamilton's ij = k) and their algebra.
#ifndef QUAT_QUATERNION_HPP_INCLUDED
#define QUAT_QUATERNION_HPP_INCLUDED

#include <optional>

#include "config.hpp"
#include "detail/math.hpp"
#include "vec3.hpp"

namespace quat {

/// Quaternion w + xi + yj + zk, scalar first, Hamilton product (ij = k, jk = i, ki = j).
/// A unit quaternion represents the active rotation v -> q v q*; q and -q are the same rotation.
template <class T>
struct quaternion {
    /// Scalar part w, vector part (x, y, z).
    /// @{
    T w, x, y, z;
    /// @}

    /// The rotation by zero angle, 1 + 0i + 0j + 0k.
    [[nodiscard]] static constexpr quaternion identity() noexcept {
        return {T(1), T(0), T(0), T(0)};
    }
};

using quatf = quaternion<float>;   ///< Single-precision quaternion.
using quatd = quaternion<double>;  ///< Double-precision quaternion.

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
/// Product with a scalar, component-wise.
template <class T>
[[nodiscard]] constexpr quaternion<T> operator*(const quaternion<T>& q, T s) noexcept {
    return {q.w * s, q.x * s, q.y * s, q.z * s};
}
/// Product with a scalar, component-wise.
template <class T>
[[nodiscard]] constexpr quaternion<T> operator*(T s, const quaternion<T>& q) noexcept {
    return q * s;
}
/// Component-wise division by s; s == 0 gives IEEE infinities or NaN.
template <class T>
[[nodiscard]] constexpr quaternion<T> operator/(const quaternion<T>& q, T s) noexcept {
    return {q.w / s, q.x / s, q.y / s, q.z / s};
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

/// Four-dimensional dot product; for unit quaternions cos of half the angle between the rotations, up to sign.
template <class T>
[[nodiscard]] constexpr T dot(const quaternion<T>& a, const quaternion<T>& b) noexcept {
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}

/// |q|^2 = q q*; overflows for components beyond sqrt(max).
template <class T>
[[nodiscard]] constexpr T squared_norm(const quaternion<T>& q) noexcept {
    return dot(q, q);
}

/// |q|, without overflow or underflow for huge or tiny components.
template <class T>
[[nodiscard]] constexpr T norm(const quaternion<T>& q) noexcept {
    const T s = squared_norm(q);
    if (s >= std::numeric_limits<T>::min() && s <= std::numeric_limits<T>::max())
        return detail::sqrt(s);
    const T scale = detail::max(detail::max(detail::abs(q.w), detail::abs(q.x)),
                                detail::max(detail::abs(q.y), detail::abs(q.z)));
    if (!(scale > T(0)) || !detail::is_finite(scale)) return detail::sqrt(s);  // 0, Inf or NaN
    return scale * detail::sqrt(squared_norm(q / scale));
}

/// q / |q|, for components anywhere from the smallest subnormal to the largest finite value.
/// Precondition: q is non-zero and finite, else the result holds NaN; try_normalize checks it.
template <class T>
[[nodiscard]] constexpr quaternion<T> normalize(const quaternion<T>& q) noexcept {
    const T s = squared_norm(q);
    if (s >= std::numeric_limits<T>::min() && s <= std::numeric_limits<T>::max())
        return q / detail::sqrt(s);
    const T scale = detail::max(detail::max(detail::abs(q.w), detail::abs(q.x)),
                                detail::max(detail::abs(q.y), detail::abs(q.z)));
    if (!(scale > T(0)) || !detail::is_finite(scale)) return q / detail::sqrt(s);  // NaN out
    const quaternion<T> scaled = q / scale;
    return scaled / detail::sqrt(squared_norm(scaled));
}

/// q / |q|, or std::nullopt when q is zero or has a non-finite component.
template <class T>
[[nodiscard]] constexpr std::optional<quaternion<T>> try_normalize(
    const quaternion<T>& q) noexcept {
    if (!detail::is_finite(q.w) || !detail::is_finite(q.x) || !detail::is_finite(q.y) ||
        !detail::is_finite(q.z))
        return std::nullopt;
    if (q.w == T(0) && q.x == T(0) && q.y == T(0) && q.z == T(0)) return std::nullopt;
    return normalize(q);
}

/// Multiplicative inverse q* / |q|^2 (the thesis's q* / |q| is wrong for non-unit q).
/// Precondition: q non-zero and |q|^2 finite and normal, else Inf/NaN; try_inverse checks it.
template <class T>
[[nodiscard]] constexpr quaternion<T> inverse(const quaternion<T>& q) noexcept {
    return conjugate(q) / squared_norm(q);
}

/// q* / |q|^2, or std::nullopt when q is zero, non-finite, or |q|^2 over- or underflows.
template <class T>
[[nodiscard]] constexpr std::optional<quaternion<T>> try_inverse(const quaternion<T>& q) noexcept {
    const T s = squared_norm(q);
    if (!(s >= std::numeric_limits<T>::min()) || !(s <= std::numeric_limits<T>::max()))
        return std::nullopt;
    return conjugate(q) / s;
}

/// Rotates v by the unit quaternion q: q (0, v) q*, computed as v + w t + u x t with t = 2 u x v
/// (u the vector part): 18 multiplications and 12 additions against 32 and 24 for two Hamilton products.
/// Precondition: |q| = 1 (a non-unit q also scales and skews v).
template <class T>
[[nodiscard]] constexpr vec3<T> rotate(const quaternion<T>& q, const vec3<T>& v) noexcept {
    const vec3<T> u{q.x, q.y, q.z};
    const vec3<T> t = cross(u, v) * T(2);
    return v + t * q.w + cross(u, t);
}

/// Angle in [0, pi] of the rotation that takes unit a to unit b, insensitive to the signs of a and b.
/// Uses 4 atan2(|a - b|, |a + b|), accurate for nearly equal and nearly opposite rotations.
template <class T>
[[nodiscard]] constexpr T angle_between(const quaternion<T>& a, const quaternion<T>& b) noexcept {
    const quaternion<T> near = dot(a, b) < T(0) ? -b : b;
    return T(4) * detail::atan2(norm(a - near), norm(a + near));
}

}  // namespace quat

#endif  // QUAT_QUATERNION_HPP_INCLUDED
