// Element-by-element batches: point i turned by rotation i (rotate_each), the products a[i] * b[i]
// (compose_each), and the conversions to_matrix_each and to_quaternion_each.
//
// Names: a function over arrays ends in _each when element i of its output comes from element i of
// each input array (rotation i turns point i; a[i] * b[i]; matrix i of rotation i). One transform
// applied to many elements keeps the plain name of its single form, with arrays in place of the
// element (batch/rotations.hpp's rotate(q, points, out), the batch slerp(a, b, ts, out),
// batch/rigid_motions.hpp's
// transform(dq, points, out)), as does a reduction of an array to one value (compose(factors)).
//
// For float and double the rotate_each and compose_each loops are written so that g++ and clang
// vectorize them (checked with -fopt-info-vec and objdump); the float array-of-structs kernels of
// AVX and AVX-512 builds spell their shuffles out instead (detail/interleaved_elements.hpp),
// since the compiled loops are bound by their lane-crossing permutes. So do the conversions
// to_matrix_each and to_quaternion_each for float in AVX and AVX-512 builds, whose kernels regroup
// the nine interleaved entries of 8 or 16 matrices in registers, and to_quaternion_each in SSE2
// builds, 4 a step; elsewhere they run the scalar conversions element by element. On a Zen 4,
// 1024 random rotations: to_matrix 1.37 us against 2.3 to 2.4 for the scalar loop and Eigen's,
// 2.5 for GLM's; to_quaternion, which the kernels run without a branch, 2.0 (AVX) and 2.1
// (AVX-512) against 4.9 for the scalar loop, which branches four ways at random, and 3.6 for GLM's
// quat_cast loop (-march=x86-64-v3). Regrouped through local arrays instead, g++ 12 vectorized
// to_quaternion slower than the scalar loop (7.3 against 4.9, AVX-512). Where a result is "the
// scalar one", it may still differ in the last bit where the compiler fuses multiply-adds
// differently in the two places (-ffp-contract).
//
// Arrays are passed as pointer + count or as contiguous containers (data() and size(), C arrays),
// as in batch/rotations.hpp; the struct-of-arrays views are batch/soa.hpp's. Aliasing: an output
// may be exactly an input of its own type (in place) or overlap no input; it may never overlap an
// input of another type. A partial overlap is a precondition violation: QUAT_ASSERT reports it in
// debug builds (a constant number of pointer range comparisons per call); with NDEBUG the values
// written are unspecified. Like all of quat's functions they live in the instruction-set
// namespace (detail/math.hpp).
#ifndef QUAT_BATCH_ELEMENTWISE_HPP_INCLUDED
#define QUAT_BATCH_ELEMENTWISE_HPP_INCLUDED

#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

#include "../config.hpp"
#include "../conversions.hpp"
#include "../detail/containers.hpp"
#include "../quaternion.hpp"
#include "../rotation_matrix.hpp"
#include "../vec3.hpp"
#include "detail/factored_rotation.hpp"
#include "detail/interleaved_elements.hpp"
#include "detail/overlap.hpp"
#include "detail/streaming_store.hpp"
#include "detail/wide_lanes.hpp"
#include "soa.hpp"

