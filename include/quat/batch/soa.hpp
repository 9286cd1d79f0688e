// Struct-of-arrays views: points as three coordinate arrays (soa_points) and rotations as four
// component arrays (soa_quaternions), the layout whose loops need no shuffles. The functions taking
// them are in batch/rotations.hpp (rotate), batch/rigid_motions.hpp (transform) and
// batch/elementwise.hpp (rotate_each).
//
// The view types are the same under every instruction set, so they stay outside the instruction-set
// namespace (detail/math.hpp); the aliasing check beside them is a function and lives inside it.
#ifndef QUAT_BATCH_SOA_HPP_INCLUDED
#define QUAT_BATCH_SOA_HPP_INCLUDED

#include <cstddef>
#include <type_traits>

#include "detail/overlap.hpp"

namespace quat {

/// Points stored as three separate coordinate arrays (struct of arrays), each `count` long.
/// Use soa_points<const T> for inputs and soa_points<T> for outputs; soa_points<T> converts to
/// soa_points<const T>, so one object can be both (an in-place rotate(q, points, points)).
template <class T>
struct soa_points {
    T* x;               ///< x coordinates
    T* y;               ///< y coordinates
    T* z;               ///< z coordinates
    std::size_t count;  ///< number of points in each array

    /// The same arrays, read-only. Always inlined: a member function is not keyed by instruction
    /// set as quat's free functions are (see detail/math.hpp), so no copy of it may be emitted.
    template <class U = T, class = std::enable_if_t<!std::is_const_v<U>>>
    [[gnu::always_inline]] constexpr operator soa_points<const U>() const noexcept {
        return {x, y, z, count};
    }
};

/// Rotations stored as four separate component arrays (struct of arrays), each `count` long:
/// rotation i is w[i] + x[i] i + y[i] j + z[i] k. Use soa_quaternions<const T> for inputs;
/// soa_quaternions<T> converts to it.
template <class T>
struct soa_quaternions {
    T* w;               ///< scalar parts
    T* x;               ///< i components
    T* y;               ///< j components
    T* z;               ///< k components
    std::size_t count;  ///< number of rotations in each array

    /// The same arrays, read-only; always inlined, as soa_points' conversion.
    template <class U = T, class = std::enable_if_t<!std::is_const_v<U>>>
    [[gnu::always_inline]] constexpr operator soa_quaternions<const U>() const noexcept {
        return {w, x, y, z, count};
    }
};

#include "../detail/isa_namespace.inc"
namespace detail {

// The aliasing rule of the struct-of-arrays forms: each output array is one of the input arrays or
// overlaps none of them; every array holds `count` elements. The inputs come as a plain array, not
// a braced list: std::initializer_list's members are the standard library's inline functions, not
// keyed by instruction set.
template <class T, std::size_t N>
[[nodiscard]] bool soa_same_or_disjoint(const T* const (&inputs)[N], soa_points<T> output,
                                        std::size_t count) noexcept {
    const std::size_t bytes = count * sizeof(T);
    const T* const outputs[] = {output.x, output.y, output.z};
    for (const T* out : outputs)
        for (const T* in : inputs)
            if (!same_or_disjoint(in, bytes, out, bytes)) return false;
    return true;
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_BATCH_SOA_HPP_INCLUDED
