// Interpolation between rotations: slerp (constant angular velocity) and nlerp (cheap, normalized).
#ifndef QUAT_INTERPOLATION_HPP_INCLUDED
#define QUAT_INTERPOLATION_HPP_INCLUDED

#include "config.hpp"
#include "detail/math.hpp"
#include "quaternion.hpp"
#include "vec3.hpp"

namespace quat {

/// Spherical linear interpolation from unit a (t = 0) to unit b (t = 1) along the shorter arc, at
/// constant angular velocity; t outside [0, 1] extrapolates along the same great circle. Returns
/// a at t = 0 and b, or -b when -b is nearer a, at t = 1, exactly. The angle comes from the chord
/// |a - b|, accurate for nearly equal and nearly opposite inputs. Precondition: unit a and b
/// (checked in debug builds). A NaN or infinite a, b or t gives a non-finite result.
template <class T>
[[nodiscard]] constexpr quaternion<T> slerp(const quaternion<T>& a, const quaternion<T>& b,
                                            detail::type_identity_t<T> t) noexcept {
    QUAT_ASSERT(detail::is_near_unit(a) && detail::is_near_unit(b),
                "quat::slerp: a or b is not a unit quaternion");
    const quaternion<T> near = dot(a, b) < T(0) ? -b : b;
    // Exact ends; adding x - x (zero when finite, NaN otherwise) keeps a NaN or infinite other end
    // visible instead of returning a clean-looking value.
    if (t == T(0)) return a + (near - near);
    if (t == T(1)) return near + (a - a);
    if (t < T(0) || t > T(1)) {
        // Beyond the ends the two weights below grow and cancel; turning a by t times the relative
        // rotation a* near, whose w = dot(a, near) >= 0, keeps the error at the level of one product.
        const quaternion<T> relative = conjugate(a) * near;
        const vec3<T> u{relative.x, relative.y, relative.z};
        const T s = norm(u);
        if (s == T(0)) return detail::is_finite(t) ? a : a * t;  // no motion; a bad t stays visible
        const T half_turn = t * detail::atan2(s, relative.w);
        const vec3<T> v = u / s * detail::sin(half_turn);
        return a * quaternion<T>{detail::cos(half_turn), v.x, v.y, v.z};
    }
    // With h half the angle between a and near (h <= pi/4 since dot(a, near) >= 0), the slerp
    // path is cos(u) e + sin(u) f, u = (2t - 1) h, where e and f are the orthonormal directions
    // of a + near and near - a (|a + near| = 2 cos h, |near - a| = 2 sin h): one sine-cosine pair
    // instead of three sines, and each direction divided by the norm it actually has, so the
    // result is unit to a few roundings whatever the rounding of h. The chord |near - a| keeps h
    // accurate for nearly equal inputs, unlike acos of the dot product.
    const quaternion<T> sum = a + near;
    const quaternion<T> difference = near - a;
    const T chord = detail::sqrt(squared_norm(difference));
    // a == near: nothing to interpolate, but a non-finite t stays visible (other NaN goes on below).
    if (chord == T(0)) return detail::is_finite(t) ? a : a * t;
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

}  // namespace quat

#endif  // QUAT_INTERPOLATION_HPP_INCLUDED
