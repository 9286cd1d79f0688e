// The relative rotation between two orientations, accurate when they are close: shared by
// kinematics.hpp (angular velocity), paths/squad.hpp (control points), rigid/sclerp.hpp and
// paths/rotation_spline.hpp, so that none of them includes another concept's header for it. Written
// for any quaternion type with w, x, y, z and the quaternion operations (found by
// argument-dependent lookup), so that this foundation header knows no type of quat's.
#ifndef QUAT_DETAIL_RELATIVE_ROTATION_HPP_INCLUDED
#define QUAT_DETAIL_RELATIVE_ROTATION_HPP_INCLUDED

namespace quat {
#include "isa_namespace.inc"
namespace detail {

/// The relative rotation q0* q1 (Body) or q1 q0* (not Body), with q1's sign taken nearer q0. Its
/// vector part comes from q1 - q0 in place of q1: q0* q0 = |q0|^2 is real, so the vector parts
/// agree exactly, but q1 - q0 is formed with one relative rounding per component, and the products
/// then round relative to the small result instead of leaving a difference of nearly equal
/// products (an absolute error of eps, a relative one of eps / angle, for q0 close to q1).
template <bool Body, class Quaternion>
[[nodiscard]] constexpr Quaternion relative_rotation(const Quaternion& q0,
                                                     const Quaternion& q1) noexcept {
    using T = decltype(q0.w);
    const Quaternion near = dot(q0, q1) < T(0) ? -q1 : q1;
    const Quaternion step = near - q0;
    const Quaternion v = Body ? conjugate(q0) * step : step * conjugate(q0);
    return {dot(q0, near), v.x, v.y, v.z};
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_DETAIL_RELATIVE_ROTATION_HPP_INCLUDED
