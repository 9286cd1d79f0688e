// Angular velocity between two orientations, and integrating an angular velocity over a time step.
#ifndef QUAT_KINEMATICS_HPP_INCLUDED
#define QUAT_KINEMATICS_HPP_INCLUDED

#include "config.hpp"
#include "conversions.hpp"
#include "detail/math.hpp"
#include "detail/relative_rotation.hpp"
#include "quaternion.hpp"
#include "vec3.hpp"

namespace quat {

#include "detail/isa_namespace.inc"
/// Body-frame angular velocity (a gyroscope's reading, radians per unit of dt) that turns unit q0
/// into unit q1 in time dt at a constant rate: integrate_body(q0, omega, dt) == q1 as rotations,
/// along the shorter arc (q1 and -q1 give the same omega, |omega dt| <= pi). Relative error of a
/// few eps even for tiny turns (|omega dt| = 1e-12). Preconditions: unit q0 and q1 (debug-checked)
/// and dt != 0; a negative dt gives the omega that satisfies the same relation, dt == 0 gives
/// infinite or NaN components, an infinite dt the limit 0, and any other NaN or infinite input NaN.
template <class T>
[[nodiscard]] constexpr vec3<T> body_angular_velocity(const quaternion<T>& q0,
                                                      const quaternion<T>& q1,
                                                      detail::type_identity_t<T> dt) noexcept {
    QUAT_ASSERT(detail::is_near_unit(q0) && detail::is_near_unit(q1),
                "quat::body_angular_velocity: q0 or q1 is not a unit quaternion");
    return to_rotation_vector(detail::relative_rotation<true>(q0, q1)) / dt;
}

/// World-frame (space-fixed axes) angular velocity that turns unit q0 into unit q1 in time dt:
/// integrate_world(q0, omega, dt) == q1 as rotations; equal to rotate(q0, body_angular_velocity).
/// Shorter arc, accuracy, preconditions and out-of-domain results as for body_angular_velocity.
template <class T>
[[nodiscard]] constexpr vec3<T> world_angular_velocity(const quaternion<T>& q0,
                                                       const quaternion<T>& q1,
                                                       detail::type_identity_t<T> dt) noexcept {
    QUAT_ASSERT(detail::is_near_unit(q0) && detail::is_near_unit(q1),
                "quat::world_angular_velocity: q0 or q1 is not a unit quaternion");
    return to_rotation_vector(detail::relative_rotation<false>(q0, q1)) / dt;
}

/// Orientation after turning unit q0 at the constant body-frame angular velocity omega (radians per
/// unit of dt, body axes) for dt: q0 * from_rotation_vector(omega * dt), exact for any |omega dt|.
/// Not renormalized: |q| drifts by a few eps per step, so renormalize a long chain of steps every
/// few dozen (see tests/test_drift.cpp). NaN or infinite input gives a non-finite result.
template <class T>
[[nodiscard]] constexpr quaternion<T> integrate_body(const quaternion<T>& q0, const vec3<T>& omega,
                                                     detail::type_identity_t<T> dt) noexcept {
    QUAT_ASSERT(detail::is_near_unit(q0), "quat::integrate_body: q0 is not a unit quaternion");
    return q0 * from_rotation_vector(omega * dt);
}

/// Orientation after turning unit q0 at the constant world-frame angular velocity omega for dt:
/// from_rotation_vector(omega * dt) * q0. Renormalization and bad input as for integrate_body.
template <class T>
[[nodiscard]] constexpr quaternion<T> integrate_world(const quaternion<T>& q0, const vec3<T>& omega,
                                                      detail::type_identity_t<T> dt) noexcept {
    QUAT_ASSERT(detail::is_near_unit(q0), "quat::integrate_world: q0 is not a unit quaternion");
    return from_rotation_vector(omega * dt) * q0;
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_KINEMATICS_HPP_INCLUDED
