// Screw parameters of rigid motions: every rigid motion turns about one axis line and slides along
// it (Chasles' theorem). The form sclerp interpolates in, and the one to read a motion in.
#ifndef QUAT_RIGID_SCREW_HPP_INCLUDED
#define QUAT_RIGID_SCREW_HPP_INCLUDED

#include "../config.hpp"
#include "../detail/math.hpp"
#include "../detail/power_of_two.hpp"
#include "../quaternion.hpp"
#include "../vec3.hpp"
#include "dual_quaternion.hpp"

namespace quat {

/// A screw motion: a turn by `angle` radians (counter-clockwise about `direction`) about the line
/// with unit `direction` and `moment` = p x direction for any point p on it, together with a slide
/// of `displacement` along `direction`. The line's point nearest the origin is direction x moment.
template <class T>
struct screw {
    vec3<T> direction;  ///< Unit direction of the axis line.
    vec3<T> moment;  ///< p x direction for a point p on the line; zero when it passes the origin.
    T angle;         ///< Turn about the line, radians.
    T displacement;  ///< Slide along direction.
};

#include "../detail/isa_namespace.inc"
/// The screw of the unit dual quaternion dq, with angle in [0, pi] (dq and -dq give the same
/// screw). A pure translation t gives angle 0, direction t / |t|, moment 0 and displacement |t|;
/// the identity gives direction (1, 0, 0) and the rest 0. A nearly pure translation has a large
/// moment: its axis lies far away, and where that is beyond max() (a slide across the axis of more
/// than about max() times half the angle, as for a subnormal angle) the moment is infinite; a
/// slide along the axis gives a zero moment at any angle. Precondition: unit dq; a NaN or infinite
/// component gives NaN in the result.
template <class T>
[[nodiscard]] constexpr screw<T> to_screw(const dual_quaternion<T>& dq) noexcept {
    const dual_quaternion<T> near = dq.real.w < T(0) ? -dq : dq;
    const vec3<T> t = translation_of(near);
    const vec3<T> v{near.real.x, near.real.y, near.real.z};
    const T s = norm(v);
    if (s == T(0)) {
        const T length = norm(t);
        const vec3<T> direction = length > T(0) ? t / length : vec3<T>{T(1), T(0), T(0)};
        return {direction, vec3<T>{T(0), T(0), T(0)}, T(0), length};
    }
    const vec3<T> l = normalize(v);  // not v / s, which is not unit when v is subnormal
    const T displacement = dot(t, l);
    // The part of t across the axis is (I - R) p for the axis point p nearest the origin; with h
    // half the angle, p = (across + cot(h) l x t) / 2 solves it, and p x l is the moment below.
    // across w / s, not across (w / s): w / s overflows for a tiny angle even where across is 0.
    // across = l x (t x l), from t x v with v and t scaled by powers of two (exact, so v still
    // lies along the axis) and compensated products: it is exactly zero for a t along v, where
    // t - l (t . l) keeps |t| eps from the rounding of l, which cot(h) turns into an infinite
    // moment when the angle is subnormal.
    const vec3<T> axis = detail::scaled_by_power_of_two(v);
    const T size = detail::binade_or_one(detail::largest_magnitude(t));
    const vec3<T> t_cross_axis = detail::accurate_cross(t / size, axis);  // (t x v) / |v| / size
    const T axis_squared = squared_norm(axis);
    const vec3<T> across = cross(axis, t_cross_axis) * (size / axis_squared);
    const vec3<T> moment =
        (t_cross_axis * (size / detail::sqrt(axis_squared)) + across * near.real.w / s) * T(0.5);
    return {l, moment, T(2) * detail::atan2(s, near.real.w), displacement};
}

/// The unit dual quaternion of the screw motion s: real part (cos(h), sin(h) direction) and dual
/// part (-d sin(h), sin(h) moment + d cos(h) direction) with h = angle / 2 and d = displacement /
/// 2. from_screw(to_screw(dq)) is dq, or -dq when dq.real.w < 0 (the same motion). Precondition:
/// unit direction, and moment orthogonal to it.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> from_screw(const screw<T>& s) noexcept {
    const T h = s.angle * T(0.5), d = s.displacement * T(0.5);
    const T c = detail::cos(h), sn = detail::sin(h);
    const vec3<T> real = s.direction * sn;
    const vec3<T> dual = s.moment * sn + s.direction * (d * c);
    return {quaternion<T>{c, real.x, real.y, real.z},
            quaternion<T>{-d * sn, dual.x, dual.y, dual.z}};
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_RIGID_SCREW_HPP_INCLUDED
