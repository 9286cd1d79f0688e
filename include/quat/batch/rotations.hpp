// Batch operations over contiguous arrays: rotating many points, composing many rotations, slerp at
// many parameters. Plain loops that compilers vectorize (checked with g++ -O3 -fopt-info-vec and
// objdump), no allocation, the same results for any scalar type. Two exceptions: the array-of-
// structs float loop of AVX builds spells its shuffles out (detail/interleaved_points_avx.hpp,
// 1.6x the compiled loop at -march=x86-64-v3), and float arrays that with their input exceed the
// last-level cache (read once at run time by cpuid), or whose output exceeds 16 MiB, are
// written on x86 with non-temporal stores (both layouts; plain stores elsewhere), the one use of
// intrinsics (detail/streaming_store.hpp).
//
// Arrays are passed either as pointer + count or as any contiguous container or view with data()
// and size() members (std::vector, std::array, std::span in C++20), or as C arrays.
// Aliasing: an output may be exactly the input (in place) or not overlap it at all. A partial
// overlap is a precondition violation: QUAT_ASSERT reports it in debug builds (one pointer-range
// check per call); with NDEBUG the values written are unspecified.
//
// One definition across instruction sets: the functions here are compiled differently under
// different -m flags (vector width, the streaming branch, FMA), so like all of quat's functions
// they
// live in the inline namespace named after the instruction set (detail/math.hpp says what the key
// covers). The struct-of-arrays views are in batch/soa.hpp, which this header includes; the loops
// that
// rotate and transform points (shared with batch/rigid_motions.hpp) in detail/transform_points.hpp.
#ifndef QUAT_BATCH_ROTATIONS_HPP_INCLUDED
#define QUAT_BATCH_ROTATIONS_HPP_INCLUDED

#include <cstddef>
#include <type_traits>
#include <utility>

#include "../config.hpp"
#include "../conversions.hpp"
#include "../detail/containers.hpp"
#include "../paths/interpolation.hpp"
#include "../quaternion.hpp"
#include "../rotation_matrix.hpp"
#include "../vec3.hpp"
#include "detail/chained_product.hpp"
#include "detail/overlap.hpp"
#include "detail/transform_points.hpp"
#include "soa.hpp"

