// Interpolation between rotations: slerp (constant angular velocity), nlerp (cheap, normalized),
// pow (a fraction or multiple of one rotation) and rotate_towards (a step of bounded angle); and the
// quaternion exponential and logarithm that pow(q, t) = exp(t log q) is built on in textbooks.
#ifndef QUAT_INTERPOLATION_HPP_INCLUDED
#define QUAT_INTERPOLATION_HPP_INCLUDED

#include <type_traits>

#include "config.hpp"
#include "detail/exp_log.hpp"
#include "detail/math.hpp"
#include "quaternion.hpp"
#include "vec3.hpp"

namespace quat {

#include "detail/isa_namespace.inc"
namespace detail {

/// The principal power p^t of a unit p with p.w >= 0 (or any w for p off the identity): turns by
/// t times p's angle about p's axis. Near the identity half the new angle is k |u| with k = t
/// atan(r) / (r w), r = |u| / w, from series in |u|^2, so that no square root of zero sits on the
/// path a dual-number scalar differentiates; elsewhere the closed form.
template <class T>
[[nodiscard]] constexpr quaternion<T> power_of_unit(const quaternion<T>& p, T t) noexcept {
    const vec3<T> u{p.x, p.y, p.z};
    const T s2 = squared_norm(u);
    if (atan_series_suffices(s2, p.w)) {
        const T k = t * atan_ratio_series(s2 / (p.w * p.w)) / p.w;  // half the new angle over |u|
        const cos_and_sinc<T> half = cos_sinc(k * k * s2, k * norm(u));
        const vec3<T> v = u * (k * half.sinc);
        return {half.cos, v.x, v.y, v.z};
    }
    const T s = norm(u);
    const T half = t * atan2(s, p.w);
    const vec3<T> v = u / s * sin(half);
    return {cos(half), v.x, v.y, v.z};
}

}  // namespace detail

/// Spherical linear interpolation from unit a (t = 0) to unit b (t = 1) along the shorter arc, at
/// constant angular velocity; t outside [0, 1] extrapolates along the same great circle. Returns
/// a at t = 0 and b, or -b when -b is nearer a, at t = 1, exactly (a user scalar, which may carry
/// derivatives, to rounding). The angle comes from the chord |a - b|, accurate for nearly equal
/// and nearly opposite inputs. Precondition: unit a and b (checked in debug builds). A NaN or
/// infinite a, b or t gives a non-finite result.
template <class T>
[[nodiscard]] constexpr quaternion<T> slerp(const quaternion<T>& a, const quaternion<T>& b,
                                            detail::type_identity_t<T> t) noexcept {
    QUAT_ASSERT(detail::is_near_unit(a) && detail::is_near_unit(b),
                "quat::slerp: a or b is not a unit quaternion");
    const quaternion<T> near = dot(a, b) < T(0) ? -b : b;
    // Exact ends; adding x - x (zero when finite, NaN otherwise) keeps a NaN or infinite other end
    // visible instead of returning a clean-looking value. Not for a user scalar, whose t may carry
    // a derivative that a constant would drop: the formulas below give the ends to rounding.
    if constexpr (std::is_floating_point_v<T>) {
        if (t == T(0)) return a + (near - near);
        if (t == T(1)) return near + (a - a);
    }
    if (t < T(0) || t > T(1)) {
        // Beyond the ends the two weights below grow and cancel; turning a by t times the relative
        // rotation a* near, whose w = dot(a, near) >= 0, keeps the error at the level of one product.
        const quaternion<T> relative = conjugate(a) * near;
        if constexpr (std::is_floating_point_v<T>) {
            // No motion; a bad t stays visible.
            if (relative.x == T(0) && relative.y == T(0) && relative.z == T(0))
                return detail::is_finite(t) ? a : a * t;
        }
        return a * detail::power_of_unit(relative, t);
    }
    // With h half the angle between a and near (h <= pi/4 since dot(a, near) >= 0), the slerp
    // path is cos(u) e + sin(u) f, u = (2t - 1) h, where e and f are the orthonormal directions
    // of a + near and near - a (|a + near| = 2 cos h, |near - a| = 2 sin h): one sine-cosine pair
    // instead of three sines, and each direction divided by the norm it actually has, so the
    // result is unit to a few roundings whatever the rounding of h. The chord |near - a| keeps h
    // accurate for nearly equal inputs, unlike acos of the dot product.
    const quaternion<T> sum = a + near;
    const quaternion<T> difference = near - a;
    const T chord2 = squared_norm(difference);
    const T chord = detail::sqrt(chord2);  // read only past the series below
    // a == near: nothing to interpolate, but a non-finite t stays visible (other NaN goes on
    // below). A user scalar takes the series below, which keeps the derivatives in b and t.
    if constexpr (std::is_floating_point_v<T>) {
        if (chord == T(0)) return detail::is_finite(t) ? a : a * t;
    }
    const T sine2 = chord2 * T(0.25);  // sin^2 h
    if (detail::series_suffices(sine2)) {
        // u = (2t - 1) h = ratio sin h, and sin(u) / chord = sinc(u) ratio / 2, from series in
        // sin^2 h: no square root of zero on the path a dual-number scalar differentiates.
        const T ratio = (t + t - T(1)) * detail::asin_ratio_series(sine2);
        const detail::cos_and_sinc<T> cs =
            detail::cos_sinc(ratio * ratio * sine2, ratio * chord * T(0.5));
        return sum * (cs.cos / detail::sqrt(squared_norm(sum))) +
               difference * (cs.sinc * ratio * T(0.5));
    }
    const T u = (t + t - T(1)) * detail::asin(chord * T(0.5));
    return sum * (detail::cos(u) / detail::sqrt(squared_norm(sum))) +
           difference * (detail::sin(u) / chord);
}

/// Normalized linear interpolation along the shorter arc: the slerp path at non-uniform speed,
/// cheaper. Precondition: unit a and b; the sign flip keeps the sum non-zero for t in [0, 1].
template <class T>
[[nodiscard]] constexpr quaternion<T> nlerp(const quaternion<T>& a, const quaternion<T>& b,
                                            detail::type_identity_t<T> t) noexcept {
    const quaternion<T> near = dot(a, b) < T(0) ? -b : b;
    return normalize(a + (near - a) * t);
}

/// Principal power of the unit quaternion q: the rotation about q's axis by t times q's angle, the
/// angle taken in [0, pi] (the shorter arc, so q and -q give the same result), equal to
/// slerp(identity, q, t). pow(q, 0) is the identity and pow(q, 1) is q or -q (w >= 0), exactly (a
/// user scalar, which may carry derivatives, to rounding). The half angle comes from
/// atan2(|v|, w), accurate near the identity and near a half turn. Precondition: unit q (checked
/// in debug builds). A NaN or infinite q or t gives a non-finite result. glm::pow differs for
/// w < 0: it keeps q's sign and so takes the longer arc.
template <class T>
[[nodiscard]] constexpr quaternion<T> pow(const quaternion<T>& q,
                                          detail::type_identity_t<T> t) noexcept {
    QUAT_ASSERT(detail::is_near_unit(q), "quat::pow: q is not a unit quaternion");
    const quaternion<T> p = q.w < T(0) ? -q : q;
    // Exact shortcuts; not for a user scalar, whose q and t may carry derivatives that a constant
    // would drop (power_of_unit gives the same values to rounding).
    if constexpr (std::is_floating_point_v<T>) {
        if (t == T(1)) return p;
        const quaternion<T> identity = quaternion<T>::identity();
        // (p - p) is zero when p is finite and NaN otherwise, so a bad q stays visible.
        if (t == T(0)) return identity + (p - p);
        // (The identity needs no shortcut: power_of_unit's series gives it exactly.)
    }
    // + (p - p): an infinite w makes atan2 return 0, which would give a clean-looking identity.
    return detail::power_of_unit(p, t) + (p - p);
}

/// The quaternion exponential of q = (w, v): e^w (cos|v|, sin|v| v / |v|), for any q (not only
/// unit or pure ones). For a unit result, w = 0: exp((0, r / 2)) is from_rotation_vector(r), the
/// rotation by |r| about r, to within a few eps. Accurate from v = 0 (a series for sin|v| / |v|, no
/// 0/0; exp((w, 0)) is (e^w, v) exactly, signed zeros kept, for float, double and long double) to huge or subnormal |v| (measured as
/// norm does, scaled); e^w overflows to Inf past w = ln max(). NaN in gives NaN out. glm::exp
/// ignores w and returns the identity for |v| < epsilon.
template <class T>
[[nodiscard]] constexpr quaternion<T> exp(const quaternion<T>& q) noexcept {
    const vec3<T> v{q.x, q.y, q.z};
    const T e = detail::scalar_exp(q.w);
    if constexpr (std::is_floating_point_v<T>) {
        // Exactly real: v itself, signed zeros kept and no 0 * Inf where e^w overflows. (A user
        // scalar's v may carry derivatives, which e^w scales: it takes the series below.)
        if (q.x == T(0) && q.y == T(0) && q.z == T(0)) return {e, q.x, q.y, q.z};
    }
    // cos|v| and sin|v| / |v|, by series in |v|^2 for small |v| (no square root of zero there).
    const detail::cos_and_sinc<T> cs = detail::cos_sinc(squared_norm(v), norm(v));
    const vec3<T> u = v * (cs.sinc * e);
    return {cs.cos * e, u.x, u.y, u.z};
}

/// The principal quaternion logarithm of q = (w, v): (ln|q|, v / |v| atan2(|v|, w)), the vector
/// part's length in [0, pi], so exp(log(q)) == q. For a unit q with w >= 0, log(q) is
/// (0, to_rotation_vector(q) / 2) to within a few eps; for w < 0 its vector part is half the
/// rotation vector of the longer way round (length above pi / 2), as q and -q differ here. Real q:
/// (ln w, 0, 0, 0) for w > 0 (v's signed zeros kept), (ln|w|, pi, 0, 0) for w < 0 (the axis
/// (1, 0, 0), as to_axis_angle and glm::log choose), (-Inf, 0, 0, 0) for zero. Accurate for tiny
/// |v| (no 0/0) and for components from subnormal to max() (|q| and |v| scaled as norm does);
/// NaN or infinite components give NaN in every component.
template <class T>
[[nodiscard]] constexpr quaternion<T> log(const quaternion<T>& q) noexcept {
    const T s2 = squared_norm(q);
    T log_norm{};
    if (detail::in_normal_range(s2)) {
        log_norm = T(0.5) * detail::scalar_log(s2);
    } else {
        // |q|^2 over- or underflowed: ln|q| = ln(scale) + ln|q / scale| with scale the largest
        // |component|, which brings |q / scale| into [1, 2].
        if (s2 != s2) return detail::nan_quaternion<T>();  // a NaN that largest_magnitude may skip
        const T scale = detail::largest_magnitude(q);
        if (!detail::is_finite(scale)) return detail::nan_quaternion<T>();
        if (scale == T(0)) return {-detail::infinity<T>(), q.x, q.y, q.z};
        log_norm = detail::scalar_log(scale) + T(0.5) * detail::scalar_log(squared_norm(q / scale));
    }
    const vec3<T> v{q.x, q.y, q.z};
    // Near the real axis v / |v| atan2(|v|, w) = (v / w) atan(r) / r with r = |v| / w, from
    // series in r^2: no square root of zero on the path a dual-number scalar differentiates.
    const T v2 = squared_norm(v);
    if (detail::atan_series_suffices(v2, q.w)) {
        const vec3<T> u = v / q.w * detail::atan_ratio_series(v2 / (q.w * q.w));
        return {log_norm, u.x, u.y, u.z};
    }
    const T length = norm(v);
    if (length == T(0)) {
        if (q.w < T(0)) return {log_norm, detail::pi<T>(), T(0), T(0)};
        return {log_norm, q.x, q.y, q.z};
    }
    const vec3<T> u = v / length * detail::atan2(length, q.w);
    return {log_norm, u.x, u.y, u.z};
}

/// The rotation at most max_angle radians from unit `from` on the shorter arc towards unit `to`,
/// never past it (Unity's Quaternion.RotateTowards): `to` itself, as given, when
/// angle_between(from, to) <= max_angle, else slerp(from, to, max_angle / angle_between(from, to)).
/// A negative max_angle counts as 0: the result is `from` (or `to` if they are the same rotation),
/// where Unity's turns away from `to`. A NaN in any input, or an infinite `from` or `to`, gives NaN;
/// an infinite max_angle gives `to`. Preconditions: unit from and to (checked in debug builds).
template <class T>
[[nodiscard]] constexpr quaternion<T> rotate_towards(
    const quaternion<T>& from, const quaternion<T>& to,
    detail::type_identity_t<T> max_angle) noexcept {
    QUAT_ASSERT(detail::is_near_unit(from) && detail::is_near_unit(to),
                "quat::rotate_towards: from or to is not a unit quaternion");
    const T angle = angle_between(from, to);  // NaN for non-finite from or to
    const T step = max_angle < T(0) ? T(0) : max_angle;
    if (angle <= step) return to;
    return slerp(from, to, step / angle);  // step / angle is in [0, 1), or NaN
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_INTERPOLATION_HPP_INCLUDED
