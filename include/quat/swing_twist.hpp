// Swing-twist decomposition: a rotation split into a turn about a given axis and a turn that moves
// it.
#ifndef QUAT_SWING_TWIST_HPP_INCLUDED
#define QUAT_SWING_TWIST_HPP_INCLUDED

#include <limits>
#include <optional>

#include "config.hpp"
#include "detail/math.hpp"
#include "quaternion.hpp"
#include "vec3.hpp"

namespace quat {

/// Result of swing_twist: q == swing * twist as rotations (the twist applied first), twist a
/// rotation about the given axis, swing a rotation about an axis perpendicular to it.
template <class T>
struct swing_twist_parts {
    quaternion<T> swing;  ///< The rotation about an axis perpendicular to the given axis.
    quaternion<T> twist;  ///< The rotation about the given axis.
};

#include "detail/isa_namespace.inc"
namespace detail {

/// swing_twist for a unit axis, or std::nullopt where the twist is undefined.
template <class T>
[[nodiscard]] constexpr std::optional<swing_twist_parts<T>> try_swing_twist_unit(
    const quaternion<T>& q, const vec3<T>& unit_axis) noexcept {
    const T along = dot(vec3<T>{q.x, q.y, q.z}, unit_axis);
    const T eps = detail::epsilon<T>();
    if (q.w * q.w + along * along <= eps * eps) return std::nullopt;  // NaN goes on, to NaN parts
    const vec3<T> v = unit_axis * along;
    const quaternion<T> twist = normalize(quaternion<T>{q.w, v.x, v.y, v.z});
    return swing_twist_parts<T>{q * conjugate(twist), twist};
}

}  // namespace detail

/// Splits the unit rotation q into swing * twist (twist applied first): twist = normalize(w, (v .
/// a) a) turns about a = axis / |axis|, and swing = q * twist* turns about an axis perpendicular to
/// a; swing is the smallest rotation taking a to rotate(q, a) (the decomposition of Unreal's
/// FQuat::ToSwingTwist). Where w^2 + (v . a)^2 <= epsilon^2 (q turns a to about -a, the twist is
/// undefined) the twist is the identity and the swing is q. Preconditions: unit q and a non-zero
/// finite axis of any length (NaN results otherwise); try_swing_twist checks them.
template <class T>
[[nodiscard]] constexpr swing_twist_parts<T> swing_twist(const quaternion<T>& q,
                                                         const vec3<T>& axis) noexcept {
    QUAT_ASSERT(detail::is_near_unit(q), "quat::swing_twist: q is not a unit quaternion");
    return detail::try_swing_twist_unit(q, normalize(axis))
        .value_or(swing_twist_parts<T>{q, quaternion<T>::identity()});
}

/// swing_twist(q, axis), or std::nullopt where the twist is undefined (w^2 + (v . a)^2 <=
/// epsilon^2), when q is not a unit quaternion (|q|^2 off 1 by more than 1/4096, the debug check of
/// swing_twist), when the axis is zero, or when q or the axis has a NaN or infinite component.
/// Never asserts: the path for untrusted input.
template <class T>
[[nodiscard]] constexpr std::optional<swing_twist_parts<T>> try_swing_twist(
    const quaternion<T>& q, const vec3<T>& axis) noexcept {
    const std::optional<vec3<T>> unit_axis = try_normalize(axis);
    if (!unit_axis || !detail::is_finite(q) || !detail::is_near_unit(q)) return std::nullopt;
    return detail::try_swing_twist_unit(q, *unit_axis);
}

}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_SWING_TWIST_HPP_INCLUDED
