// Dual quaternions real + eps dual (eps^2 = 0): rigid motions x -> R x + t in 8 numbers.
#ifndef QUAT_RIGID_DUAL_QUATERNION_HPP_INCLUDED
#define QUAT_RIGID_DUAL_QUATERNION_HPP_INCLUDED

#include <optional>
#include <type_traits>

#include "../config.hpp"
#include "../detail/math.hpp"
#include "../quaternion.hpp"
#include "../vec3.hpp"

namespace quat {

/// Dual quaternion real + eps dual with eps^2 = 0. A unit dual quaternion (|real| = 1, dot(real,
/// dual) = 0) is the rigid motion x -> R x + t with real the rotation R and dual = (0, t) real / 2;
/// dq and -dq are the same motion. Members are public, as for quaternion.
template <class T>
struct dual_quaternion {
    quaternion<T> real;  ///< The rotation.
    quaternion<T> dual;  ///< Half the translation times the rotation: (0, t) real / 2.

    /// Components left uninitialized, as in a plain struct; dual_quaternion<T>{} is zero.
    dual_quaternion() = default;
    /// The dual quaternion real_part + eps dual_part.
    [[gnu::always_inline]] constexpr dual_quaternion(const quaternion<T>& real_part,
                                                     const quaternion<T>& dual_part) noexcept
        : real(real_part), dual(dual_part) {}
    /// Conversion from another precision, component by component.
    template <class U>
    [[gnu::always_inline]] constexpr explicit dual_quaternion(const dual_quaternion<U>& dq) noexcept
        : real(quaternion<T>(dq.real)), dual(quaternion<T>(dq.dual)) {}

    /// The motion that moves nothing: real 1, dual 0.
    [[nodiscard]] [[gnu::always_inline]] static constexpr dual_quaternion identity() noexcept {
        return {quaternion<T>::identity(), quaternion<T>{T(0), T(0), T(0), T(0)}};
    }
    /// The pure translation x -> x + t: to_dual_quaternion(identity, t), real 1, dual (0, t / 2).
    [[nodiscard]] [[gnu::always_inline]] static constexpr dual_quaternion from_translation(
        const vec3<T>& t) noexcept {
        return to_dual_quaternion(quaternion<T>::identity(), t);
    }
};

using dual_quaternionf = dual_quaternion<float>;   ///< Single-precision dual quaternion.
using dual_quaterniond = dual_quaternion<double>;  ///< Double-precision dual quaternion.

#include "../detail/isa_namespace.inc"
/// The rigid motion x -> R x + t that first rotates by unit `rotation`, then translates by
/// `translation`: real = rotation, dual = (0, translation) rotation / 2.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> to_dual_quaternion(const quaternion<T>& rotation,
                                                              const vec3<T>& translation) noexcept {
    const quaternion<T> half{T(0), translation.x * T(0.5), translation.y * T(0.5),
                             translation.z * T(0.5)};
    return {rotation, half * rotation};
}

/// The pure rotation x -> R x by unit `rotation`: to_dual_quaternion(rotation, {0, 0, 0}), real =
/// rotation, dual zero. (A pure translation is dual_quaternion<T>::from_translation(t).)
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> to_dual_quaternion(
    const quaternion<T>& rotation) noexcept {
    return to_dual_quaternion(rotation, vec3<T>{T(0), T(0), T(0)});
}

/// The rotation of the unit dual quaternion dq (its real part).
template <class T>
[[nodiscard]] constexpr quaternion<T> rotation_of(const dual_quaternion<T>& dq) noexcept {
    return dq.real;
}

