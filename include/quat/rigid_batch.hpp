// Rigid motions over many elements: moving many points by one dual quaternion or homogeneous
// matrix (array of structs and struct of arrays), and composing many dual quaternions. The loops,
// aliasing rules and instruction-set namespaces are those of batch.hpp.
#ifndef QUAT_RIGID_BATCH_HPP_INCLUDED
#define QUAT_RIGID_BATCH_HPP_INCLUDED

#include <cstddef>
#include <type_traits>
#include <utility>

#include "batch.hpp"
#include "config.hpp"
#include "conversions.hpp"
#include "detail/containers.hpp"
#include "dual_quaternion.hpp"
#include "homogeneous_matrix.hpp"
#include "vec3.hpp"

namespace quat {
#if defined(__AVX512F__)
inline namespace isa_avx512 {
#elif defined(__AVX2__)
inline namespace isa_avx2 {
#elif defined(__AVX__)
inline namespace isa_avx {
#else
inline namespace isa_baseline {
#endif

/// output[i] = R input[i] + t for i < count (array of structs), the rigid motion of the 4x4 matrix
/// m: 9 multiply-adds and 3 additions per point. output == input is allowed; other overlaps are
/// not. Precondition: last row (0, 0, 0, 1), not read.
template <class T>
void transform(const homogeneous_matrix<T>& m, const vec3<T>* input, vec3<T>* output,
               std::size_t count) noexcept {
    QUAT_ASSERT(
        detail::same_or_disjoint(input, count * sizeof(vec3<T>), output, count * sizeof(vec3<T>)),
        "quat::transform: output partially overlaps input");
    detail::transform_points<true>(rotation_block(m), translation_of(m), input, output, count);
}

/// output[i] = transform(dq, input[i]) for unit dq (array of structs): dq becomes a matrix and a
/// translation once. Aliasing as for the matrix overload.
template <class T>
void transform(const dual_quaternion<T>& dq, const vec3<T>* input, vec3<T>* output,
               std::size_t count) noexcept {
    transform(to_homogeneous(dq), input, output, count);
}

/// Struct-of-arrays form of the matrix overload: each output array may be its own input array or
/// not overlap any input. Precondition: output.count >= input.count.
template <class T>
void transform(const homogeneous_matrix<T>& m, soa_points<const T> input,
               soa_points<T> output) noexcept {
    QUAT_ASSERT(output.count >= input.count, "quat::transform: output shorter than input");
    QUAT_ASSERT(detail::soa_same_or_disjoint(input, output),
                "quat::transform: an output array partially overlaps an input array");
    detail::transform_points<true>(rotation_block(m), translation_of(m), input, output);
}

/// Struct-of-arrays form of the dual-quaternion overload; aliasing as for the matrix overload.
template <class T>
void transform(const dual_quaternion<T>& dq, soa_points<const T> input,
               soa_points<T> output) noexcept {
    transform(to_homogeneous(dq), input, output);
}

/// Container form of the array-of-structs transform by unit dq: any contiguous input and output
/// of vec3<T>. Precondition: size(output) >= size(input).
template <class T, class Input, class Output, class = detail::if_point_arrays<T, Input, Output>>
void transform(const dual_quaternion<T>& dq, const Input& input, Output&& output) noexcept {
    QUAT_ASSERT(detail::size_of(output) >= detail::size_of(input),
                "quat::transform: output shorter than input");
    transform(dq, detail::data_of(input), detail::data_of(output), detail::size_of(input));
}
/// Container form of the array-of-structs transform by the 4x4 matrix m.
template <class T, class Input, class Output, class = detail::if_point_arrays<T, Input, Output>>
void transform(const homogeneous_matrix<T>& m, const Input& input, Output&& output) noexcept {
    QUAT_ASSERT(detail::size_of(output) >= detail::size_of(input),
                "quat::transform: output shorter than input");
    transform(m, detail::data_of(input), detail::data_of(output), detail::size_of(input));
}

/// The product dq[0] dq[1] ... dq[count - 1] (dq[count - 1] applies first); identity when
/// count == 0. Four interleaved chains as in the quaternion compose: the same motion by
/// associativity, rounded differently.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> compose(const dual_quaternion<T>* dq,
                                                   std::size_t count) noexcept {
    return detail::interleaved_product(dq, count);
}

/// compose over any contiguous container or view of dual_quaternion<T>.
template <class Range, class T = std::remove_cv_t<std::remove_pointer_t<
                           decltype(detail::data_of(std::declval<const Range&>()))>>>
[[nodiscard]] constexpr std::enable_if_t<std::is_same_v<T, dual_quaternion<decltype(T{}.real.w)>>,
                                         T>
compose(const Range& factors) noexcept {
    return compose(detail::data_of(factors), detail::size_of(factors));
}

}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_RIGID_BATCH_HPP_INCLUDED
