// Rotations that align one direction with another: rotation_between (shortest arc) and
// look_rotation (a camera's orientation from where it looks and which way is up).
#ifndef QUAT_ALIGN_HPP_INCLUDED
#define QUAT_ALIGN_HPP_INCLUDED

#include <optional>

#include "detail/shortest_arc.hpp"
#include "quaternion.hpp"
#include "vec3.hpp"

namespace quat {

#include "detail/isa_namespace.inc"

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
