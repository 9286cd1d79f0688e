// Screw linear interpolation (ScLERP) between rigid motions: the constant-velocity screw motion,
// the rigid-motion counterpart of slerp.
#ifndef QUAT_RIGID_SCLERP_HPP_INCLUDED
#define QUAT_RIGID_SCLERP_HPP_INCLUDED

#include <limits>
#include <type_traits>

#include "../config.hpp"
#include "../detail/math.hpp"
#include "../detail/relative_rotation.hpp"
#include "../quaternion.hpp"
#include "../vec3.hpp"
#include "dual_quaternion.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
/// Screw linear interpolation from unit a (t = 0) to unit b (t = 1): a (a^-1 b)^t, the motion at
/// constant screw velocity, so the angle about the screw axis and the slide along it grow linearly
/// in t; equal to the matrix form a exp(t log(a^-1 b)) of the 4x4 transforms. Takes the shorter
/// path (relative angle in [0, pi], as slerp does); t outside [0, 1] extrapolates along the same
/// screw. Returns a at t = 0 and b, or -b when -b is nearer a, at t = 1, exactly (a user scalar,
/// which may carry derivatives, to rounding). Stable for equal and nearly equal rotations (a pure
/// or nearly pure translation) and near half turns: no division by the sine of a small angle.
/// Precondition: unit a and b (debug-checked real parts); NaN or infinite input gives a non-finite
/// result.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> sclerp(const dual_quaternion<T>& a,
                                                  const dual_quaternion<T>& b,
                                                  detail::type_identity_t<T> t) noexcept {
    QUAT_ASSERT(detail::is_near_unit(a.real) && detail::is_near_unit(b.real),
                "quat::sclerp: a or b is not a unit dual quaternion");
    const dual_quaternion<T> near = dot(a.real, b.real) < T(0) ? -b : b;
    // Exact ends; adding x - x (zero when finite, NaN otherwise) keeps a bad other end visible.
    // Not for a user scalar, whose t may carry a derivative that a constant would drop.
    if constexpr (std::is_floating_point_v<T>) {
        if (t == T(0)) return {a.real + (near.real - near.real), a.dual + (near.dual - near.dual)};
        if (t == T(1)) return {near.real + (a.real - a.real), near.dual + (a.dual - a.dual)};
    }

    // The relative motion a^-1 near: rotation r (w >= 0, formed accurately for nearly equal
    // rotations) and translation u, both in a's frame.
    const quaternion<T> r = detail::relative_rotation<true>(a.real, near.real);
    const vec3<T> u = rotate(conjugate(a.real), translation_of(near) - translation_of(a));
    const vec3<T> v{r.x, r.y, r.z};
    const T s2 = squared_norm(v), s = norm(v);
    // Everything below is written with v and |v|^2, never the axis v / |v|, and with series
    // where h, half the relative angle, is small (|v| is read only where it is not): accurate for
    // tiny h (a pure or nearly pure translation), and a dual-number scalar gets finite derivatives
    // at h = 0. hs = h / |v|, by atan's series near h = 0 (w = 0, a half turn, is left to atan2,
    // also in constant evaluation, where 1 / 0 is an error).
    T hs{}, cosine{}, sine_over_s{};  // h / |v|, cos(t h), sin(t h) / |v|
    T inverse2{};                     // 1 / |v|^2 where h is not small, else 0
    if (detail::atan_series_suffices(s2, r.w)) {
        hs = detail::atan_ratio_series(s2 / (r.w * r.w)) / r.w;
        const detail::cos_and_sinc<T> turn_t = detail::cos_sinc(t * t * hs * hs * s2, t * hs * s);
        cosine = turn_t.cos;
        sine_over_s = t * hs * turn_t.sinc;
    } else {
        const T h = detail::atan2(s, r.w), inverse = T(1) / s;
        hs = h * inverse;
        cosine = detail::cos(t * h);
        sine_over_s = detail::sin(t * h) * inverse;
        inverse2 = inverse * inverse;
    }
    const T h2 = hs * hs * s2;
    // The screw moves u to (A I + B [l]x + (t - A) l l^T) u, l the axis, with A + i B =
    // sin(t h) / sin(h) e^{i (t - 1) h}: the ratio (1 - e^{i t 2h}) / (1 - e^{i 2h}) by which
    // (I - R) scales the plane across the axis, while the slide along l is t times u's. With
    // l = v / |v|, sin(h) = |v| / |r| and cos(h) = w / |r|: A = (sin(t h) / |v|)(cos(t h) w +
    // sin(t h) |v|), B l = (B / |v|) v and (t - A) l l^T = ((t - A) / |v|^2) v v^T.
    const T across_cos = sine_over_s * (cosine * r.w + sine_over_s * s2);    // A
    const T across_sin_over_s = sine_over_s * (sine_over_s * r.w - cosine);  // B / |v|
    // (t - A) / |v|^2 = m D |r| hs^3 / 2, m = 2t - 1, D = (sinc(h) - sinc(m h)) / h^2, which
    // cancels in closed form for small h: its series while the first omitted term,
    // h^6 (m^8 - 1) / 362880, is below epsilon relative to D (at most g^6 / 15120 of it).
    const T m = t + t - T(1), m2 = m * m;
    const T g2 = h2 * detail::max(T(1), m2);
    T slide{};
    if (g2 * g2 * g2 < T(15120) * detail::epsilon<T>()) {
        const T d = (m2 - T(1)) / T(6) - h2 * (m2 * m2 - T(1)) / T(120) +
                    h2 * h2 * (m2 * m2 * m2 - T(1)) / T(5040);
        slide = m * d * norm(r) * hs * hs * hs / T(2);
    } else {
        // (The division only where h is tiny but |t| beyond about 50.)
        slide = (t - across_cos) * (inverse2 > T(0) ? inverse2 : T(1) / s2);
    }
    const vec3<T> moved =
        u * across_cos + cross(v, u) * across_sin_over_s + v * (dot(v, u) * slide);
    const vec3<T> turn = v * sine_over_s;
    return a * to_dual_quaternion(quaternion<T>{cosine, turn.x, turn.y, turn.z}, moved);
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_RIGID_SCLERP_HPP_INCLUDED
