// Checking and unpacking the (time, pose) keyframes both keyframe paths take, and the loop behind
// their evaluate(ts, out).
#ifndef QUAT_TRAJECTORY_DETAIL_KEYFRAME_POSES_HPP_INCLUDED
#define QUAT_TRAJECTORY_DETAIL_KEYFRAME_POSES_HPP_INCLUDED

#include <cstddef>
#include <optional>
#include <type_traits>
#include <vector>

#include "../../detail/containers.hpp"
#include "../../detail/math.hpp"
#include "../../paths/detail/segments.hpp"
#include "../../quaternion.hpp"
#include "../../rigid/dual_quaternion.hpp"
#include "../../vec3.hpp"
#include "../keyframe_path_state.hpp"

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

/// out[k] = pose_at(t, i) for an output of dual_quaternion<T>, state_at(t, i) for one of
/// keyframe_path_state<T>, t = ts[k] converted to T and i its segment of the keyframe `times`, for
/// the shorter of ts and out. The segment search starts from the last one, so that times in
/// increasing order cost constant time each.
template <class T, class Times, class Output, class PoseAt, class StateAt>
void evaluate_keyframe_path(const std::vector<T>& times, const Times& ts, Output& out,
                            const PoseAt& pose_at, const StateAt& state_at) noexcept {
    using element = std::remove_pointer_t<decltype(data_of(out))>;
    static_assert(std::is_same_v<element, dual_quaternion<T>> ||
                      std::is_same_v<element, keyframe_path_state<T>>,
                  "quat keyframe path evaluate: out holds dual_quaternion<T> or "
                  "keyframe_path_state<T>");
    const std::size_t count = size_of(ts) < size_of(out) ? size_of(ts) : size_of(out);
    const auto* t = data_of(ts);
    element* result = data_of(out);
    std::size_t segment = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const T time = to_scalar<T>(t[k]);
        segment = segment_of(times.data(), times.size(), time, segment);
        if constexpr (std::is_same_v<element, dual_quaternion<T>>)
            result[k] = pose_at(time, segment);
        else result[k] = state_at(time, segment);
    }
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_DETAIL_KEYFRAME_POSES_HPP_INCLUDED
