// A segment's cubic in the segment's own time u in [0, 1], f(u) = ((a u + b) u + c) u, and bounds
// on it and its derivatives: the form rotation_spline keeps its rotation vectors in and the
// keyframe paths of trajectory/ their positions and twists.
#ifndef QUAT_PATHS_DETAIL_SEGMENT_CUBIC_HPP_INCLUDED
#define QUAT_PATHS_DETAIL_SEGMENT_CUBIC_HPP_INCLUDED

#include "../../detail/math.hpp"
#include "../../vec3.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

/// f(u) = ((a u + b) u + c) u for u in [0, 1]: f(0) = 0. Coefficients in the value's own unit
/// (length, angle), whatever the unit of time.
template <class T>
struct hermite_cubic {
    vec3<T> a, b, c;
};

/// |x| + |y| + |z|.
template <class T>
[[nodiscard]] constexpr T sum_of_magnitudes(const vec3<T>& v) noexcept {
    return detail::abs(v.x) + detail::abs(v.y) + detail::abs(v.z);
}

/// A bound on |f|, |df/dt| and |d2f/dt2| over the segment (u in [0, 1]), or infinity where one
/// overflows: angle (or length), rate and second.
template <class T>
struct cubic_bounds {
    T value, rate, second;
};

/// The bounds of f over a segment lasting `duration`; divided by the duration twice rather than by
/// its square, which over- or underflows first.
template <class T>
[[nodiscard]] constexpr cubic_bounds<T> cubic_bounds_of(const hermite_cubic<T>& f,
                                                        T duration) noexcept {
    const T a = sum_of_magnitudes(f.a), b = sum_of_magnitudes(f.b), c = sum_of_magnitudes(f.c);
    return {a + b + c, (T(3) * a + T(2) * b + c) / duration,
            (T(6) * a + T(2) * b) / duration / duration};
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_PATHS_DETAIL_SEGMENT_CUBIC_HPP_INCLUDED
