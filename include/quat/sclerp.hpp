// Screw linear interpolation (ScLERP) between rigid motions: the constant-velocity screw motion,
// the rigid-motion counterpart of slerp.
#ifndef QUAT_SCLERP_HPP_INCLUDED
#define QUAT_SCLERP_HPP_INCLUDED

#include <limits>

#include "config.hpp"
#include "detail/math.hpp"
#include "detail/relative_rotation.hpp"
#include "dual_quaternion.hpp"
#include "quaternion.hpp"
#include "vec3.hpp"

namespace quat {

#include "detail/isa_namespace.inc"
/// Screw linear interpolation from unit a (t = 0) to unit b (t = 1): a (a^-1 b)^t, the motion at
/// constant screw velocity, so the angle about the screw axis and the slide along it grow linearly
/// in t; equal to the matrix form a exp(t log(a^-1 b)) of the 4x4 transforms. Takes the shorter
/// path (relative angle in [0, pi], as slerp does); t outside [0, 1] extrapolates along the same
/// screw. Returns a at t = 0 and b, or -b when -b is nearer a, at t = 1, exactly. Stable for equal
/// and nearly equal rotations (a pure or nearly pure translation) and near half turns: no division
/// by the sine of a small angle. Precondition: unit a and b (debug-checked real parts); NaN or
/// infinite input gives a non-finite result.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> sclerp(const dual_quaternion<T>& a,
                                                  const dual_quaternion<T>& b,
                                                  detail::type_identity_t<T> t) noexcept {
    QUAT_ASSERT(detail::is_near_unit(a.real) && detail::is_near_unit(b.real),
                "quat::sclerp: a or b is not a unit dual quaternion");
    const dual_quaternion<T> near = dot(a.real, b.real) < T(0) ? -b : b;
    // Exact ends; adding x - x (zero when finite, NaN otherwise) keeps a bad other end visible.
    if (t == T(0)) return {a.real + (near.real - near.real), a.dual + (near.dual - near.dual)};
    if (t == T(1)) return {near.real + (a.real - a.real), near.dual + (a.dual - a.dual)};

    // The relative motion a^-1 near: rotation r (w >= 0, formed accurately for nearly equal
    // rotations) and translation u, both in a's frame.
    const quaternion<T> r = detail::relative_rotation<true>(a.real, near.real);
    const vec3<T> u = rotate(conjugate(a.real), translation_of(near) - translation_of(a));
    const vec3<T> v{r.x, r.y, r.z};
    const T s = norm(v), n = norm(r);
    const T h = detail::atan2(s, r.w);  // half the relative angle, in [0, pi/2]
    const T sine = detail::sin(t * h), cosine = detail::cos(t * h);
    // ratio = sin(t h) / sin(h), with its series where sin(h) is tiny or zero (the next term,
    // t (1 - t^2)(7 - 3 t^2) h^4 / 360, is below eps there for t in [0, 1]).
    const T ratio =
        h * h < detail::epsilon<T>() ? t + t * (T(1) - t * t) * (h * h) / T(6) : sine * n / s;
    // The screw moves u to (A I + B [l]x + (t - A) l l^T) u, l the axis, with A + i B =
    // sin(t h) / sin(h) e^{i (t - 1) h}: the ratio (1 - e^{i t 2h}) / (1 - e^{i 2h}) by which
    // (I - R) scales the plane across the axis, while the slide along l is t times u's. B and
    // t - A vanish with h, so the axis direction, inaccurate for tiny h, never matters.
    const T ch = r.w / n, sh = s / n;
    const T across_cos = ratio * (cosine * ch + sine * sh);  // A
    const T across_sin = ratio * (sine * ch - cosine * sh);  // B
    const vec3<T> l = s > T(0) ? v / s : vec3<T>{T(0), T(0), T(0)};
    const vec3<T> moved =
        u * across_cos + cross(l, u) * across_sin + l * ((t - across_cos) * dot(l, u));
    const vec3<T> turn = l * sine;
    return a * to_dual_quaternion(quaternion<T>{cosine, turn.x, turn.y, turn.z}, moved);
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_SCLERP_HPP_INCLUDED
