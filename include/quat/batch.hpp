// Batch operations over contiguous arrays: rotating many points, composing many rotations, slerp at
// many parameters. Plain loops over fixed-size blocks that compilers vectorize (checked with
// g++ -O3 -fopt-info-vec); no allocation, no intrinsics, the same results for any scalar type.
//
// Arrays are passed either as pointer + count or as any contiguous container or view with
// std::data() and std::size() (std::vector, std::array, C arrays, std::span in C++20).
// Aliasing: an output may be exactly the input (in place) or not overlap it at all; a partial
// overlap gives unspecified values.
#pragma once

#include <cstddef>
#include <iterator>
#include <type_traits>

#include "config.hpp"
#include "conversions.hpp"
#include "interpolation.hpp"
#include "quaternion.hpp"
#include "rotation_matrix.hpp"
#include "vec3.hpp"

namespace quat {

/// Points stored as three separate coordinate arrays (struct of arrays), each `count` long.
/// Use soa_points<const T> for inputs and soa_points<T> for outputs.
template <class T>
struct soa_points {
    T* x;
    T* y;
    T* z;
    std::size_t count;
};

namespace detail {

// Points per block. Each block is read from the input, computed into local arrays that cannot
// alias anything, then stored: the compiler needs no run-time overlap checks, and in-place calls
// work. 256 floats per coordinate keep the three local arrays within 3 KiB of L1.
inline constexpr std::size_t batch_block = 256;

template <class T>
constexpr void rotate_block(const rotation_matrix<T>& m, const vec3<T>* input, vec3<T>* output,
                            std::size_t n) noexcept {
    const T m00 = m(0, 0), m01 = m(0, 1), m02 = m(0, 2), m10 = m(1, 0), m11 = m(1, 1), m12 = m(1, 2),
            m20 = m(2, 0), m21 = m(2, 1), m22 = m(2, 2);
    T rx[batch_block]{}, ry[batch_block]{}, rz[batch_block]{};
    for (std::size_t i = 0; i < n; ++i) {
        const T x = input[i].x, y = input[i].y, z = input[i].z;
        rx[i] = m00 * x + m01 * y + m02 * z;
        ry[i] = m10 * x + m11 * y + m12 * z;
        rz[i] = m20 * x + m21 * y + m22 * z;
    }
    for (std::size_t i = 0; i < n; ++i) output[i] = vec3<T>{rx[i], ry[i], rz[i]};
}

template <class T>
constexpr void rotate_block(const rotation_matrix<T>& m, const T* x, const T* y, const T* z, T* ox, T* oy,
                            T* oz, std::size_t n) noexcept {
    const T m00 = m(0, 0), m01 = m(0, 1), m02 = m(0, 2), m10 = m(1, 0), m11 = m(1, 1), m12 = m(1, 2),
            m20 = m(2, 0), m21 = m(2, 1), m22 = m(2, 2);
    T rx[batch_block]{}, ry[batch_block]{}, rz[batch_block]{};
    for (std::size_t i = 0; i < n; ++i) {
        rx[i] = m00 * x[i] + m01 * y[i] + m02 * z[i];
        ry[i] = m10 * x[i] + m11 * y[i] + m12 * z[i];
        rz[i] = m20 * x[i] + m21 * y[i] + m22 * z[i];
    }
    for (std::size_t i = 0; i < n; ++i) ox[i] = rx[i];
    for (std::size_t i = 0; i < n; ++i) oy[i] = ry[i];
    for (std::size_t i = 0; i < n; ++i) oz[i] = rz[i];
}

template <class T, class Input, class Output>
using if_point_arrays = std::enable_if_t<
    std::is_convertible_v<decltype(std::data(std::declval<const Input&>())), const vec3<T>*> &&
    std::is_convertible_v<decltype(std::data(std::declval<Output&>())), vec3<T>*>>;

}  // namespace detail

/// output[i] = m input[i] for i < count (array of structs). output == input is allowed; other
/// overlaps are not. Equal to rotate(m, input[i]) up to rounding order.
template <class T>
constexpr void rotate(const rotation_matrix<T>& m, const vec3<T>* input, vec3<T>* output, std::size_t count) noexcept {
    for (std::size_t start = 0; start < count; start += detail::batch_block) {
        const std::size_t n = count - start < detail::batch_block ? count - start : detail::batch_block;
        detail::rotate_block(m, input + start, output + start, n);
    }
}

/// output[i] = rotate(q, input[i]) for unit q (array of structs): q becomes a matrix once, so each
/// point costs 9 multiply-adds. Aliasing as for the matrix overload.
template <class T>
constexpr void rotate(const quaternion<T>& q, const vec3<T>* input, vec3<T>* output, std::size_t count) noexcept {
    rotate(to_matrix(q), input, output, count);
}

/// Struct-of-arrays rotation by m: each output array may be its own input array or not overlap
/// any input. Precondition: output.count >= input.count.
template <class T>
constexpr void rotate(const rotation_matrix<T>& m, soa_points<const T> input, soa_points<T> output) noexcept {
    QUAT_ASSERT(output.count >= input.count, "output shorter than input");
    for (std::size_t start = 0; start < input.count; start += detail::batch_block) {
        const std::size_t n = input.count - start < detail::batch_block ? input.count - start : detail::batch_block;
        detail::rotate_block(m, input.x + start, input.y + start, input.z + start, output.x + start,
                             output.y + start, output.z + start, n);
    }
}

/// Struct-of-arrays rotation by unit q (through its matrix); aliasing as for the matrix overload.
template <class T>
constexpr void rotate(const quaternion<T>& q, soa_points<const T> input, soa_points<T> output) noexcept {
    rotate(to_matrix(q), input, output);
}

/// Container form of the array-of-structs rotation by unit q: any contiguous input and output of
/// vec3<T> (std::vector, std::array, std::span, ...). Precondition: size(output) >= size(input).
template <class T, class Input, class Output, class = detail::if_point_arrays<T, Input, Output>>
constexpr void rotate(const quaternion<T>& q, const Input& input, Output& output) noexcept {
    QUAT_ASSERT(std::size(output) >= std::size(input), "output shorter than input");
    rotate(q, std::data(input), std::data(output), std::size(input));
}
/// Container form of the array-of-structs rotation by m.
template <class T, class Input, class Output, class = detail::if_point_arrays<T, Input, Output>>
constexpr void rotate(const rotation_matrix<T>& m, const Input& input, Output& output) noexcept {
    QUAT_ASSERT(std::size(output) >= std::size(input), "output shorter than input");
    rotate(m, std::data(input), std::data(output), std::size(input));
}

// COMPOSE

}  // namespace quat
