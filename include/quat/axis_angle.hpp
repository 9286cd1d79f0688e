// Rotations given as a unit axis and an angle.
#ifndef QUAT_AXIS_ANGLE_HPP_INCLUDED
#define QUAT_AXIS_ANGLE_HPP_INCLUDED

#include "vec3.hpp"

namespace quat {

/// Rotation by `angle` radians, counter-clockwise about the unit vector `axis` seen from its tip.
/// Conversions from it expect a unit axis; try_to_quaternion normalizes and checks untrusted input.
template <class T>
struct axis_angle {
    /// The unit axis and the angle in radians.
    /// @{
    vec3<T> axis;
    T angle;
    /// @}
};

}  // namespace quat

#endif  // QUAT_AXIS_ANGLE_HPP_INCLUDED