namespace quat {
#include "../detail/isa_namespace.inc"
namespace detail {

// The rotation of one element: rotate_factored for float and double, whose loops vectorize; for
// other scalars (long double, user types) the arithmetic of rotate(q, v), whose results they get.
// Neither checks |q| (rotate's debug check stays out of the loops).
template <class T>
[[nodiscard]] constexpr vec3<T> rotate_element(const quaternion<T>& q, const vec3<T>& v) noexcept {
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
        return rotate_factored(q, v);
    } else {
        return rotate_unchecked(q, v);
    }
}

// The loops below ask clang to vectorize; where it cannot (at -O1 with the sanitizers, for one),
// its -Wpass-failed warning would break -Werror builds of user code, so it is silenced here.
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wpass-failed"
#endif

template <class T>
void rotate_each_loop(const quaternion<T>* rotations, const vec3<T>* points, vec3<T>* output,
                      std::size_t count) noexcept {
    // Element i is read before it is written and no iteration touches another's element, so the
    // in-place call (output == points) is safe with vectorization: tell the compiler, which would
    // otherwise check for overlap at run time. The components are stored one by one: clang does
    // not vectorize the copy of a whole vec3 here.
#if defined(__clang__)
#pragma clang loop vectorize(assume_safety)
#elif defined(__GNUC__)
#pragma GCC ivdep
#endif
    for (std::size_t i = 0; i < count; ++i) {
        const vec3<T> r = rotate_element(rotations[i], points[i]);
        output[i].x = r.x;
        output[i].y = r.y;
        output[i].z = r.z;
    }
}

// With Stream, the floats per non-temporal store (the vector's width, or 4; each output array
// aligned to that many floats), the whole vectors are stored non-temporally; 0 stores plainly.
// Downward runs the whole vectors from the last to the first (streaming_store.hpp's sweep says
// why). With Prefetch (plain stores only), the vector loop asks for its output lines ahead of its
// stores (prefetch_outputs).
template <std::size_t Stream = 0, bool Downward = false, bool Prefetch = false, class T>
void rotate_each_soa(soa_quaternions<const T> q, soa_points<const T> p,
                     soa_points<T> output) noexcept {
    static_assert(!Prefetch || Stream == 0, "non-temporal stores read no lines to prefetch");
    std::size_t done = 0;
    // Whole vectors of lanes written out (detail/wide_lanes.hpp says why), the rest below. Each
    // step loads the next vector of every input before it stores its own results, which keeps
    // the loads clear of 4K aliasing with the stores (detail::transform_block's struct-of-arrays
    // loop says more), and is safe where an output array is an input array.
    if constexpr (has_wide_lanes<T>) {
        using V = wide_t<T>;
        constexpr std::size_t lanes = wide_count<T>;
        struct element {
            V w, x, y, z, px, py, pz;
        };
        auto load = [&](std::size_t at) noexcept {
            return element{load_wide(q.w + at), load_wide(q.x + at), load_wide(q.y + at),
                           load_wide(q.z + at), load_wide(p.x + at), load_wide(p.y + at),
                           load_wide(p.z + at)};
        };
        auto turn = [&](const element& e, std::size_t at) noexcept {
            V rx, ry, rz;
            rotate_factored_lanes(e.w, e.x, e.y, e.z, e.px, e.py, e.pz, rx, ry, rz);
            if constexpr (Stream != 0) {
                // Each line is filled in the sweep's direction: a downward sweep that wrote its
                // pieces upward ran 4.0-4.2 ns an element instead of 1.0-1.1 (AVX-512, outputs
                // 16 bytes off the inputs modulo 4096, which the line then straddles).
                for (std::size_t step = 0; step < lanes; step += Stream) {
                    const std::size_t piece = Downward ? lanes - Stream - step : step;
                    stream_vector<Stream>(output.x + at + piece,
                                          reinterpret_cast<const T*>(&rx) + piece);
                    stream_vector<Stream>(output.y + at + piece,
                                          reinterpret_cast<const T*>(&ry) + piece);
                    stream_vector<Stream>(output.z + at + piece,
                                          reinterpret_cast<const T*>(&rz) + piece);
                }
            } else {
                store_wide(output.x + at, rx);
                store_wide(output.y + at, ry);
                store_wide(output.z + at, rz);
            }
        };
        const std::size_t whole = p.count - p.count % lanes;  // as in detail::transform_block
        if (whole != 0) {
            // Downward, the unsigned step wraps: adding it subtracts lanes.
            constexpr std::size_t step = Downward ? std::size_t(0) - lanes : lanes;
            std::size_t at = Downward ? whole - lanes : 0;
            element current = load(at);
            for (std::size_t left = whole / lanes - 1; left != 0; --left, at += step) {
                const element next = load(at + step);
                if constexpr (Prefetch) prefetch_outputs(output.x, output.y, output.z, at, p.count);
                turn(current, at);
                current = next;
            }
            turn(current, at);
            done = whole;
        }
    }
    // As above; each output array may be any one of the input arrays.
#if defined(__clang__)
#pragma clang loop vectorize(assume_safety)
#elif defined(__GNUC__)
#pragma GCC ivdep
#endif
    for (std::size_t i = done; i < p.count; ++i) {
        const vec3<T> r = rotate_element(quaternion<T>{q.w[i], q.x[i], q.y[i], q.z[i]},
                                         vec3<T>{p.x[i], p.y[i], p.z[i]});
        output.x[i] = r.x;
        output.y[i] = r.y;
        output.z[i] = r.z;
    }
}

// rotate_each_soa out of cache (float, AVX builds): from the first element where output.x starts
// a cache line on (the first at most 15 plainly), the three output arrays are written with
// non-temporal stores straight from the registers, whole vectors where each array is aligned to
// one, else 16-byte pieces where each is 16-byte aligned (every malloc'd float array, at whatever
// offset into a line the heap put it): 40 bytes of memory traffic an element instead of 52, as
// for the array-of-structs form. The sweep runs upward or downward, whichever keeps its loads off
// the stores' 4K aliases (streaming_store.hpp), and stores plainly where neither does; the reach
// is eight steps of the loop, past which no offset measured slower. Zen 4, 4M elements (harness,
// medians of 15 interleaved calls): arrays as consecutive heap blocks put them (inputs 16 bytes
// apart modulo 4096, outputs after them) 1.36-1.56 ns an element downward against 2.08-2.21 plain
// and 4.49-4.51 upward (x86-64-v3), 1.18-1.56 against 1.75-2.08 and 1.87-2.12 (AVX-512).
#if defined(__AVX__)
[[gnu::noinline]] inline void rotate_each_soa_streaming(soa_quaternions<const float> q,
                                                        soa_points<const float> p,
                                                        soa_points<float> output) noexcept {
    const std::size_t head = elements_before_line(output.x, p.count);
    rotate_each_soa(soa_quaternions<const float>{q.w, q.x, q.y, q.z, head},
                    soa_points<const float>{p.x, p.y, p.z, head}, output);
    const std::size_t rest = p.count - head;
    const soa_quaternions<const float> q_rest{q.w + head, q.x + head, q.y + head, q.z + head, rest};
    const soa_points<const float> p_rest{p.x + head, p.y + head, p.z + head, rest};
    const soa_points<float> output_rest{output.x + head, output.y + head, output.z + head, rest};
    auto aligned = [&](std::size_t bytes) noexcept {
        return is_aligned(output_rest.x, bytes) && is_aligned(output_rest.y, bytes) &&
               is_aligned(output_rest.z, bytes);
    };
    const float* const inputs[] = {q_rest.w, q_rest.x, q_rest.y, q_rest.z,
                                   p_rest.x, p_rest.y, p_rest.z};
    const float* const outputs[] = {output_rest.x, output_rest.y, output_rest.z};
    const sweep way = aligned(16)
                          ? sweep_clear_of_aliasing(inputs, outputs, 8 * sizeof(wide_t<float>))
                          : sweep::neither;
    const bool whole = aligned(sizeof(wide_t<float>));
    if (way == sweep::upward && whole) {
        rotate_each_soa<stream_width>(q_rest, p_rest, output_rest);
    } else if (way == sweep::upward) {
        rotate_each_soa<4>(q_rest, p_rest, output_rest);
    } else if (way == sweep::downward && whole) {
        rotate_each_soa<stream_width, true>(q_rest, p_rest, output_rest);
    } else if (way == sweep::downward) {
        rotate_each_soa<4, true>(q_rest, p_rest, output_rest);
    } else {
        rotate_each_soa<0, false, true>(q_rest, p_rest, output_rest);
    }
    stream_fence();
}
#endif

template <class T>
void compose_each_loop(const quaternion<T>* a, const quaternion<T>* b, quaternion<T>* output,
                       std::size_t count, std::size_t done = 0) noexcept {
    // In place (output == a or b) is safe as in rotate_each_loop.
#if defined(__clang__)
#pragma clang loop vectorize(assume_safety)
#elif defined(__GNUC__)
#pragma GCC ivdep
#endif
    for (std::size_t i = done; i < count; ++i) {
        const quaternion<T> r = a[i] * b[i];
        output[i].w = r.w;
        output[i].x = r.x;
        output[i].y = r.y;
        output[i].z = r.z;
    }
}

#if defined(__clang__)
#pragma clang diagnostic pop
#endif

// rotate_each_loop in two steps: each block of elements is copied to local component arrays, which
// the struct-of-arrays loop turns, and copied back. In SSE2 builds, where g++ 12 splits the one
// loop into 4-wide pieces and shuffles, this took 2.1 us per 1024 elements against 4.5 (clang 14:
// 1.7 against 1.9); with AVX2 and AVX-512 the one loop is faster (g++: 1.09 us against 1.24, and
// 0.63 against 0.77); rotate_each/quat/quaternion/float/1024.
template <class T>
void rotate_each_blocks(const quaternion<T>* rotations, const vec3<T>* points, vec3<T>* output,
                        std::size_t count) noexcept {
    constexpr std::size_t block = 64;
    for (std::size_t start = 0; start < count; start += block) {
        const std::size_t n = count - start < block ? count - start : block;
        T w[block], x[block], y[block], z[block], px[block], py[block], pz[block];
        for (std::size_t i = 0; i < n; ++i) {
            w[i] = rotations[start + i].w;
            x[i] = rotations[start + i].x;
            y[i] = rotations[start + i].y;
            z[i] = rotations[start + i].z;
        }
        for (std::size_t i = 0; i < n; ++i) {
            px[i] = points[start + i].x;
            py[i] = points[start + i].y;
            pz[i] = points[start + i].z;
        }
        rotate_each_soa(soa_quaternions<const T>{w, x, y, z, n}, soa_points<const T>{px, py, pz, n},
                        soa_points<T>{px, py, pz, n});
        for (std::size_t i = 0; i < n; ++i) {
            output[start + i].x = px[i];
            output[start + i].y = py[i];
            output[start + i].z = pz[i];
        }
    }
}

// rotate_each out of cache (float, AVX builds): the points are written with non-temporal stores
// straight from the kernels' registers, as transform_streaming writes rotate's, from a 64-byte
// boundary of the output on (the first at most 15 plainly, so that no cache line is written
// partly each way); the last few plainly. Each point's line is then written once, without the
// read for ownership a plain store makes: 40 bytes of memory traffic an element instead of 52.
// Zen 4, 4M elements (harness, medians of 21): 5.9-6.4 ms against 8.4-9.7 plain, GLM's loop
// 6.8-7.5 (AVX-512); 6.2-7.2 against 8.3-9.6, GLM 7.3-8.2 (x86-64-v3).
#if defined(__AVX__)
[[gnu::noinline]] inline void rotate_each_streaming(const quaternion<float>* rotations,
                                                    const vec3<float>* points, vec3<float>* output,
                                                    std::size_t count) noexcept {
    std::size_t done = elements_before_line(output, count);
    rotate_each_loop(rotations, points, output, done);
    if (is_aligned(output + done, 64))
        done +=
            rotate_each_kernels<true>(rotations + done, points + done, output + done, count - done);
    rotate_each_loop(rotations + done, points + done, output + done, count - done);
    stream_fence();
}
#endif

// compose_each out of cache (float, AVX builds): as rotate_each_streaming, the products written
// with non-temporal stores straight from the kernels' registers from a 64-byte boundary of the
// output on: 48 bytes of memory traffic a product instead of 64. Zen 4, 4M products (harness,
// medians of 21): 6.6-7.6 ms against 9.2-10.3 plain, GLM's loop 8.7-10.2 (AVX-512); 5.7-6.6
// against 8.7-9.5, GLM 8.3-9.0 (x86-64-v3).
#if defined(__AVX__)
[[gnu::noinline]] inline void compose_each_streaming(const quaternion<float>* a,
                                                     const quaternion<float>* b,
                                                     quaternion<float>* output,
                                                     std::size_t count) noexcept {
    std::size_t done = elements_before_line(output, count);
    compose_each_loop(a, b, output, done);
    if (is_aligned(output + done, 64))
        done += compose_each_kernels<true>(a + done, b + done, output + done, count - done);
    compose_each_loop(a, b, output, count, done);
    stream_fence();
}
#endif

template <class T>
void rotate_each_aos(const quaternion<T>* rotations, const vec3<T>* points, vec3<T>* output,
                     std::size_t count) noexcept {
#if defined(__AVX__)
    if constexpr (std::is_same_v<T, float>) {
        if (has_streaming_kernel && streams_output(count * sizeof(vec3<float>))) {
            rotate_each_streaming(rotations, points, output, count);
            return;
        }
    }
    const std::size_t done = rotate_each_kernels(rotations, points, output, count);
    rotate_each_loop(rotations + done, points + done, output + done, count - done);
#else
    const std::size_t done = rotate_each_kernels(rotations, points, output, count);
    rotate_each_blocks(rotations + done, points + done, output + done, count - done);
#endif
}

}  // namespace detail

