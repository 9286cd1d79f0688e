// 3D vectors: the points and axes that rotations act on.
#ifndef QUAT_VEC3_HPP_INCLUDED
#define QUAT_VEC3_HPP_INCLUDED

#include <cstddef>
#include <limits>
#include <optional>

#include "config.hpp"
#include "detail/math.hpp"

namespace quat {

/// A 3D vector or point with public components.
template <class T>
struct vec3 {
    /// Cartesian components.
    /// @{
    T x, y, z;
    /// @}

    /// Components left uninitialized, as in a plain struct; vec3<T>{} is the zero vector.
    vec3() = default;
    /// The vector (x, y, z).
    [[gnu::always_inline]] constexpr vec3(T x_value, T y_value, T z_value) noexcept
        : x(x_value), y(y_value), z(z_value) {}
    /// Conversion from another precision, component by component: vec3<float>{vd}.
    template <class U>
    [[gnu::always_inline]] constexpr explicit vec3(const vec3<U>& v) noexcept
        : x(static_cast<T>(v.x)), y(static_cast<T>(v.y)), z(static_cast<T>(v.z)) {}

    /// Component i in {0, 1, 2}: x, y, z (checked in debug builds).
    [[nodiscard]] [[gnu::always_inline]] constexpr T& operator[](std::size_t i) noexcept {
        QUAT_ASSERT(i < 3, "vec3 index out of range");
        return i == 0 ? x : (i == 1 ? y : z);
    }
    /// Component i in {0, 1, 2}, read-only.
    [[nodiscard]] [[gnu::always_inline]] constexpr const T& operator[](
        std::size_t i) const noexcept {
        QUAT_ASSERT(i < 3, "vec3 index out of range");
        return i == 0 ? x : (i == 1 ? y : z);
    }
};

#include "detail/isa_namespace.inc"
/// Negation.
template <class T>
[[nodiscard]] constexpr vec3<T> operator-(const vec3<T>& v) noexcept {
    return {-v.x, -v.y, -v.z};
}
/// Component-wise sum.
template <class T>
[[nodiscard]] constexpr vec3<T> operator+(const vec3<T>& a, const vec3<T>& b) noexcept {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
/// Component-wise difference.
template <class T>
[[nodiscard]] constexpr vec3<T> operator-(const vec3<T>& a, const vec3<T>& b) noexcept {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
/// Product with a scalar, component-wise; s converts to T (v * 2 for a vec3<float>).
template <class T>
[[nodiscard]] constexpr vec3<T> operator*(const vec3<T>& v, detail::type_identity_t<T> s) noexcept {
    return {v.x * s, v.y * s, v.z * s};
}
/// Product with a scalar, component-wise; s converts to T.
template <class T>
[[nodiscard]] constexpr vec3<T> operator*(detail::type_identity_t<T> s, const vec3<T>& v) noexcept {
    return v * s;
}
/// Component-wise division by s (converted to T); s == 0 gives IEEE infinities or NaN.
template <class T>
[[nodiscard]] constexpr vec3<T> operator/(const vec3<T>& v, detail::type_identity_t<T> s) noexcept {
    return {v.x / s, v.y / s, v.z / s};
}
/// v = v + w.
template <class T>
constexpr vec3<T>& operator+=(vec3<T>& v, const vec3<T>& w) noexcept {
    return v = v + w;
}
/// v = v - w.
template <class T>
constexpr vec3<T>& operator-=(vec3<T>& v, const vec3<T>& w) noexcept {
    return v = v - w;
}
/// v = v * s.
template <class T>
constexpr vec3<T>& operator*=(vec3<T>& v, detail::type_identity_t<T> s) noexcept {
    return v = v * s;
}
/// v = v / s.
template <class T>
constexpr vec3<T>& operator/=(vec3<T>& v, detail::type_identity_t<T> s) noexcept {
    return v = v / s;
}
/// Exact component-wise equality.
template <class T>
[[nodiscard]] constexpr bool operator==(const vec3<T>& a, const vec3<T>& b) noexcept {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}
/// Negation of ==.
template <class T>
[[nodiscard]] constexpr bool operator!=(const vec3<T>& a, const vec3<T>& b) noexcept {
    return !(a == b);
}

/// Dot product.
template <class T>
[[nodiscard]] constexpr T dot(const vec3<T>& a, const vec3<T>& b) noexcept {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// Cross product, right-handed: cross({1,0,0}, {0,1,0}) == {0,0,1}.
template <class T>
[[nodiscard]] constexpr vec3<T> cross(const vec3<T>& a, const vec3<T>& b) noexcept {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// |v|^2; overflows for components beyond sqrt(max).
template <class T>
[[nodiscard]] constexpr T squared_norm(const vec3<T>& v) noexcept {
    return dot(v, v);
}

namespace detail {

/// The largest |component| of v.
template <class T>
[[nodiscard]] constexpr T largest_magnitude(const vec3<T>& v) noexcept {
    return max(max(abs(v.x), abs(v.y)), abs(v.z));
}

/// True when every component of v is finite.
template <class T>
[[nodiscard]] constexpr bool is_finite(const vec3<T>& v) noexcept {
    return is_finite(v.x) && is_finite(v.y) && is_finite(v.z);
}

/// True when every component of v is finite and one is non-zero: a vector with a direction.
template <class T>
[[nodiscard]] constexpr bool has_direction(const vec3<T>& v) noexcept {
    return is_finite(v) && !(v.x == T(0) && v.y == T(0) && v.z == T(0));
}

}  // namespace detail

namespace detail {

/// a + t (b - a) with std::lerp's guarantees (C++20, P0811): exactly a at t = 0 and b at t = 1,
/// monotonic in t, lerp(a, a, t) == a for finite t. Where a and b differ in sign (or one is zero)
/// the weighted sum t b + (1 - t) a has them all; otherwise a + t (b - a), exactly b at t = 1 and
/// kept from passing b just before it. The same value as std::lerp wherever that is not NaN; where
/// it is (a NaN or infinite a or t), NaN, not std::lerp's b.
template <class T>
[[nodiscard]] constexpr T lerp(T a, T b, T t) noexcept {
    if ((a <= T(0) && b >= T(0)) || (a >= T(0) && b <= T(0))) return t * b + (T(1) - t) * a;
    if (t == T(1)) return b;
    const T x = a + t * (b - a);
    // Moving towards b and beyond: never short of b. Otherwise never past it. A NaN x is kept.
    if ((t > T(1)) == (b > a)) return !(x <= b) ? x : b;
    return !(x >= b) ? x : b;
}

}  // namespace detail

/// The point a + t (b - a), component by component as std::lerp computes it: exactly a at t = 0
/// and b at t = 1, monotonic in t, and a for a == b; t outside [0, 1] extrapolates. NaN in gives
/// NaN out (where std::lerp may return b). Not a rotation interpolation (slerp and nlerp are).
template <class T>
[[nodiscard]] constexpr vec3<T> lerp(const vec3<T>& a, const vec3<T>& b,
                                     detail::type_identity_t<T> t) noexcept {
    return {detail::lerp(a.x, b.x, t), detail::lerp(a.y, b.y, t), detail::lerp(a.z, b.z, t)};
}

/// Euclidean length |v|, without overflow or underflow for huge or tiny components.
template <class T>
[[nodiscard]] constexpr T norm(const vec3<T>& v) noexcept {
    const T s = squared_norm(v);
    // The fast path is exact enough whenever s neither overflowed nor lost precision to underflow.
    if (detail::in_normal_range(s)) return detail::sqrt(s);
    const T scale = detail::largest_magnitude(v);
    if (!(scale > T(0)) || !detail::is_finite(scale)) return detail::sqrt(s);  // 0, Inf or NaN
    return scale * detail::sqrt(squared_norm(v / scale));
}

/// v / |v| for components anywhere from the smallest subnormal to the largest finite value (the
/// length may overflow, the direction does not). Precondition: v is non-zero and finite, else NaN
/// in every component; try_normalize checks it.
template <class T>
[[nodiscard]] constexpr vec3<T> normalize(const vec3<T>& v) noexcept {
    const T s = squared_norm(v);
    if (detail::in_normal_range(s)) return v / detail::sqrt(s);
    // |v|^2 over- or underflowed (or v is zero or not finite): divide by the largest |component|
    // first, which keeps every ratio and brings |v| into [1, sqrt(3)].
    const T scale = detail::largest_magnitude(v);
    if (!(scale > T(0)) || !detail::is_finite(scale)) {
        const T nan = detail::quiet_nan<T>();
        return {nan, nan, nan};
    }
    const vec3<T> scaled = v / scale;
    return scaled / detail::sqrt(squared_norm(scaled));
}

/// v / |v|, or std::nullopt when v is zero or has a non-finite component; any finite non-zero
/// length is accepted, subnormal or near max().
template <class T>
[[nodiscard]] constexpr std::optional<vec3<T>> try_normalize(const vec3<T>& v) noexcept {
    if (!detail::has_direction(v)) return std::nullopt;
    return normalize(v);
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_VEC3_HPP_INCLUDED
