// Continuous Euler angles: the angles of a rotation nearest to the previous frame's angles, so a
// smooth motion gives smooth angles through +-pi and through gimbal lock.
#ifndef QUAT_CONTINUOUS_EULER_HPP_INCLUDED
#define QUAT_CONTINUOUS_EULER_HPP_INCLUDED

#include <limits>

#include "detail/math.hpp"
#include "euler.hpp"
#include "quaternion.hpp"

namespace quat {

#include "detail/isa_namespace.inc"
namespace detail {

// The angle equal to x modulo 2 pi that is nearest to `near`: near + (x - near) wrapped into
// [-pi, pi] by atan2 of its sine and cosine, which needs no rounding to an integer count of turns
// (and so works for any scalar and any magnitude); NaN or infinite input gives NaN.
template <class T>
[[nodiscard]] constexpr T nearest_equivalent_angle(T x, T near) noexcept {
    const T difference = x - near;
    return near + detail::atan2(detail::sin(difference), detail::cos(difference));
}

template <class T, sequence S, frame F>
[[nodiscard]] constexpr euler<T, S, F> unwrapped_near(const euler<T, S, F>& e,
                                                      const euler<T, S, F>& previous) noexcept {
    return {nearest_equivalent_angle(e[0], previous[0]),
            nearest_equivalent_angle(e[1], previous[1]),
            nearest_equivalent_angle(e[2], previous[2])};
}

template <class T, sequence S, frame F>
[[nodiscard]] constexpr T squared_distance(const euler<T, S, F>& a,
                                           const euler<T, S, F>& b) noexcept {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
           (a[2] - b[2]) * (a[2] - b[2]);
}

}  // namespace detail

/// Euler angles of the unit quaternion q (convention S, F) nearest to `previous`, for tracking a
/// motion frame by frame without jumps: feed each call the previous call's result. Of the two
/// triples of every rotation ((a, b, c) and (a + pi, pi - b, c + pi) for Tait–Bryan sequences, (a +
/// pi, -b, c + pi) for proper Euler ones), each angle moved by whole turns to lie within pi of its
/// previous value, the one nearer `previous` (sum of squared differences) is returned; angles are
/// not limited to [-pi, pi], the middle one included. At or near gimbal lock, where q fixes only a
/// + c or a - c, the third angle keeps its previous value and the first takes the rest: where
/// extract_euler reports gimbal_lock (q does not determine the split beyond rounding, and the plain
/// extraction's third angle of 0 is as arbitrary), and wherever else that changes the rotation by
/// at most 2 epsilon (|middle-angle distance to the lock| times the change of the third angle). So
/// the free angle never jumps, and the result represents q within 10 epsilon at the lock.
/// Precondition: unit q, or any non-zero scale of it. NaN or infinite q gives NaN; a NaN or
/// infinite angle of previous gives NaN in that angle.
template <sequence S, frame F, class T>
[[nodiscard]] constexpr euler<T, S, F> to_euler(const quaternion<T>& q,
                                                const euler<T, S, F>& previous) noexcept {
    constexpr detail::axis_triple axes = detail::axes_of(S);
    constexpr bool proper = axes.first == axes.third;
    const T half_turn = detail::pi<T>();
    const euler_extraction<T, S, F> extraction = extract_euler<S, F>(q);
    const euler<T, S, F>& e = extraction.angles;
    const euler<T, S, F> mirror{e[0] + half_turn, proper ? -e[1] : half_turn - e[1],
                                e[2] + half_turn};
    const euler<T, S, F> first = detail::unwrapped_near(e, previous);
    const euler<T, S, F> second = detail::unwrapped_near(mirror, previous);
    euler<T, S, F> best =
        detail::squared_distance(second, previous) < detail::squared_distance(first, previous)
            ? second
            : first;

    // Distance of the middle angle from its lock (pi/2 modulo pi for Tait–Bryan, 0 modulo pi for
    // proper), as the sine of that distance.
    const T from_lock = detail::abs(proper ? detail::sin(best[1]) : detail::cos(best[1]));
    const T third_change = previous[2] - best[2];  // within pi after unwrapping
    if (extraction.gimbal_lock ||
        from_lock * detail::abs(third_change) <= T(2) * detail::epsilon<T>()) {
        // At the lock R depends on a + sign c only. Intrinsic R_i(a) R_j(b) R_k(c): R_j(b) turns
        // e_k into sin(b) parity e_i (Tait–Bryan) or cos(b) e_i (proper, k = i), so sign is the
        // sign of that factor; extrinsic R_k(c) R_j(b) R_i(a) puts R_j(b)^T e_k there instead,
        // which flips the Tait–Bryan sign.
        const T parity = (axes.second - axes.first + 3) % 3 == 1 ? T(1) : T(-1);
        const T factor = proper ? detail::cos(best[1])
                                : (F == frame::intrinsic ? parity : -parity) * detail::sin(best[1]);
        const T sign = factor < T(0) ? T(-1) : T(1);
        best[0] =
            detail::nearest_equivalent_angle(best[0] + sign * (best[2] - previous[2]), previous[0]);
        best[2] = previous[2];
    }
    return best;
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_CONTINUOUS_EULER_HPP_INCLUDED
