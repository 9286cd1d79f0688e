// One segment's cubic of a keyframe path, written in the segment's own time u in [0, 1], and the
// clamped C2 cubic spline of positions that the split keyframe path moves its origin along.
#ifndef QUAT_TRAJECTORY_DETAIL_HERMITE_CUBIC_HPP_INCLUDED
#define QUAT_TRAJECTORY_DETAIL_HERMITE_CUBIC_HPP_INCLUDED

#include <cstddef>
#include <type_traits>
#include <vector>

#include "../../detail/math.hpp"
#include "../../paths/detail/segment_cubic.hpp"
#include "../../paths/detail/segments.hpp"
#include "../../vec3.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

/// The cubic with f(0) = 0, f(1) = rise and slopes df/du = start at 0 and end at 1.
template <class T>
[[nodiscard]] constexpr hermite_cubic<T> hermite_cubic_of(const vec3<T>& rise, const vec3<T>& start,
                                                          const vec3<T>& end) noexcept {
    return {rise * T(-2) + start + end, rise * T(3) - start * T(2) - end, start};
}

/// A cubic's value and first two derivatives in the caller's time.
template <class T>
struct cubic_motion {
    vec3<T> value, rate, second;
};

/// The value, rate and second derivative at u of a segment lasting `duration`; divided by the
/// duration twice rather than by its square, which over- or underflows first.
template <class T>
[[nodiscard]] constexpr cubic_motion<T> cubic_motion_at(const hermite_cubic<T>& f, T u,
                                                        T duration) noexcept {
    return {((f.a * u + f.b) * u + f.c) * u, ((f.a * (T(3) * u) + f.b * T(2)) * u + f.c) / duration,
            (f.a * (T(6) * u) + f.b * T(2)) / duration / duration};
}

/// The vector converted to T component by component, beyond T's range an infinity (the plain
/// conversion from double to float is undefined there).
template <class T, class S>
[[nodiscard]] constexpr vec3<T> narrow(const vec3<S>& v) noexcept {
    return {to_scalar<T>(v.x), to_scalar<T>(v.y), to_scalar<T>(v.z)};
}

/// The C2 cubic spline through `positions` at `times` (count >= 2) whose velocities at the first
/// and last keyframes are those of the first and last segments' straight lines, as segment cubics
/// of the displacement from each keyframe. Solved in double for float, in a unit of time between
/// the shortest and longest duration (their geometric mean), by the Thomas algorithm: the system
/// 2 v_(k-1) / h_(k-1) + 4 (1 / h_(k-1) + 1 / h_k) v_k + 2 v_(k+1) / h_k
///     = 6 (p_k - p_(k-1)) / h_(k-1)^2 + 6 (p_(k+1) - p_k) / h_k^2
/// (continuity of the second derivative at inner keyframe k) is strictly diagonally dominant.
template <class T>
void clamped_cubic_spline(const T* times, const vec3<T>* positions, std::size_t count,
                          std::vector<hermite_cubic<T>>& cubics) {
    using S = std::conditional_t<std::is_same_v<T, float>, double, T>;
    const std::size_t segments = count - 1;
    std::vector<S> duration(segments), diagonal(count);
    std::vector<vec3<S>> rise(segments), velocity(count);
    S shortest = infinity<S>(), longest = S(0);
    for (std::size_t j = 0; j < segments; ++j) {
        duration[j] = static_cast<S>(times[j + 1]) - static_cast<S>(times[j]);
        rise[j] = vec3<S>(positions[j + 1]) - vec3<S>(positions[j]);
        shortest = duration[j] < shortest ? duration[j] : shortest;
        longest = duration[j] > longest ? duration[j] : longest;
    }
    const S unit_of_time = detail::sqrt(shortest) * detail::sqrt(longest);
    for (std::size_t j = 0; j < segments; ++j) duration[j] = duration[j] / unit_of_time;
    velocity[0] = rise[0] / duration[0];
    velocity[segments] = rise[segments - 1] / duration[segments - 1];
    // Forward elimination over the inner keyframes 1 .. count - 2, then back substitution.
    for (std::size_t k = 1; k < segments; ++k) {
        const S hp = duration[k - 1], hs = duration[k];
        diagonal[k] = S(4) / hp + S(4) / hs;
        velocity[k] = rise[k - 1] * (S(6) / (hp * hp)) + rise[k] * (S(6) / (hs * hs));
        if (k == 1) velocity[k] -= velocity[0] * (S(2) / hp);
        else {
            const S factor = (S(2) / hp) / diagonal[k - 1];
            diagonal[k] -= factor * (S(2) / hp);
            velocity[k] -= velocity[k - 1] * factor;
        }
        if (k + 1 == segments) velocity[k] -= velocity[segments] * (S(2) / hs);
    }
    for (std::size_t k = segments - 1; k >= 1; --k) {
        if (k + 1 < segments) velocity[k] -= velocity[k + 1] * (S(2) / duration[k]);
        velocity[k] = velocity[k] / diagonal[k];
    }
    cubics.resize(segments);
    for (std::size_t j = 0; j < segments; ++j) {
        // Two keyframes: the straight line, whose higher terms would round to tiny values.
        const hermite_cubic<S> f = count == 2 ? hermite_cubic<S>{vec3<S>{}, vec3<S>{}, rise[j]}
                                              : hermite_cubic_of(rise[j], velocity[j] * duration[j],
                                                                 velocity[j + 1] * duration[j]);
        cubics[j] = {narrow<T>(f.a), narrow<T>(f.b), narrow<T>(f.c)};
    }
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_DETAIL_HERMITE_CUBIC_HPP_INCLUDED