namespace quat {
#include "../detail/isa_namespace.inc"
namespace detail {

// Slerp parameters per block computed into local arrays first: the output could alias t's type.
inline constexpr std::size_t batch_block_slerp = 128;

// sin(x) for |x| <= pi/2 by its Taylor polynomial x - x^3/3! + ..., cut where the first dropped
// term is below epsilon / 100 at pi/2 (through x^13 for float, x^21 for double). Unlike std::sin it
// vectorizes.
template <class T>
struct sine_series {
    static constexpr std::size_t terms = sizeof(T) <= 4 ? 7 : 11;
    T coefficient[terms];
    constexpr sine_series() noexcept : coefficient{} {
        long double c = 1.0L;
        for (std::size_t k = 0; k < terms; ++k) {
            coefficient[k] = static_cast<T>(c);
            c = -c / static_cast<long double>((2 * k + 2) * (2 * k + 3));
        }
    }
};

template <class T>
[[nodiscard]] constexpr T sin_half_pi(T x) noexcept {
    constexpr sine_series<T> series{};
    const T x2 = x * x;
    T acc = series.coefficient[sine_series<T>::terms - 1];
    for (std::size_t k = sine_series<T>::terms - 1; k-- > 0;)
        acc = acc * x2 + series.coefficient[k];
    return x * acc;
}

// The batch slerp for float and double: see slerp(a, b, t, output, count). Each t converts to T
// as it is read. a and b are the caller's copies, never elements of output.
template <class T, class U>
void slerp_polynomial(const quaternion<T>& a, const quaternion<T>& b, const U* t,
                      quaternion<T>* output, std::size_t count) noexcept {
    const quaternion<T> near = dot(a, b) < T(0) ? -b : b;
    const T chord = detail::sqrt(squared_norm(a - near));  // 2 sin(angle/2)
    const T sum = detail::sqrt(squared_norm(a + near));    // 2 cos(angle/2)
    const T angle = T(2) * detail::atan2(chord, sum);      // in [0, pi/2]
    bool in_range = angle * angle * angle * angle >= detail::epsilon<T>();
    for (std::size_t i = 0; i < count && in_range; ++i) {
        const T ti = static_cast<T>(t[i]);
        in_range = ti >= T(0) && ti <= T(1);
    }
    if (!in_range) {
        for (std::size_t i = 0; i < count; ++i) output[i] = slerp(a, b, static_cast<T>(t[i]));
        return;
    }
    const T inverse_sine = T(2) / (chord * sum);
    for (std::size_t start = 0; start < count; start += detail::batch_block_slerp) {
        const std::size_t n =
            count - start < detail::batch_block_slerp ? count - start : detail::batch_block_slerp;
        const U* tb = t + start;
        // Uninitialized: every used slot is written first.
        T rw[detail::batch_block_slerp], rx[detail::batch_block_slerp],
            ry[detail::batch_block_slerp], rz[detail::batch_block_slerp];
        for (std::size_t i = 0; i < n; ++i) {
            const T ti = static_cast<T>(tb[i]);
            T wa = detail::sin_half_pi((T(1) - ti) * angle) * inverse_sine;
            T wb = detail::sin_half_pi(ti * angle) * inverse_sine;
            // Exact ends by arithmetic on 0/1 flags (selects here keep g++ from vectorizing for
            // SSE2): 1 - w is exact for w near 1, so w + (1 - w) is exactly 1.
            const T at_start = T(ti == T(0)), at_end = T(ti == T(1));
            wa = (wa + at_start * (T(1) - wa)) * (T(1) - at_end);
            wb = wb + at_end * (T(1) - wb);
            rw[i] = a.w * wa + near.w * wb;
            rx[i] = a.x * wa + near.x * wb;
            ry[i] = a.y * wa + near.y * wb;
            rz[i] = a.z * wa + near.z * wb;
        }
        for (std::size_t i = 0; i < n; ++i)
            output[start + i] = quaternion<T>{rw[i], rx[i], ry[i], rz[i]};
    }
}

}  // namespace detail

/// output[i] = m input[i] for i < count (array of structs). output == input is allowed; other
/// overlaps are not. Equal to rotate(m, input[i]) up to rounding order.
template <class T>
void rotate(const rotation_matrix<T>& m, const vec3<T>* input, vec3<T>* output,
            std::size_t count) noexcept {
    QUAT_ASSERT(
        detail::same_or_disjoint(input, count * sizeof(vec3<T>), output, count * sizeof(vec3<T>)),
        "quat::rotate: output partially overlaps input");
    detail::transform_points<false>(m, vec3<T>{}, input, output, count);
}

/// output[i] = rotate(q, input[i]) for unit q (array of structs): q becomes a matrix once, so each
/// point costs 9 multiply-adds. Aliasing as for the matrix overload.
template <class T>
void rotate(const quaternion<T>& q, const vec3<T>* input, vec3<T>* output,
            std::size_t count) noexcept {
    rotate(to_matrix(q), input, output, count);
}

/// Struct-of-arrays rotation by m: each output array may be its own input array or not overlap any
/// input (rotate(m, points, points) rotates in place). Precondition: output.count >= input.count.
template <class T>
void rotate(const rotation_matrix<T>& m, soa_points<const detail::type_identity_t<T>> input,
            soa_points<T> output) noexcept {
    QUAT_ASSERT(output.count >= input.count, "quat::rotate: output shorter than input");
    QUAT_ASSERT(detail::soa_same_or_disjoint({input.x, input.y, input.z}, output, input.count),
                "quat::rotate: an output array partially overlaps an input array");
    detail::transform_points<false>(m, vec3<T>{}, input, output);
}

/// Struct-of-arrays rotation by unit q (through its matrix); aliasing as for the matrix overload.
template <class T>
void rotate(const quaternion<T>& q, soa_points<const detail::type_identity_t<T>> input,
            soa_points<T> output) noexcept {
    rotate(to_matrix(q), input, output);
}

/// Container form of the array-of-structs rotation by unit q: any contiguous input and output of
/// vec3<T> (std::vector, std::array, std::span, ...). Precondition: size(output) >= size(input)
/// (QUAT_ASSERT); unchecked, the first min(size(input), size(output)) points, never past either.
template <class T, class Input, class Output,
          class = detail::if_arrays_of<vec3<T>, vec3<T>, Input, Output>>
void rotate(const quaternion<T>& q, const Input& input, Output&& output) noexcept {
    QUAT_ASSERT(detail::size_of(output) >= detail::size_of(input),
                "quat::rotate: output shorter than input");
    rotate(q, detail::data_of(input), detail::data_of(output), detail::common_size(input, output));
}
/// Container form of the array-of-structs rotation by m, with the precondition of the one by q.
template <class T, class Input, class Output,
          class = detail::if_arrays_of<vec3<T>, vec3<T>, Input, Output>>
void rotate(const rotation_matrix<T>& m, const Input& input, Output&& output) noexcept {
    QUAT_ASSERT(detail::size_of(output) >= detail::size_of(input),
                "quat::rotate: output shorter than input");
    rotate(m, detail::data_of(input), detail::data_of(output), detail::common_size(input, output));
}

/// The product q[0] q[1] ... q[count - 1] (q[count - 1] applies first); identity when count == 0.
/// Four runs of consecutive factors are multiplied in interleaved, independent chains and the four
/// partial products joined at the end, so the CPU overlaps four products instead of waiting on
/// each: the same rotation as the left-to-right loop by associativity, rounded differently: over
/// 100 sets of 1024 random unit factors the two differ by at most 2.5e-6 (float) and 5.1e-15
/// (double) per component, as large as the sequential loop's own error against long double (2.7e-6,
/// 4.7e-15).
template <class T>
[[nodiscard]] constexpr quaternion<T> compose(const quaternion<T>* q, std::size_t count) noexcept {
    return detail::chained_product(q, count);
}

/// compose over any contiguous container or view of quaternion<T>.
template <class Range, class T = detail::element_scalar_t<quaternion, Range>>
[[nodiscard]] constexpr quaternion<T> compose(const Range& factors) noexcept {
    return compose(detail::data_of(factors), detail::size_of(factors));
}

/// output[i] = slerp(a, b, t[i]) for i < count: the angle is computed once and the sines by a
/// polynomial that vectorizes, to within a few ulp of the scalar slerp. Exact at t = 0 and 1.
/// a and b are taken by value, so they may be elements of output (slerp(out[0], b, t, out, n)).
/// The scalar type is the rotations'; t may be of another (double times for float rotations), and
/// each t converts to T. Preconditions: unit a and b (checked in debug builds, as by the scalar
/// slerp); output does not overlap t. For t outside [0, 1], nearly equal a and b, or
/// non-float/double scalars, each value falls back to the scalar slerp.
template <class T, class U, class = std::enable_if_t<std::is_convertible_v<const U&, T>>>
void slerp(quaternion<T> a, quaternion<T> b, const U* t, quaternion<T>* output,
           std::size_t count) noexcept {
    QUAT_ASSERT(detail::is_near_unit(a) && detail::is_near_unit(b),
                "quat::slerp: a or b is not a unit quaternion, checked once for the batch");
    QUAT_ASSERT(detail::disjoint(t, count * sizeof(U), output, count * sizeof(quaternion<T>)),
                "quat::slerp: output overlaps t");
    if constexpr (!std::is_same_v<T, float> && !std::is_same_v<T, double>) {
        for (std::size_t i = 0; i < count; ++i) output[i] = slerp(a, b, static_cast<T>(t[i]));
    } else {
        detail::slerp_polynomial(a, b, t, output, count);
    }
}

/// slerp at every t of a contiguous container (of T or another scalar type, which converts) into a
/// contiguous output of quaternion<T>; a and b may be elements of output. Precondition:
/// size(output) >= size(t) (QUAT_ASSERT); unchecked, the first min(size(t), size(output)).
template <class T, class Parameters, class Output,
          class = std::enable_if_t<std::is_convertible_v<
              decltype(detail::data_of(std::declval<Output&>())), quaternion<T>*>>>
void slerp(quaternion<T> a, quaternion<T> b, const Parameters& t, Output&& output) noexcept {
    QUAT_ASSERT(detail::size_of(output) >= detail::size_of(t),
                "quat::slerp: output shorter than the parameters");
    slerp(a, b, detail::data_of(t), static_cast<quaternion<T>*>(detail::data_of(output)),
          detail::common_size(t, output));
}

}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_BATCH_ROTATIONS_HPP_INCLUDED