/// output[i] = rotate(rotations[i], points[i]) for i < count (arrays of structs), for unit
/// rotations; output == points is allowed, other overlaps are not. Like rotate(q, v) it tolerates
/// |q|^2 = 1 + d with d small (the result is off by at most 2 d^2 |v|, unchecked); far from unit
/// the result is not a rotation of the point. For float and double the loop vectorizes and rounds
/// differently from rotate(q, v), within 4.2 eps |v| (measured); other scalars run rotate(q, v)'s
/// arithmetic.
template <class T>
void rotate_each(const quaternion<T>* rotations, const vec3<T>* points, vec3<T>* output,
                 std::size_t count) noexcept {
    QUAT_ASSERT(detail::same_or_disjoint(points, count * sizeof(vec3<T>), output,
                                         count * sizeof(vec3<T>)) &&
                    detail::disjoint(rotations, count * sizeof(quaternion<T>), output,
                                     count * sizeof(vec3<T>)),
                "quat::rotate_each: output partially overlaps an input");
    detail::rotate_each_aos(rotations, points, output, count);
}

/// Struct-of-arrays rotate_each: point (points.x[i], points.y[i], points.z[i]) turned by rotation
/// (rotations.w[i], ...), by the arithmetic of the array-of-structs form (equal up to how the
/// compiler fuses multiply-adds). Each output array may be one of the input arrays or overlap
/// none. Preconditions: rotations.count == points.count <= output.count; unit rotations as for the
/// array-of-structs form.
template <class T>
void rotate_each(soa_quaternions<const detail::type_identity_t<T>> rotations,
                 soa_points<const detail::type_identity_t<T>> points,
                 soa_points<T> output) noexcept {
    QUAT_ASSERT(rotations.count == points.count,
                "quat::rotate_each: rotations and points differ in size");
    QUAT_ASSERT(output.count >= points.count, "quat::rotate_each: output shorter than the input");
    QUAT_ASSERT(detail::soa_same_or_disjoint({rotations.w, rotations.x, rotations.y, rotations.z,
                                              points.x, points.y, points.z},
                                             output, points.count),
                "quat::rotate_each: an output array partially overlaps an input array");
#if defined(__AVX__)
    if constexpr (std::is_same_v<T, float> && detail::stream_width == detail::wide_count<float>) {
        if (detail::streams_output(3 * points.count * sizeof(float))) {
            detail::rotate_each_soa_streaming(rotations, points, output);
            return;
        }
    }
#endif
    if (detail::has_wide_lanes<T> && 10 * points.count * sizeof(T) > detail::prefetch_bytes) {
        detail::rotate_each_soa<0, false, true>(rotations, points, output);
        return;
    }
    detail::rotate_each_soa(rotations, points, output);
}