namespace detail {

/// 2 x, or +-max() where x is within a few units of roundoff of max() / 2 and the doubling alone
/// would overflow (a value of max() read back with rounding error); infinite beyond that.
template <class T>
[[nodiscard]] constexpr T doubled_within_range(T x) noexcept {
    const T twice = x + x;
    if constexpr (std::is_floating_point_v<T>) {
        constexpr T limit = largest<T>() / T(2) * (T(1) + T(16) * epsilon<T>());
        if (!is_finite(twice) && abs(x) <= limit) return x < T(0) ? -largest<T>() : largest<T>();
    }
    return twice;
}

/// Half the translation, t / 2 = the vector part of dual real*: w_r d - w_d r + r x d, without
/// the scalar part the full product would spend 4 multiplications on (12 multiplications, 9
/// additions). Each component is a dot product of r with a signed permutation of d, so no partial
/// sum exceeds |r| |d| = |t| / 2 (at most sqrt(3) max() / 2): only a doubling can overflow.
template <class T>
[[nodiscard]] constexpr vec3<T> half_translation(const dual_quaternion<T>& dq) noexcept {
    const quaternion<T>& r = dq.real;
    const quaternion<T>& d = dq.dual;
    return {r.w * d.x - d.w * r.x + (r.y * d.z - r.z * d.y),
            r.w * d.y - d.w * r.y + (r.z * d.x - r.x * d.z),
            r.w * d.z - d.w * r.z + (r.x * d.y - r.y * d.x)};
}

}  // namespace detail

/// The translation t = 2 dual real* of the unit dual quaternion dq, as a vector, for components
/// up to max(): one that rounding alone carries past max() (as in reading back a translation of
/// max() through to_dual_quaternion) is +-max(), not infinite.
/// Precondition: |real| = 1; a real part of norm s gives s^2 t.
template <class T>
[[nodiscard]] constexpr vec3<T> translation_of(const dual_quaternion<T>& dq) noexcept {
    const vec3<T> half = detail::half_translation(dq);
    return {detail::doubled_within_range(half.x), detail::doubled_within_range(half.y),
            detail::doubled_within_range(half.z)};
}

/// Negation: the same rigid motion.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> operator-(const dual_quaternion<T>& dq) noexcept {
    return {-dq.real, -dq.dual};
}

/// Product (a.real + eps a.dual)(b.real + eps b.dual): as rigid motions, a * b applies b first.
/// 48 multiplications and 40 additions.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> operator*(const dual_quaternion<T>& a,
                                                     const dual_quaternion<T>& b) noexcept {
    return {a.real * b.real, a.real * b.dual + a.dual * b.real};
}

/// a = a * b: as rigid motions, b is applied first, then the old a.
template <class T>
constexpr dual_quaternion<T>& operator*=(dual_quaternion<T>& a,
                                         const dual_quaternion<T>& b) noexcept {
    return a = a * b;
}

/// Product with a scalar, all eight components (as GLM's tdualquat * s); s converts to T. Not a
/// rigid motion unless s is +-1: normalize or blend weights use it.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> operator*(const dual_quaternion<T>& dq,
                                                     detail::type_identity_t<T> s) noexcept {
    return {dq.real * s, dq.dual * s};
}
/// Product with a scalar, all eight components; s converts to T.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> operator*(detail::type_identity_t<T> s,
                                                     const dual_quaternion<T>& dq) noexcept {
    return dq * s;
}
/// Division of all eight components by s (converted to T); s == 0 gives IEEE infinities or NaN.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> operator/(const dual_quaternion<T>& dq,
                                                     detail::type_identity_t<T> s) noexcept {
    return {dq.real / s, dq.dual / s};
}
/// dq = dq * s.
template <class T>
constexpr dual_quaternion<T>& operator*=(dual_quaternion<T>& dq,
                                         detail::type_identity_t<T> s) noexcept {
    return dq = dq * s;
}
/// dq = dq / s.
template <class T>
constexpr dual_quaternion<T>& operator/=(dual_quaternion<T>& dq,
                                         detail::type_identity_t<T> s) noexcept {
    return dq = dq / s;
}

/// Exact component-wise equality; dq == -dq is false although both are one motion.
template <class T>
[[nodiscard]] constexpr bool operator==(const dual_quaternion<T>& a,
                                        const dual_quaternion<T>& b) noexcept {
    return a.real == b.real && a.dual == b.dual;
}
/// Negation of ==.
template <class T>
[[nodiscard]] constexpr bool operator!=(const dual_quaternion<T>& a,
                                        const dual_quaternion<T>& b) noexcept {
    return !(a == b);
}

