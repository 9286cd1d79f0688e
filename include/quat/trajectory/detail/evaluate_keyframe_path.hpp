// The loop behind both keyframe paths' evaluate(ts, out): each time's segment found from the last.
#ifndef QUAT_TRAJECTORY_DETAIL_EVALUATE_KEYFRAME_PATH_HPP_INCLUDED
#define QUAT_TRAJECTORY_DETAIL_EVALUATE_KEYFRAME_PATH_HPP_INCLUDED

#include <cstddef>
#include <type_traits>
#include <vector>

#include "../../detail/containers.hpp"
#include "../../detail/math.hpp"
#include "../../paths/detail/segments.hpp"
#include "../../rigid/dual_quaternion.hpp"
#include "../keyframe_path_state.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

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

#endif  // QUAT_TRAJECTORY_DETAIL_EVALUATE_KEYFRAME_PATH_HPP_INCLUDED