/// Container form of rotate_each: contiguous rotations (quaternion<T>) and points, any contiguous
/// output of vec3<T>. Preconditions: size(rotations) == size(points) <= size(output) (QUAT_ASSERT);
/// unchecked, the common length of the three, never past any of them.
template <class Rotations, class Points, class Output,
          class T = detail::element_scalar_t<quaternion, Rotations>,
          class = detail::if_arrays_of<vec3<T>, vec3<T>, Points, Output>>
void rotate_each(const Rotations& rotations, const Points& points, Output&& output) noexcept {
    QUAT_ASSERT(detail::size_of(rotations) == detail::size_of(points),
                "quat::rotate_each: rotations and points differ in size");
    QUAT_ASSERT(detail::size_of(output) >= detail::size_of(points),
                "quat::rotate_each: output shorter than the input");
    rotate_each(detail::data_of(rotations), detail::data_of(points), detail::data_of(output),
                detail::common_size(rotations, points, output));
}

/// output[i] = a[i] * b[i] for i < count: as rotations, b[i] applies first (Hamilton product).
/// output may be exactly a or b (or both); other overlaps are not allowed. The results are those
/// of operator*, any unit or non-unit input.
template <class T>
void compose_each(const quaternion<T>* a, const quaternion<T>* b, quaternion<T>* output,
                  std::size_t count) noexcept {
    QUAT_ASSERT(detail::same_or_disjoint(a, count * sizeof(quaternion<T>), output,
                                         count * sizeof(quaternion<T>)) &&
                    detail::same_or_disjoint(b, count * sizeof(quaternion<T>), output,
                                             count * sizeof(quaternion<T>)),
                "quat::compose_each: output partially overlaps an input");
#if defined(__AVX__)
    if constexpr (std::is_same_v<T, float>) {
        if (detail::has_streaming_kernel &&
            detail::streams_output(count * sizeof(quaternion<float>))) {
            detail::compose_each_streaming(a, b, output, count);
            return;
        }
    }
#endif
    const std::size_t done = detail::compose_each_kernels(a, b, output, count);
    detail::compose_each_loop(a, b, output, count, done);
}

