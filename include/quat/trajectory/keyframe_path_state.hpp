// The state of a rigid body moving along a keyframe path at one time: its pose and the first two
// derivatives of its motion, each in the frame its name says.
#ifndef QUAT_TRAJECTORY_KEYFRAME_PATH_STATE_HPP_INCLUDED
#define QUAT_TRAJECTORY_KEYFRAME_PATH_STATE_HPP_INCLUDED

#include "../config.hpp"
#include "../detail/math.hpp"
#include "../quaternion.hpp"
#include "../rigid/dual_quaternion.hpp"
#include "../vec3.hpp"

namespace quat {
#include "../detail/isa_namespace.inc"

/// Pose, velocity and acceleration of a rigid body at one time. The pose maps body coordinates to
/// world coordinates (p_world = R p_body + t, t the body origin's position). "World" vectors are in
/// the fixed axes; "body" vectors are the same physical vectors in the body's own axes (R^T times
/// the world one). So body_velocity = R^T dt/dt and body_acceleration = R^T d2t/dt2 (what an ideal
/// accelerometer reads before gravity), which is not the rate of body_velocity: that is
/// body_acceleration - body_angular_velocity x body_velocity. (body_velocity, body_angular_velocity)
/// is the body twist, the rate of log(X(t0)^-1 X(t)) at t0. The angular acceleration is the same
/// vector in both frames: world_angular_acceleration = R body_angular_acceleration.
template <class T>
struct keyframe_path_state {
    dual_quaternion<T> pose;            ///< body to world, unit
    vec3<T> velocity;                   ///< world: d/dt of the position t
    vec3<T> acceleration;               ///< world: d2/dt2 of the position t
    vec3<T> angular_velocity;           ///< world axes: dR/dt = [angular_velocity]x R
    vec3<T> angular_acceleration;       ///< world axes: d/dt of angular_velocity
    vec3<T> body_velocity;              ///< body axes: R^T velocity
    vec3<T> body_acceleration;          ///< body axes: R^T acceleration
    vec3<T> body_angular_velocity;      ///< body axes: dR/dt = R [body_angular_velocity]x
    vec3<T> body_angular_acceleration;  ///< body axes: d/dt of body_angular_velocity
};

namespace detail {

/// The state with NaN in every component: the value of a path without keyframes.
template <class T>
[[nodiscard]] constexpr keyframe_path_state<T> nan_keyframe_path_state() noexcept {
    const T nan = quiet_nan<T>();
    const quaternion<T> q{nan, nan, nan, nan};
    const vec3<T> v{nan, nan, nan};
    return {{q, q}, v, v, v, v, v, v, v, v};
}

/// The state of rotation `rotation` at `position`, from the world-frame linear motion and the
/// body-frame angular motion (the form both keyframe paths compute them in).
template <class T>
[[nodiscard]] constexpr keyframe_path_state<T> make_keyframe_path_state(
    const quaternion<T>& rotation, const vec3<T>& position, const vec3<T>& velocity,
    const vec3<T>& acceleration, const vec3<T>& body_angular_velocity,
    const vec3<T>& body_angular_acceleration) noexcept {
    const quaternion<T> inverse = conjugate(rotation);
    return {to_dual_quaternion(rotation, position),
            velocity,
            acceleration,
            rotate_unchecked(rotation, body_angular_velocity),
            rotate_unchecked(rotation, body_angular_acceleration),
            rotate_unchecked(inverse, velocity),
            rotate_unchecked(inverse, acceleration),
            body_angular_velocity,
            body_angular_acceleration};
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_KEYFRAME_PATH_STATE_HPP_INCLUDED
