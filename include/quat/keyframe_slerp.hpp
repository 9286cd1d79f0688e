// Piecewise slerp through keyframes at given times: scipy's Slerp(times, rotations)(t).
#ifndef QUAT_KEYFRAME_SLERP_HPP_INCLUDED
#define QUAT_KEYFRAME_SLERP_HPP_INCLUDED

#include <cstddef>

#include "config.hpp"
#include "detail/containers.hpp"
#include "detail/segments.hpp"
#include "interpolation.hpp"
#include "quaternion.hpp"

namespace quat {

/// The rotation at time t on the piecewise slerp through unit `rotations` at strictly increasing
/// `times` (contiguous containers with data() and size(), or C arrays, of equal size >= 1): slerp
/// of the two keyframes around t, at constant angular velocity along the shorter arc within each
/// segment, the same rotations as scipy's Slerp(times, rotations)(t). Exactly rotations[i] at
/// times[i]; t before the first time or after the last gives the end keyframe (scipy raises
/// there). The angular velocity jumps at every keyframe: squad or rotation_spline is smooth.
/// Preconditions: equal, non-zero sizes, strictly increasing times,
/// unit rotations (debug builds check the times the search visits). A NaN t or keyframe gives NaN.
template <class Times, class Rotations, class T = detail::quaternion_scalar_t<Rotations>>
[[nodiscard]] constexpr quaternion<T> keyframe_slerp(const Times& times, const Rotations& rotations,
                                                     detail::type_identity_t<T> t) noexcept {
    const std::size_t count = detail::size_of(rotations);
    QUAT_ASSERT(count > 0 && detail::size_of(times) == count,
                "quat::keyframe_slerp: times and rotations differ in size or are empty");
    const auto* time = detail::data_of(times);
    const quaternion<T>* rotation = detail::data_of(rotations);
    if (count == 1) return t == t ? rotation[0] : rotation[0] * t;
    const T first = static_cast<T>(time[0]), last = static_cast<T>(time[count - 1]);
    if (t <= first) return rotation[0];
    if (t >= last) return rotation[count - 1];
    const std::size_t i = detail::segment_of(time, count, t);  // a NaN t goes on to slerp
    const T start = static_cast<T>(time[i]);
    return slerp(rotation[i], rotation[i + 1], (t - start) / (static_cast<T>(time[i + 1]) - start));
}

}  // namespace quat

#endif  // QUAT_KEYFRAME_SLERP_HPP_INCLUDED