/// Container form of compose_each. Preconditions: size(a) == size(b) <= size(output) (QUAT_ASSERT);
/// unchecked, the common length of the three, never past any of them.
template <class A, class B, class Output, class T = detail::element_scalar_t<quaternion, A>,
          class = detail::if_arrays_of<quaternion<T>, quaternion<T>, B, Output>>
void compose_each(const A& a, const B& b, Output&& output) noexcept {
    QUAT_ASSERT(detail::size_of(a) == detail::size_of(b),
                "quat::compose_each: a and b differ in size");
    QUAT_ASSERT(detail::size_of(output) >= detail::size_of(a),
                "quat::compose_each: output shorter than the input");
    compose_each(detail::data_of(a), detail::data_of(b), detail::data_of(output),
                 detail::common_size(a, b, output));
}

/// output[i] = to_matrix(q[i]) for i < count, for unit q[i] (unchecked: a non-unit q gives a matrix
/// that is not a rotation). output must not overlap q.
template <class T>
void to_matrix_each(const quaternion<T>* q, rotation_matrix<T>* output,
                    std::size_t count) noexcept {
    QUAT_ASSERT(detail::disjoint(q, count * sizeof(quaternion<T>), output,
                                 count * sizeof(rotation_matrix<T>)),
                "quat::to_matrix_each: output overlaps the input");
    const std::size_t done = detail::to_matrix_each_kernels(q, output, count);
    // The rest counted from 0, as detail::transform_block's tail, for the same g++ warning.
    for (std::size_t i = 0, rest = count - done; i < rest; ++i) {
        const quaternion<T> r = q[done + i];
        output[done + i] = detail::scaled_matrix(r, r.x + r.x, r.y + r.y, r.z + r.z);
    }
}

