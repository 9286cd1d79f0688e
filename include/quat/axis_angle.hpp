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

    /// Members left uninitialized, as in a plain struct; axis_angle<T>{} is all zero.
    axis_angle() = default;
    /// The rotation by angle_value radians about unit_axis.
    [[gnu::always_inline]] constexpr axis_angle(const vec3<T>& unit_axis, T angle_value) noexcept
        : axis(unit_axis), angle(angle_value) {}
    /// Conversion from another precision: axis_angle<double>{af}.
    template <class U>
    [[gnu::always_inline]] constexpr explicit axis_angle(const axis_angle<U>& rotation) noexcept
        : axis(rotation.axis), angle(static_cast<T>(rotation.angle)) {}
};

}  // namespace quat

#endif  // QUAT_AXIS_ANGLE_HPP_INCLUDED
