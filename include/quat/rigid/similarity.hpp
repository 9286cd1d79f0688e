// Similarities x -> s R x + t: a rigid motion after a uniform scale about the origin, what
// align_points_with_scale fits. Applied, composed and inverted with the scale, and written as a
// general 4x4 matrix (homogeneous_matrix holds rigid motions only).
#ifndef QUAT_RIGID_SIMILARITY_HPP_INCLUDED
#define QUAT_RIGID_SIMILARITY_HPP_INCLUDED

#include "../config.hpp"
#include "../conversions.hpp"
#include "../detail/math.hpp"
#include "../matrix.hpp"
#include "../quaternion.hpp"
#include "../rotation_matrix.hpp"
#include "../vec3.hpp"
#include "dual_quaternion.hpp"

namespace quat {

/// The similarity x -> scale R x + t: the uniform scaling by `scale` about the origin, then the
/// rigid motion (R, t) of the unit dual quaternion `motion`, so transform(s, p) is
/// transform(s.motion, p * s.scale). Any finite scale applies (0 maps every point to t, a negative
/// one adds the point reflection x -> -x); inverse needs a non-zero one.
template <class T>
struct similarity {
    dual_quaternion<T> motion;  ///< R and t, applied after the scale.
    T scale;                    ///< The uniform scale s.

    /// The similarity that moves nothing: the identity motion, scale 1.
    [[nodiscard]] [[gnu::always_inline]] static constexpr similarity identity() noexcept {
        return {dual_quaternion<T>::identity(), T(1)};
    }
};

#include "../detail/isa_namespace.inc"
/// scale R p + t: the point p moved by the similarity s. Precondition: s.motion a unit dual
/// quaternion, as for transform(dual_quaternion, p) (|real| is checked in debug builds).
template <class T>
[[nodiscard]] constexpr vec3<T> transform(const similarity<T>& s, const vec3<T>& p) noexcept {
    QUAT_ASSERT(detail::is_near_unit(s.motion.real),
                "quat::transform: the similarity's motion is not a unit dual quaternion");
    return detail::rotate_unchecked(s.motion.real, p) * s.scale + translation_of(s.motion);
}

/// The composition a * b: b first, then a, x -> a(b(x)), whose scale is a.scale b.scale and whose
/// motion is a.motion after b's translation scaled by a.scale: (R_a R_b, a.scale R_a t_b + t_a).
template <class T>
[[nodiscard]] constexpr similarity<T> operator*(const similarity<T>& a,
                                                const similarity<T>& b) noexcept {
    // The dual part is t times the rotation over 2, so scaling it scales b's translation alone.
    const dual_quaternion<T> scaled_b{b.motion.real, b.motion.dual * a.scale};
    return {a.motion * scaled_b, a.scale * b.scale};
}

/// The inverse similarity x -> R^T (x - t) / scale: motion (R^T, -R^T t / scale), scale 1 / scale,
/// so that s * inverse(s) and inverse(s) * s are the identity (to rounding). A zero, NaN or
/// infinite scale has no inverse: every component of the result is NaN.
template <class T>
[[nodiscard]] constexpr similarity<T> inverse(const similarity<T>& s) noexcept {
    if (!(s.scale != T(0)) || !detail::is_finite(s.scale)) {
        const quaternion<T> nan = detail::nan_quaternion<T>();
        return {{nan, nan}, detail::quiet_nan<T>()};
    }
    const dual_quaternion<T> rigid = inverse(s.motion);
    const T shrink = T(1) / s.scale;
    return {{rigid.real, rigid.dual * shrink}, shrink};
}

/// The 4x4 matrix of s acting on column vectors (x, y, z, 1): scale R in the upper left 3x3 block,
/// t in the last column, (0, 0, 0, 1) as the last row; m (p, 1) = (transform(s, p), 1). A general
/// matrix, not a homogeneous_matrix: that type holds rigid motions. Precondition as for transform.
template <class T>
[[nodiscard]] constexpr matrix<T, 4, 4> to_matrix4(const similarity<T>& s) noexcept {
    QUAT_ASSERT(detail::is_near_unit(s.motion.real),
                "quat::to_matrix4: the similarity's motion is not a unit dual quaternion");
    const rotation_matrix<T> r = to_matrix(s.motion.real);
    const vec3<T> t = translation_of(s.motion);
    const T column[3] = {t.x, t.y, t.z};
    matrix<T, 4, 4> m{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m(i, j) = r(i, j) * s.scale;
        m(i, 3) = column[i];
        m(3, i) = T(0);
    }
    m(3, 3) = T(1);
    return m;
}

}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_RIGID_SIMILARITY_HPP_INCLUDED