/// The multiplicative inverse real^-1 - eps real^-1 dual real^-1, which for a unit dq is the
/// inverse rigid motion x -> R^T (x - t). Valid for every dq with a non-zero real part, whether or
/// not dual is orthogonal to real, and for any magnitude whose inverse is representable (as
/// inverse(quaternion)). A zero real part or a NaN or infinite real component gives NaN in both
/// parts; a NaN or infinite dual component, NaN in the dual part.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> inverse(const dual_quaternion<T>& dq) noexcept {
    const quaternion<T> real = inverse(dq.real);
    return {real, -(real * dq.dual * real)};
}

/// The unit dual quaternion nearest dq: divided by |real|, then the dual part's component along
/// the real part removed, so dot(real, dual) = 0 and translation_of reads a pure vector. The
/// rotation is normalize(dq.real); the translation is that of dq for a dq with orthogonal parts.
/// Precondition: real non-zero and dq finite, else the result holds NaN; try_normalize checks it.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> normalize(const dual_quaternion<T>& dq) noexcept {
    const quaternion<T> real = normalize(dq.real);
    const quaternion<T> dual = dq.dual / norm(dq.real);
    return {real, dual - real * dot(real, dual)};
}

/// normalize(dq), or std::nullopt when the real part is zero, any component is not finite, or the
/// normalized dual part overflows.
template <class T>
[[nodiscard]] constexpr std::optional<dual_quaternion<T>> try_normalize(
    const dual_quaternion<T>& dq) noexcept {
    const quaternion<T>& d = dq.dual;
    if (!try_normalize(dq.real) || !detail::is_finite(d)) return std::nullopt;
    const dual_quaternion<T> result = normalize(dq);
    // A dual part huge beside a tiny real part can overflow once divided by |real|.
    if (!detail::is_finite(squared_norm(result.dual))) return std::nullopt;
    return result;
}

/// R p + t: moves the point p by the unit dual quaternion dq, with rotate(real, p)'s accuracy for
/// a real part a few eps off unit. Overflows only where R p + t does, even for a translation
/// component near max(); a result component below 2 min() (subnormal halves) is a multiple of
/// 2 denorm_min(). Precondition: |real| = 1 and dot(real, dual) = 0, as normalize returns them
/// (|real| is checked in debug builds).
template <class T>
[[nodiscard]] constexpr vec3<T> transform(const dual_quaternion<T>& dq, const vec3<T>& p) noexcept {
    QUAT_ASSERT(detail::is_near_unit(dq.real),
                "quat::transform: the real part is not a unit quaternion");
    // (R p) / 2 + t / 2, doubled once: halving by a power of 2 is exact, so this is R p + t
    // rounded once per step, as rotate(real, p) + translation_of(dq), without translation_of's
    // range check on t alone, whose branches kept a loop over many motions from vectorizing
    // (1.4x the time). s / 2 = 2 - |r|^2 is exactly half of rotate's 4 - 2 |r|^2.
    const quaternion<T>& r = dq.real;
    const T s = T(2) - squared_norm(r);
    const rotation_matrix<T> half_rotation =
        detail::scaled_matrix(r, r.x * s, r.y * s, r.z * s, T(0.5));
    const vec3<T> half = rotate(half_rotation, p) + detail::half_translation(dq);
    return half + half;
}

/// dq * p, as GLM's tdualquat * vec3 and Eigen's Isometry3 * Vector3 write it: the same as
/// transform(dq, p), debug check included. A point transform: p is rotated, then translated (use
/// transform_vector for a direction).
template <class T>
[[nodiscard]] constexpr vec3<T> operator*(const dual_quaternion<T>& dq, const vec3<T>& p) noexcept {
    return transform(dq, p);
}

/// R v: turns the direction v by the rotation of the unit dual quaternion dq, without translating.
/// Precondition: |real| = 1 (checked in debug builds).
template <class T>
[[nodiscard]] constexpr vec3<T> transform_vector(const dual_quaternion<T>& dq,
                                                 const vec3<T>& v) noexcept {
    QUAT_ASSERT(detail::is_near_unit(dq.real),
                "quat::transform_vector: the real part is not a unit quaternion");
    return detail::rotate_unchecked(dq.real, v);
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_RIGID_DUAL_QUATERNION_HPP_INCLUDED
