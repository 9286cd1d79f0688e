// Squad through keyframes at given times: Shoemake's spherical cubic with its control points scaled
// for uneven spacing, so that the angular velocity is continuous across every inner keyframe.
#ifndef QUAT_PATHS_KEYFRAME_SQUAD_HPP_INCLUDED
#define QUAT_PATHS_KEYFRAME_SQUAD_HPP_INCLUDED

#include <cstddef>

#include "../config.hpp"
#include "../detail/containers.hpp"
#include "../detail/math.hpp"
#include "../quaternion.hpp"
#include "detail/segments.hpp"
#include "squad.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
namespace detail {

/// (before - after) / (before + after) for positive durations, formed from their ratio so that
/// neither the sum nor the difference can overflow or underflow: exactly 0 for equal durations,
/// and +-1 in the limit of one duration negligible beside the other.
template <class T>
[[nodiscard]] constexpr T duration_skew(T before, T after) noexcept {
    if (before > after) {
        const T ratio = after / before;
        return (T(1) - ratio) / (T(1) + ratio);
    }
    const T ratio = before / after;
    return (ratio - T(1)) / (T(1) + ratio);
}

}  // namespace detail

/// The rotation at time t on Shoemake's squad through unit `rotations` at strictly increasing
/// `times` (containers, C arrays and time types as for keyframe_slerp), its control points scaled
/// for uneven spacing so that the angular velocity is continuous across every keyframe. On segment
/// i, with h_i = t_(i+1) - t_i: squad(q_i, a_i, a_(i+1), q_(i+1), (t - t_i) / h_i), where
///     a_i = q_i exp(-(h_(i-1) log(q_i* q_(i+1)) + h_i log(q_i* q_(i-1))) / (2 (h_(i-1) + h_i)))
/// (neighbours on q_i's hemisphere, as squad_control takes them) and a_0, a_(n-1) are the end
/// keyframes themselves. Derivation (docs/keyframes.md): near q_i the segment after it is
/// q_i exp(u (l_i + 2 c)), the one before q_i exp((u - 1) (l_(i-1) - 2 c)), with l the logs of
/// the steps and c = log(q_i* a_i); equal rates per unit of time on both sides give a_i, and the
/// tangent (l_(i-1) + l_i) / (h_(i-1) + h_i) of Kochanek and Bartels' adjustment for unequal
/// intervals (SIGGRAPH 1984), with every control point within a quarter turn of its keyframe.
/// Evenly spaced times give squad_control's points by the same operations. Exactly rotations[i]
/// at times[i]; the end keyframes are left and reached at their segment's slerp velocity (as in
/// rotation_spline: two keyframes give keyframe_slerp) and held outside the times.
/// Preconditions, debug checks (messages naming keyframe_squad) and release results for bad sizes
/// or times are keyframe_slerp's. A NaN t gives NaN; a NaN or infinite keyframe k a non-finite
/// component on segments k - 2 to k + 1, where it is an end or a control point's neighbour.
template <class Times, class Rotations, class T = detail::element_scalar_t<quaternion, Rotations>>
[[nodiscard]] constexpr quaternion<T> keyframe_squad(const Times& times, const Rotations& rotations,
                                                     detail::type_identity_t<T> t) noexcept {
    const std::size_t count = detail::size_of(rotations);
    QUAT_ASSERT(count > 0 && detail::size_of(times) == count,
                "quat::keyframe_squad: times and rotations differ in size or are empty");
    if (count == 0 || detail::size_of(times) != count) {
        const T nan = detail::quiet_nan<T>();
        return {nan, nan, nan, nan};
    }
    const auto* time = detail::data_of(times);
    QUAT_ASSERT(detail::are_keyframe_times<T>(time, count),
                "quat::keyframe_squad: keyframe times are not increasing, or not finite");
    const quaternion<T>* rotation = detail::data_of(rotations);
    const auto at = [time](std::size_t k) { return detail::to_scalar<T>(time[k]); };
    const T first = at(0), last = at(count - 1);
    if (count == 1 || t <= first || t >= last) {
        const quaternion<T>& end = count == 1 || t <= first ? rotation[0] : rotation[count - 1];
        QUAT_ASSERT(detail::is_near_unit(end),
                    "quat::keyframe_squad: a rotation is not a unit quaternion");
        return t == t ? end : end * t;
    }
    const std::size_t i = detail::segment_of(time, count, t);  // a NaN t goes on to squad
    const bool first_segment = i == 0, last_segment = i + 2 == count;
    // The keyframes the segment uses: its ends and, for the control points, their neighbours.
    QUAT_ASSERT(detail::is_near_unit(rotation[first_segment ? i : i - 1]) &&
                    detail::is_near_unit(rotation[i]) && detail::is_near_unit(rotation[i + 1]) &&
                    detail::is_near_unit(rotation[last_segment ? i + 1 : i + 2]),
                "quat::keyframe_squad: a rotation is not a unit quaternion");
    const T start = at(i), end = at(i + 1), duration = end - start;
    const quaternion<T> control_start =
        first_segment
            ? rotation[i]
            : detail::skewed_squad_control(rotation[i - 1], rotation[i], rotation[i + 1],
                                           detail::duration_skew(start - at(i - 1), duration));
    const quaternion<T> control_end =
        last_segment
            ? rotation[i + 1]
            : detail::skewed_squad_control(rotation[i], rotation[i + 1], rotation[i + 2],
                                           detail::duration_skew(duration, at(i + 2) - end));
    return squad(rotation[i], control_start, control_end, rotation[i + 1], (t - start) / duration);
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_PATHS_KEYFRAME_SQUAD_HPP_INCLUDED
