// Checking and unpacking the (time, pose) keyframes both keyframe paths take.
#ifndef QUAT_TRAJECTORY_DETAIL_KEYFRAME_POSES_HPP_INCLUDED
#define QUAT_TRAJECTORY_DETAIL_KEYFRAME_POSES_HPP_INCLUDED

#include <cstddef>
#include <optional>
#include <vector>

#include "../../detail/math.hpp"
#include "../../paths/detail/segments.hpp"
#include "../../quaternion.hpp"
#include "../../rigid/dual_quaternion.hpp"
#include "../../vec3.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

/// True when the `count` times, converted to T, are finite and strictly increasing, and every
/// pose is finite with a non-zero real part whose normalized translation is finite: what try_make
/// of both keyframe paths asks of its input beyond count >= 2.
template <class T, class Time>
[[nodiscard]] bool are_valid_keyframe_poses(const Time* times, const dual_quaternion<T>* poses,
                                            std::size_t count) noexcept {
    for (std::size_t i = 0; i < count; ++i) {
        const T t = to_scalar<T>(times[i]);
        if (!is_finite(t) || (i > 0 && !(to_scalar<T>(times[i - 1]) < t))) return false;
        const std::optional<dual_quaternion<T>> pose = try_normalize(poses[i]);
        if (!pose || !is_finite(translation_of(*pose))) return false;
    }
    return true;
}

/// The times converted to T, and each pose normalized and split into its rotation and the
/// position of the body's origin.
template <class T, class Time>
void unpack_keyframe_poses(const Time* times, const dual_quaternion<T>* poses, std::size_t count,
                           std::vector<T>& out_times, std::vector<quaternion<T>>& rotations,
                           std::vector<vec3<T>>& positions) {
    out_times.resize(count);
    rotations.resize(count);
    positions.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const dual_quaternion<T> pose = normalize(poses[i]);
        out_times[i] = to_scalar<T>(times[i]);
        rotations[i] = pose.real;
        positions[i] = translation_of(pose);
    }
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_DETAIL_KEYFRAME_POSES_HPP_INCLUDED
