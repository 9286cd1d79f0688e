// Checking and unpacking the (time, pose) keyframes both keyframe paths take.
#ifndef QUAT_TRAJECTORY_DETAIL_KEYFRAME_POSES_HPP_INCLUDED
#define QUAT_TRAJECTORY_DETAIL_KEYFRAME_POSES_HPP_INCLUDED

#include <cstddef>
#include <optional>
#include <vector>

#include "../../detail/containers.hpp"
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

/// Keyframes unpacked: the times converted to T, the rotations and the body origin's positions.
template <class T>
struct keyframes {
    std::vector<T> times;
    std::vector<quaternion<T>> rotations;
    std::vector<vec3<T>> positions;
};

/// The keyframes of containers (data() and size(), or C arrays) of `times` and of dual_quaternion
/// `poses`, the first `count` of each, each pose normalized.
template <class T, class Times, class Poses>
[[nodiscard]] keyframes<T> unpack_keyframe_poses(const Times& times, const Poses& poses,
                                                 std::size_t count) {
    const auto* time = data_of(times);
    const dual_quaternion<T>* pose = data_of(poses);
    keyframes<T> k;
    k.times.resize(count);
    k.rotations.resize(count);
    k.positions.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const dual_quaternion<T> unit = normalize(pose[i]);
        k.times[i] = to_scalar<T>(time[i]);
        k.rotations[i] = unit.real;
        k.positions[i] = translation_of(unit);
    }
    return k;
}

/// The keyframes, or std::nullopt when there are fewer than two, the sizes differ or
/// are_valid_keyframe_poses does not hold: the input checks of both keyframe paths' try_make.
template <class T, class Times, class Poses>
[[nodiscard]] std::optional<keyframes<T>> try_unpack_keyframe_poses(const Times& times,
                                                                    const Poses& poses) {
    const std::size_t count = size_of(times);
    if (count < 2 || size_of(poses) != count) return std::nullopt;
    const dual_quaternion<T>* pose = data_of(poses);
    if (!are_valid_keyframe_poses(data_of(times), pose, count)) return std::nullopt;
    return unpack_keyframe_poses<T>(times, poses, count);
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_DETAIL_KEYFRAME_POSES_HPP_INCLUDED
