// Piecewise slerp through keyframes at given times: scipy's Slerp(times, rotations)(t).
#ifndef QUAT_PATHS_KEYFRAME_SLERP_HPP_INCLUDED
#define QUAT_PATHS_KEYFRAME_SLERP_HPP_INCLUDED

#include <cstddef>
#include <limits>

#include "../config.hpp"
#include "../detail/containers.hpp"
#include "../quaternion.hpp"
#include "detail/segments.hpp"
#include "interpolation.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
/// The rotation at time t on the piecewise slerp through unit `rotations` at strictly increasing
/// `times` (contiguous containers with data() and size(), or C arrays, of equal size >= 1; times
/// of any arithmetic type, converted to T): slerp of the two keyframes around t, at constant
/// angular velocity along the shorter arc within each segment, the same rotations as scipy's
/// Slerp(times, rotations)(t). Exactly rotations[i] at times[i]; t before the first time or after
/// the last gives the end keyframe (scipy raises there). The angular velocity jumps at every
/// keyframe: squad or rotation_spline is smooth.
/// Preconditions: equal, non-zero sizes, finite and strictly increasing times, unit rotations.
/// Debug builds check the sizes, every time on every call (O(n): the search alone visits too few
/// to catch an unsorted list) and the keyframes the result comes from; release builds return NaN
/// for empty or unequal sizes and an unspecified, possibly NaN, rotation for bad times. A NaN t
/// gives NaN; a NaN or infinite keyframe gives a non-finite component wherever it is used (held
/// as it is outside the times, as slerp gives it inside).
template <class Times, class Rotations, class T = detail::element_scalar_t<quaternion, Rotations>>
[[nodiscard]] constexpr quaternion<T> keyframe_slerp(const Times& times, const Rotations& rotations,
                                                     detail::type_identity_t<T> t) noexcept {
    const std::size_t count = detail::size_of(rotations);
    QUAT_ASSERT(count > 0 && detail::size_of(times) == count,
                "quat::keyframe_slerp: times and rotations differ in size or are empty");
    if (count == 0 || detail::size_of(times) != count) {
        const T nan = detail::quiet_nan<T>();
        return {nan, nan, nan, nan};
    }
    const auto* time = detail::data_of(times);
    QUAT_ASSERT(detail::are_keyframe_times<T>(time, count),
                "quat::keyframe_slerp: keyframe times are not increasing, or not finite");
    const quaternion<T>* rotation = detail::data_of(rotations);
    const T first = detail::to_scalar<T>(time[0]), last = detail::to_scalar<T>(time[count - 1]);
    if (count == 1 || t <= first || t >= last) {
        const quaternion<T>& end = count == 1 || t <= first ? rotation[0] : rotation[count - 1];
        // Checked here, as slerp would, so that the message names the function the user called.
        QUAT_ASSERT(detail::is_near_unit(end),
                    "quat::keyframe_slerp: a rotation is not a unit quaternion");
        return t == t ? end : end * t;
    }
    const std::size_t i = detail::segment_of(time, count, t);  // a NaN t goes on to slerp
    QUAT_ASSERT(detail::is_near_unit(rotation[i]) && detail::is_near_unit(rotation[i + 1]),
                "quat::keyframe_slerp: a rotation is not a unit quaternion");
    const T start = detail::to_scalar<T>(time[i]);
    return slerp(rotation[i], rotation[i + 1],
                 (t - start) / (detail::to_scalar<T>(time[i + 1]) - start));
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_PATHS_KEYFRAME_SLERP_HPP_INCLUDED
