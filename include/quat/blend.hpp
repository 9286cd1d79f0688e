// Dual-quaternion linear blending of rigid motions (Kavan, Collins, Zara and O'Sullivan, "Skinning
// with dual quaternions", I3D 2007): skinning without the collapse of blended matrices.
#ifndef QUAT_BLEND_HPP_INCLUDED
#define QUAT_BLEND_HPP_INCLUDED

#include <cstddef>
#include <type_traits>
#include <utility>

#include "config.hpp"
#include "detail/containers.hpp"
#include "dual_quaternion.hpp"
#include "quaternion.hpp"

namespace quat {

/// Dual-quaternion linear blending: the sum of weights[i] transforms[i], each term's sign taken so
/// its real part is on the first one's hemisphere, then normalized (unit real part, dual part
/// orthogonal to it). Unlike a blend of matrices it is always a rigid motion, so a skinned joint
/// twisted by 180 degrees keeps its volume. Weights need not sum to 1 (normalization removes the
/// scale) and may be negative. Preconditions: unit transforms; a zero blended real part (count 0,
/// zero weights, or weights cancelling) gives NaN.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> blend(const dual_quaternion<T>* transforms,
                                                 const T* weights, std::size_t count) noexcept {
    quaternion<T> real{T(0), T(0), T(0), T(0)}, dual{T(0), T(0), T(0), T(0)};
    for (std::size_t i = 0; i < count; ++i) {
        const T w = dot(transforms[i].real, transforms[0].real) < T(0) ? -weights[i] : weights[i];
        real += transforms[i].real * w;
        dual += transforms[i].dual * w;
    }
    return normalize(dual_quaternion<T>{real, dual});
}

/// blend over contiguous containers (std::vector, std::array, std::span, C arrays) of
/// dual_quaternion<T> and of T. Precondition: equal sizes (checked in debug builds).
template <class Transforms, class Weights,
          class T = std::remove_cv_t<
              std::remove_pointer_t<decltype(detail::data_of(std::declval<const Weights&>()))>>>
[[nodiscard]] constexpr dual_quaternion<T> blend(const Transforms& transforms,
                                                 const Weights& weights) noexcept {
    QUAT_ASSERT(detail::size_of(transforms) == detail::size_of(weights),
                "quat::blend: transforms and weights differ in size");
    return blend(static_cast<const dual_quaternion<T>*>(detail::data_of(transforms)),
                 detail::data_of(weights), detail::size_of(weights));
}

}  // namespace quat

#endif  // QUAT_BLEND_HPP_INCLUDED
