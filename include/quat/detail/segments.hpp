// Finding the segment of a keyframe path that holds a time.
#ifndef QUAT_DETAIL_SEGMENTS_HPP_INCLUDED
#define QUAT_DETAIL_SEGMENTS_HPP_INCLUDED

#include <cstddef>

#include "../config.hpp"

namespace quat::detail {

/// The segment i in [0, count - 2] with times[i] <= t < times[i + 1]: 0 for t before times[1]
/// (and for NaN), count - 2 from times[count - 2] on. `hint`, a segment tried first together with
/// its successor, makes a walk through sorted times constant time per step. count >= 2; debug
/// builds check that the times the search visits increase.
template <class Time, class T>
[[nodiscard]] constexpr std::size_t segment_of(const Time* times, std::size_t count, T t,
                                               std::size_t hint = 0) noexcept {
    const auto time = [times](std::size_t i) { return static_cast<T>(times[i]); };
    const std::size_t last = count - 2;
    if (hint <= last && !(t < time(hint))) {
        if (hint == last || t < time(hint + 1)) return hint;
        if (hint + 1 == last || t < time(hint + 2)) return hint + 1;
    }
    // Binary search for the last i <= last with times[i] <= t (times[0] counts as -infinity).
    std::size_t low = 0, high = last;
    while (low < high) {
        const std::size_t middle = low + (high - low + 1) / 2;
        QUAT_ASSERT(time(middle - 1) < time(middle), "quat: keyframe times are not increasing");
        if (t < time(middle) || t != t) high = middle - 1;
        else low = middle;
    }
    return low;
}

}  // namespace quat::detail

#endif  // QUAT_DETAIL_SEGMENTS_HPP_INCLUDED
