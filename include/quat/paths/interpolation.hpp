// Interpolation between rotations: slerp (constant angular velocity), nlerp (cheap, normalized),
// pow (a fraction or multiple of one rotation) and rotate_towards (a step of bounded angle); and
// the quaternion exponential and logarithm that pow(q, t) = exp(t log q) is built on in textbooks.
#ifndef QUAT_PATHS_INTERPOLATION_HPP_INCLUDED
#define QUAT_PATHS_INTERPOLATION_HPP_INCLUDED

#include <type_traits>

#include "../config.hpp"
#include "../detail/exp_log.hpp"
#include "../detail/math.hpp"
#include "../quaternion.hpp"
#include "../vec3.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
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

/// The Taylor coefficients of asin(x) / x = sum_k c_k x^2k, c_k = (2k)! / (4^k k!^2 (2k + 1)),
/// k = 0 ... 20, by the ratio c_{k+1} / c_k = (2k + 1)^2 / ((2k + 2)(2k + 3)).
struct asin_ratio_coefficients {
    double c[21];
};
[[nodiscard]] constexpr asin_ratio_coefficients make_asin_ratio_coefficients() noexcept {
    asin_ratio_coefficients r{};
    r.c[0] = 1;
    for (int k = 0; k < 20; ++k)
        r.c[k + 1] = r.c[k] * double((2 * k + 1) * (2 * k + 1)) / double((2 * k + 2) * (2 * k + 3));
    return r;
}

/// asin(x) / x for y = x^2 <= 1/2 (|x| <= sin(pi/4)) to a relative 2.3e-9 (the first omitted
/// term at y = 1/2; 0.04 float ulp), exact as y -> 0. The terms are summed in pairs of pairs
/// (Estrin's scheme): 5 multiply-adds deep, against 20 by Horner's rule.
[[nodiscard]] constexpr double asin_ratio_double(double y) noexcept {
    constexpr asin_ratio_coefficients k = make_asin_ratio_coefficients();
    const double y2 = y * y, y4 = y2 * y2, y8 = y4 * y4, y16 = y8 * y8;
    const double p0 = k.c[0] + k.c[1] * y, p1 = k.c[2] + k.c[3] * y, p2 = k.c[4] + k.c[5] * y,
                 p3 = k.c[6] + k.c[7] * y, p4 = k.c[8] + k.c[9] * y, p5 = k.c[10] + k.c[11] * y,
                 p6 = k.c[12] + k.c[13] * y, p7 = k.c[14] + k.c[15] * y, p8 = k.c[16] + k.c[17] * y,
                 p9 = k.c[18] + k.c[19] * y;
    const double q0 = p0 + p1 * y2, q1 = p2 + p3 * y2, q2 = p4 + p5 * y2, q3 = p6 + p7 * y2,
                 q4 = p8 + p9 * y2;
    const double r0 = q0 + q1 * y4, r1 = q2 + q3 * y4, r2 = q4 + k.c[20] * y4;
    return (r0 + r1 * y8) + r2 * y16;
}

/// slerp's path for float a, near (dot(a, near) >= 0, a != near) and t in [0, 1], in double
/// arithmetic throughout: the path of slerp below, cos(u) e + sin(u) f with u = (2t - 1) h, each
/// direction divided by the norm it has, but h = asin(sin h), sin u and cos u by polynomials
/// instead of asinf and sincosf. Why: on a Zen 4 with AVX2, glibc's asinf (a division, and a
/// square root past 0.5) and sincosf, called one after the other behind the square root of the
/// chord, made one slerp a long chain of dependent operations, 0.9x GLM's speed. Here
/// the series of asin(x) / x starts from x^2 (the chord squared) while the square roots and the
/// one division run beside it, and the result is rounded to float once (float products are exact
/// in double, the sums and series err by about 1e-9 relative at most), within a unit in the last
/// place of the exact slerp of the given float inputs. h <= pi/4 (dot(a, near) >= 0), so
/// |x| = sin h <= sin(pi/4) and |u| <= pi/4: sin u to u^9 and cos u to u^10 leave 2e-9.
[[nodiscard]] constexpr quaternion<float> slerp_float(const quaternion<float>& a,
                                                      const quaternion<float>& near,
                                                      float t) noexcept {
    const double aw = static_cast<double>(a.w), ax = static_cast<double>(a.x),
                 ay = static_cast<double>(a.y), az = static_cast<double>(a.z);
    const double bw = static_cast<double>(near.w), bx = static_cast<double>(near.x),
                 by = static_cast<double>(near.y), bz = static_cast<double>(near.z);
    const double sw = aw + bw, sx = ax + bx, sy = ay + by, sz = az + bz;  // exact
    const double dw = bw - aw, dx = bx - ax, dy = by - ay, dz = bz - az;  // exact
    // Summed in pairs: two operations shorter than one after the other.
    const double sum2 = (sw * sw + sx * sx) + (sy * sy + sz * sz);    // 4 cos^2 h
    const double chord2 = (dw * dw + dx * dx) + (dy * dy + dz * dz);  // 4 sin^2 h
    const double sum_norm = detail::sqrt(sum2), chord = detail::sqrt(chord2);
    const double inverse = 1.0 / (sum_norm * chord);
    const double h = chord * 0.5 * asin_ratio_double(chord2 * 0.25);
    const double u = (static_cast<double>(t) + static_cast<double>(t) - 1.0) * h;
    const double v = u * u, v2 = v * v;
    const double sin_u =
        u * ((1.0 - v * (1.0 / 6)) + v2 * ((1.0 / 120 - v * (1.0 / 5040)) + v2 * (1.0 / 362880)));
    const double cos_u = (1.0 - v * 0.5) + v2 * ((1.0 / 24 - v * (1.0 / 720)) +
                                                 v2 * (1.0 / 40320 - v * (1.0 / 3628800)));
    // cos(u) / |sum| and sin(u) / chord, by one division off the path above.
    const double along = cos_u * (chord * inverse), across = sin_u * (sum_norm * inverse);
    return {
        static_cast<float>(sw * along + dw * across), static_cast<float>(sx * along + dx * across),
        static_cast<float>(sy * along + dy * across), static_cast<float>(sz * along + dz * across)};
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
        // rotation a* near, whose w = dot(a, near) >= 0, keeps the error at the level of one
        // product.
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
    if constexpr (std::is_same_v<T, float>) {
        // a == near: nothing to interpolate, but a non-finite t stays visible.
        if (a.w == near.w && a.x == near.x && a.y == near.y && a.z == near.z)
            return detail::is_finite(t) ? a : a * t;
        return detail::slerp_float(a, near, t);
    }
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

/// The quaternion exponential of q = (w, v): e^w (cos|v|, sin|v| v / |v|), for any q (not only unit
/// or pure ones). For a unit result, w = 0: exp((0, r / 2)) is from_rotation_vector(r), the
/// rotation by |r| about r, to within a few eps. Accurate from v = 0 (a series for sin|v| / |v|, no
/// 0/0; exp((w, 0)) is (e^w, v) exactly, signed zeros kept, for float, double and long double) to
/// huge or subnormal |v| (measured as norm does, scaled); e^w overflows to Inf past w = ln max().
/// NaN in gives NaN out. glm::exp ignores w and returns the identity for |v| < epsilon.
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
/// where Unity's turns away from `to`. A NaN in any input, or an infinite `from` or `to`, gives
/// NaN; an infinite max_angle gives `to`. Preconditions: unit from and to (checked in debug
/// builds).
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

#endif  // QUAT_PATHS_INTERPOLATION_HPP_INCLUDED
