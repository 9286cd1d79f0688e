// Finding the segment of a keyframe path that holds a time, and checking keyframe times.
#ifndef QUAT_PATHS_DETAIL_SEGMENTS_HPP_INCLUDED
#define QUAT_PATHS_DETAIL_SEGMENTS_HPP_INCLUDED

#include <cstddef>
#include <limits>
#include <type_traits>

#include "../../detail/math.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

/// static_cast<T>(x), except that a floating-point x beyond T's largest finite value gives an
/// infinity of its sign, as IEEE rounding would (the cast itself is undefined there): a double
/// time of 1e300 beside float rotations becomes infinite, which the checks then see.
template <class T, class U>
[[nodiscard]] constexpr T to_scalar(U x) noexcept {
    if constexpr (std::is_floating_point_v<T> && std::is_floating_point_v<U> &&
                  (sizeof(U) > sizeof(T))) {
        const U largest = static_cast<U>(detail::largest<T>());
        if (x > largest) return detail::infinity<T>();
        if (x < -largest) return -detail::infinity<T>();
    }
    return static_cast<T>(x);
}

/// The segment i in [0, count - 2] with times[i] <= t < times[i + 1]: 0 for t before times[1]
/// (and for NaN), count - 2 from times[count - 2] on, and 0 when count < 2 (no segment: callers
/// check that first). `hint`, a segment tried first together with its successor, makes a walk
/// through sorted times constant time per step. Unsorted times give some index in [0, count - 2],
/// never one out of range; callers check the order (the search visits too few times to).
template <class Time, class T>
[[nodiscard]] constexpr std::size_t segment_of(const Time* times, std::size_t count, T t,
                                               std::size_t hint = 0) noexcept {
    if (count < 2) return 0;  // count - 2 would wrap
    const auto time = [times](std::size_t i) { return to_scalar<T>(times[i]); };
    const std::size_t last = count - 2;
    if (hint <= last && !(t < time(hint))) {
        if (hint == last || t < time(hint + 1)) return hint;
        if (hint + 1 == last || t < time(hint + 2)) return hint + 1;
    }
    // Binary search for the last i <= last with times[i] <= t (times[0] counts as -infinity).
    std::size_t low = 0, high = last;
    while (low < high) {
        const std::size_t middle = low + (high - low + 1) / 2;
        if (t < time(middle) || t != t) high = middle - 1;
        else low = middle;
    }
    return low;
}

/// True when the `count` times, converted to T, are finite and strictly increasing; the debug
/// check of the keyframe paths. Always true for scalars other than float, double and long double,
/// so that debug checks ask nothing more of a user scalar.
template <class T, class Time>
[[nodiscard]] constexpr bool are_keyframe_times(const Time* times, std::size_t count) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        for (std::size_t i = 0; i < count; ++i) {
            const T time = to_scalar<T>(times[i]);
            if (!is_finite(time) || (i > 0 && !(to_scalar<T>(times[i - 1]) < time))) return false;
        }
    } else {
        static_cast<void>(times);
        static_cast<void>(count);
    }
    return true;
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_PATHS_DETAIL_SEGMENTS_HPP_INCLUDED
