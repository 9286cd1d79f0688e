// Shoemake's spherical cubic (squad): a path through keyframes whose angular velocity is
// continuous across them when the keyframes are evenly spaced in time.
#ifndef QUAT_PATHS_SQUAD_HPP_INCLUDED
#define QUAT_PATHS_SQUAD_HPP_INCLUDED

#include "../config.hpp"
#include "../conversions.hpp"
#include "../detail/math.hpp"
#include "../detail/relative_rotation.hpp"
#include "../quaternion.hpp"
#include "../vec3.hpp"
#include "interpolation.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
namespace detail {

/// squad_control with the tangent skewed towards one neighbour: q exp(-((l_n + l_p) + skew (l_n -
/// l_p)) / 4), l_n = log(q* next), l_p = log(q* previous), neighbours on q's hemisphere. skew = 0
/// is Shoemake's control point, computed with exactly its operations; keyframe_squad passes
/// skew = (h_before - h_after) / (h_before + h_after) for keyframes at uneven times.
template <class T>
[[nodiscard]] constexpr quaternion<T> skewed_squad_control(const quaternion<T>& previous,
                                                           const quaternion<T>& current,
                                                           const quaternion<T>& next,
                                                           T skew) noexcept {
    // log of a unit quaternion is half its rotation vector; exp(v) is from_rotation_vector(2 v).
    const vec3<T> to_next = to_rotation_vector(relative_rotation<true>(current, next));
    const vec3<T> to_previous = to_rotation_vector(relative_rotation<true>(current, previous));
    vec3<T> sum = to_next + to_previous;
    if (skew != T(0)) sum = sum + (to_next - to_previous) * skew;
    return current * from_rotation_vector(sum * T(-0.25));
}

}  // namespace detail

/// Shoemake's inner control point for keyframe `current` of a squad path (K. Shoemake, "Animating
/// rotation with quaternion curves", SIGGRAPH 1985; Dam, Koch and Lillholm, "Quaternions,
/// interpolation and animation", 1998, eq. 6.53): a = q exp(-(log(q* next) + log(q* previous)) / 4)
/// with q = current, `previous` and `next` first taken on q's hemisphere, so the path never takes
/// the long way round whatever the signs of the keyframes (GLM's glm::intermediate does not align
/// them). At the ends of a path pass the end keyframe twice, squad_control(q0, q0, q1): the path
/// then starts (and ends) at half the end segment's slerp speed. keyframe_squad builds the whole
/// path from keyframes at given times, with these points scaled for uneven spacing.
/// Preconditions: unit quaternions (checked in debug builds); NaN or infinite input gives NaN.
template <class T>
[[nodiscard]] constexpr quaternion<T> squad_control(const quaternion<T>& previous,
                                                    const quaternion<T>& current,
                                                    const quaternion<T>& next) noexcept {
    QUAT_ASSERT(detail::is_near_unit(previous) && detail::is_near_unit(current) &&
                    detail::is_near_unit(next),
                "quat::squad_control: an input is not a unit quaternion");
    return detail::skewed_squad_control(previous, current, next, T(0));
}

/// The spherical cubic from keyframe q1 (t = 0) to keyframe q2 (t = 1) with inner control points
/// a1 = squad_control(q0, q1, q2) and a2 = squad_control(q1, q2, q3):
/// slerp(slerp(q1, q2, t), slerp(a1, a2, t), 2t(1 - t)). Returns q1 at t = 0 and q2 (or -q2) at
/// t = 1 exactly; every slerp takes the shorter arc, so the result depends only on the rotations,
/// not on the signs of the quaternions. With keyframes evenly spaced in time the angular velocity
/// is continuous across keyframes; with uneven spacing it jumps by about the ratio of the
/// neighbouring durations there (the controls know nothing of time): keyframe_squad scales the
/// controls for the spacing, and rotation_spline is smooth to the acceleration. Argument order:
/// keyframe, control, control, keyframe (GLM's glm::squad takes q1, q2, s1, s2: a port that keeps
/// GLM's order compiles and is wrong). Preconditions: unit inputs (debug-checked) and t in
/// [0, 1]; a NaN or infinite input gives a non-finite component (at t = 0 and t = 1 only where
/// that keyframe is returned).
template <class T>
[[nodiscard]] constexpr quaternion<T> squad(const quaternion<T>& q1, const quaternion<T>& a1,
                                            const quaternion<T>& a2, const quaternion<T>& q2,
                                            detail::type_identity_t<T> t) noexcept {
    // Checked here, although slerp checks too, so that the message names squad, not slerp.
    QUAT_ASSERT(detail::is_near_unit(q1) && detail::is_near_unit(a1) && detail::is_near_unit(a2) &&
                    detail::is_near_unit(q2),
                "quat::squad: an input is not a unit quaternion");
    return slerp(slerp(q1, q2, t), slerp(a1, a2, t), T(2) * t * (T(1) - t));
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_PATHS_SQUAD_HPP_INCLUDED
