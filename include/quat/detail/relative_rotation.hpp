// The relative rotation between two orientations, accurate when they are close: shared by
// kinematics.hpp (angular velocity), squad.hpp (control points), sclerp.hpp and
// rotation_spline.hpp, so that none of them includes another concept's header for it.
#ifndef QUAT_DETAIL_RELATIVE_ROTATION_HPP_INCLUDED
#define QUAT_DETAIL_RELATIVE_ROTATION_HPP_INCLUDED

#include "../quaternion.hpp"

namespace quat {
#include "isa_namespace.inc"
namespace detail {

/// The relative rotation q0* q1 (Body) or q1 q0* (not Body), with q1's sign taken nearer q0. Its
/// vector part comes from q1 - q0 in place of q1: q0* q0 = |q0|^2 is real, so the vector parts
/// agree exactly, but q1 - q0 is formed with one relative rounding per component, and the products
/// then round relative to the small result instead of leaving a difference of nearly equal
/// products (an absolute error of eps, a relative one of eps / angle, for q0 close to q1).
template <bool Body, class T>
[[nodiscard]] constexpr quaternion<T> relative_rotation(const quaternion<T>& q0,
                                                        const quaternion<T>& q1) noexcept {
    const quaternion<T> near = dot(q0, q1) < T(0) ? -q1 : q1;
    const quaternion<T> step = near - q0;
    const quaternion<T> v = Body ? conjugate(q0) * step : step * conjugate(q0);
    return {dot(q0, near), v.x, v.y, v.z};
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_DETAIL_RELATIVE_ROTATION_HPP_INCLUDED