/// Container form of to_matrix_each. Precondition: size(output) >= size(q) (QUAT_ASSERT);
/// unchecked, the first min(size(q), size(output)).
template <class Rotations, class Output, class T = detail::element_scalar_t<quaternion, Rotations>,
          class = detail::if_arrays_of<quaternion<T>, rotation_matrix<T>, Rotations, Output>>
void to_matrix_each(const Rotations& q, Output&& output) noexcept {
    QUAT_ASSERT(detail::size_of(output) >= detail::size_of(q),
                "quat::to_matrix_each: output shorter than the input");
    to_matrix_each(detail::data_of(q), detail::data_of(output), detail::common_size(q, output));
}

/// output[i] = to_quaternion(m[i]) for i < count (w >= 0). Precondition: rotation matrices, as for
/// the scalar to_quaternion; output must not overlap m.
template <class T>
void to_quaternion_each(const rotation_matrix<T>* m, quaternion<T>* output,
                        std::size_t count) noexcept {
    QUAT_ASSERT(detail::disjoint(m, count * sizeof(rotation_matrix<T>), output,
                                 count * sizeof(quaternion<T>)),
                "quat::to_quaternion_each: output overlaps the input");
    const std::size_t done = detail::to_quaternion_each_kernels(m, output, count);
    for (std::size_t i = 0, rest = count - done; i < rest; ++i)
        output[done + i] = to_quaternion(m[done + i]);
}

/// Container form of to_quaternion_each. Precondition: size(output) >= size(m) (QUAT_ASSERT);
/// unchecked, the first min(size(m), size(output)).
template <class Matrices, class Output,
          class T = detail::element_scalar_t<rotation_matrix, Matrices>,
          class = detail::if_arrays_of<rotation_matrix<T>, quaternion<T>, Matrices, Output>>
void to_quaternion_each(const Matrices& m, Output&& output) noexcept {
    QUAT_ASSERT(detail::size_of(output) >= detail::size_of(m),
                "quat::to_quaternion_each: output shorter than the input");
    to_quaternion_each(detail::data_of(m), detail::data_of(output), detail::common_size(m, output));
}

}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_BATCH_ELEMENTWISE_HPP_INCLUDED
