// Dual-quaternion linear blending of rigid motions (Kavan, Collins, Zara and O'Sullivan, "Skinning
// with dual quaternions", I3D 2007): skinning without the collapse of blended matrices.
#ifndef QUAT_RIGID_BLEND_HPP_INCLUDED
#define QUAT_RIGID_BLEND_HPP_INCLUDED

#include <cstddef>

#include "../config.hpp"
#include "../detail/containers.hpp"
#include "../quaternion.hpp"
#include "dual_quaternion.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"

/// Dual-quaternion linear blending: the sum of weights[i] transforms[i], each term's sign taken so
/// its real part is on the first one's hemisphere, then normalized (unit real part, dual part
/// orthogonal to it). Unlike a blend of matrices it is always a rigid motion, so a skinned joint
/// twisted by 180 degrees keeps its volume. Weights (scalars convertible to T) need not sum to 1:
/// they are divided by the largest |weight| first and normalization removes the scale, so any
/// finite size works, subnormal to max(); they may be negative. Preconditions: unit real parts
/// (QUAT_ASSERT; unchecked, longer ones count more); a zero blended real part (count 0, zero
/// weights, or weights cancelling), a NaN or infinite weight or component gives NaN in every
/// component.
template <class T, class Weight>
[[nodiscard]] constexpr dual_quaternion<T> blend(const dual_quaternion<T>* transforms,
                                                 const Weight* weights,
                                                 std::size_t count) noexcept {
    T largest = T(0);
    for (std::size_t i = 0; i < count; ++i) {
        QUAT_ASSERT(detail::is_near_unit(transforms[i].real),
                    "quat::blend: a transform's real part is not a unit quaternion");
        const T w = static_cast<T>(weights[i]), size = w < T(0) ? -w : w;
        largest = size > largest || !(size == size) ? size : largest;
    }
    // A NaN or infinite largest weight propagates as NaN: inf / inf.
    const T scale = largest > T(0) ? largest : T(1);
    quaternion<T> real{T(0), T(0), T(0), T(0)}, dual{T(0), T(0), T(0), T(0)};
    for (std::size_t i = 0; i < count; ++i) {
        const T scaled = static_cast<T>(weights[i]) / scale;
        const T w = dot(transforms[i].real, transforms[0].real) < T(0) ? -scaled : scaled;
        real += transforms[i].real * w;
        dual += transforms[i].dual * w;
    }
    const dual_quaternion<T> result = normalize(dual_quaternion<T>{real, dual});
    // NaN in every component when any is not finite: a NaN translation beside a finite rotation
    // would pass for half a result.
    const T parts[8] = {result.real.w, result.real.x, result.real.y, result.real.z,
                        result.dual.w, result.dual.x, result.dual.y, result.dual.z};
    for (const T& part : parts)
        if (!detail::is_finite(part)) {
            const T nan = detail::quiet_nan<T>();
            return {{nan, nan, nan, nan}, {nan, nan, nan, nan}};
        }
    return result;
}

/// blend over contiguous containers (std::vector, std::array, std::span, C arrays) of
/// dual_quaternion<T> and of scalars convertible to T (the precision is the transforms').
/// Precondition: equal sizes (QUAT_ASSERT); unchecked, other sizes blend as count 0: NaN.
template <class Transforms, class Weights,
          class T = detail::element_scalar_t<dual_quaternion, Transforms>>
[[nodiscard]] constexpr dual_quaternion<T> blend(const Transforms& transforms,
                                                 const Weights& weights) noexcept {
    QUAT_ASSERT(detail::same_size(transforms, weights),
                "quat::blend: transforms and weights differ in size");
    return blend(detail::data_of(transforms), detail::data_of(weights),
                 detail::same_size(transforms, weights) ? detail::size_of(weights) : 0);
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_RIGID_BLEND_HPP_INCLUDED
