// The loops that move many points by one matrix, output[i] = m input[i] (+ t): the batch rotate
// (batch/rotations.hpp) and the batch rigid transform (batch/rigid_motions.hpp), for arrays of
// structs and struct of arrays. Plain loops that compilers vectorize; the float array-of-structs
// loop of AVX builds spells its shuffles out (interleaved_points_avx.hpp), and float arrays that
// with their input exceed the last-level cache are written on x86 with non-temporal stores
// (streaming_store.hpp).
#ifndef QUAT_BATCH_DETAIL_TRANSFORM_POINTS_HPP_INCLUDED
#define QUAT_BATCH_DETAIL_TRANSFORM_POINTS_HPP_INCLUDED

#include <cstddef>
#include <type_traits>

#include "../../rotation_matrix.hpp"
#include "../../vec3.hpp"
#include "../soa.hpp"
#include "interleaved_points_avx.hpp"
#include "interleaved_points_neon.hpp"
#include "streaming_store.hpp"
#include "wide_lanes.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

// Points per block where a block is computed into a local buffer first: the streaming rotation.
inline constexpr std::size_t batch_block = 256;

// The loops below ask clang to vectorize; where it cannot (at -O1 with the sanitizers, for one),
// its -Wpass-failed warning would break -Werror builds of user code, so it is silenced here.
#if defined(__clang__)
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wpass-failed"
#endif

// output[i] = m input[i], plus t when Translate (rigid motions); rotate passes Translate = false,
// so its results carry no added zero.
template <bool Translate, class T>
void transform_block(const rotation_matrix<T>& m, const vec3<T>& t, const vec3<T>* input,
                     vec3<T>* output, std::size_t n) noexcept {
    std::size_t done = 0;
    // Float: groups of 16 and 8 points by the explicit shuffles of interleaved_points_avx.hpp in
    // AVX builds, of 4 by interleaved_points_neon.hpp on AArch64, the rest (all of it elsewhere)
    // below.
    if constexpr (std::is_same_v<T, float>) {
        static_assert(sizeof(vec3<float>) == 3 * sizeof(float),
                      "vec3<float> must be three packed floats");
        if (n >= 8)
            done = transform_interleaved_floats<Translate>(m, t, &input[0].x, &output[0].x, n);
        if (n >= 4 && done == 0)
            done = transform_interleaved_neon<Translate>(m, t, &input[0].x, &output[0].x, n);
        // The matrix's entries are read for the loop below only after the kernels, which keeps
        // the compiler from holding (and spilling) them across the kernels' calls: with them read
        // first, 64 points took 10 ns more than a plain loop.
        if (done == n) return;
    }
    const T m00 = m(0, 0), m01 = m(0, 1), m02 = m(0, 2), m10 = m(1, 0), m11 = m(1, 1),
            m12 = m(1, 2), m20 = m(2, 0), m21 = m(2, 1), m22 = m(2, 2);
    const T tx = t.x, ty = t.y, tz = t.z;
    // Point i is read before it is written and no iteration touches another's point, so the
    // in-place call is safe with vectorization; tell the compiler, saving its overlap check. The
    // index counts the rest from 0: from done, g++ 12 warned of an overflowing iteration when n
    // is the constant 1024 (-Waggressive-loop-optimizations, x86-64-v3).
#if defined(__clang__)
#pragma clang loop vectorize(assume_safety)
#elif defined(__GNUC__)
#pragma GCC ivdep
#endif
    for (std::size_t i = 0, rest = n - done; i < rest; ++i) {
        const T x = input[done + i].x, y = input[done + i].y, z = input[done + i].z;
        T ox = m00 * x + m01 * y + m02 * z, oy = m10 * x + m11 * y + m12 * z,
          oz = m20 * x + m21 * y + m22 * z;
        if constexpr (Translate) {
            ox += tx;
            oy += ty;
            oz += tz;
        }
        output[done + i] = vec3<T>{ox, oy, oz};
    }
}

// Writes the points with non-temporal stores. The first points (at most 15) are stored plainly
// up to a 64-byte boundary of the output, so that no cache line is written partly by plain and
// partly by non-temporal stores. Then the AVX kernels stream straight from their registers
// (interleaved_points_avx.hpp); the rest (the last few points, or all of them for a build without
// the kernels, which transform_points does not stream) is computed block by block into a local
// buffer, which is streamed to memory: blocks of 16 points are 192 bytes, three whole lines. The
// points are one float array (vec3<float> is three floats with no padding). Measured on a Zen 4
// (4M points, g++ 12, medians of 11): unaligned blocks 4.3-6.3 ms, aligned blocks 3.5-3.8,
// streamed from the kernel 3.2-3.5; a streaming copy of the same bytes 3.2-3.4.
template <bool Translate>
void transform_streaming(const rotation_matrix<float>& m, const vec3<float>& t,
                         const vec3<float>* input, vec3<float>* output,
                         std::size_t count) noexcept {
    static_assert(sizeof(vec3<float>) == 3 * sizeof(float),
                  "vec3<float> must be three packed floats");
    static_assert(batch_block % 16 == 0, "blocks of whole cache lines");
    std::size_t start = elements_before_line(output, count);
    transform_block<Translate>(m, t, input, output, start);
    if (is_aligned(output + start, 16))
        start += transform_interleaved_floats<Translate, true>(m, t, &input[start].x,
                                                               &output[start].x, count - start);
    alignas(64) vec3<float> buffer[batch_block];
    for (; start < count; start += batch_block) {
        const std::size_t n = count - start < batch_block ? count - start : batch_block;
        transform_block<Translate>(m, t, input + start, buffer, n);
        stream_floats(&output[start].x, &buffer[0].x, 3 * n);
    }
    stream_fence();
}

// With Prefetch, the vector loop asks for its output lines ahead of its stores (prefetch_outputs).
template <bool Translate, class T, bool Prefetch = false>
void transform_block(const rotation_matrix<T>& m, const vec3<T>& t, const T* x, const T* y,
                     const T* z, T* ox, T* oy, T* oz, std::size_t n) noexcept {
    const T m00 = m(0, 0), m01 = m(0, 1), m02 = m(0, 2), m10 = m(1, 0), m11 = m(1, 1),
            m12 = m(1, 2), m20 = m(2, 0), m21 = m(2, 1), m22 = m(2, 2);
    const T tx = t.x, ty = t.y, tz = t.z;
    std::size_t done = 0;
    // Whole vectors of lanes written out (detail/wide_lanes.hpp says why), in the same order of
    // operations as the loop below, which does the rest. Each step loads the next vector of each
    // array before it stores its own results: where an output array starts a little past an input
    // array modulo 4096 bytes (arrays of 1024 floats allocated one after another), a load that
    // follows a store to the same page offset waits for it (4K aliasing). 1024 points: 88 ns
    // against 110 storing first, and 300 with each input loaded again for every multiply-add (as
    // g++ compiled the loop without the carried registers).
    if constexpr (has_wide_lanes<T>) {
        using V = wide_t<T>;
        constexpr std::size_t lanes = wide_count<T>;
        const V w00 = broadcast_wide(m00), w01 = broadcast_wide(m01), w02 = broadcast_wide(m02),
                w10 = broadcast_wide(m10), w11 = broadcast_wide(m11), w12 = broadcast_wide(m12),
                w20 = broadcast_wide(m20), w21 = broadcast_wide(m21), w22 = broadcast_wide(m22);
        const V wx = broadcast_wide(tx), wy = broadcast_wide(ty), wz = broadcast_wide(tz);
        auto move = [&](V px, V py, V pz, std::size_t at) noexcept {
            V rx = w00 * px + w01 * py + w02 * pz, ry = w10 * px + w11 * py + w12 * pz,
              rz = w20 * px + w21 * py + w22 * pz;
            if constexpr (Translate) {
                rx += wx;
                ry += wy;
                rz += wz;
            }
            store_wide(ox + at, rx);
            store_wide(oy + at, ry);
            store_wide(oz + at, rz);
        };
        // The points in whole vectors, counted so that the loop below visibly does at most
        // lanes - 1 (g++ 12 for AArch64 otherwise warns of an overflowing iteration in it).
        const std::size_t whole = n - n % lanes;
        if (whole != 0) {
            V px = load_wide(x), py = load_wide(y), pz = load_wide(z);
            for (; done + lanes < whole; done += lanes) {
                const V nx = load_wide(x + done + lanes), ny = load_wide(y + done + lanes),
                        nz = load_wide(z + done + lanes);
                if constexpr (Prefetch) prefetch_outputs(ox, oy, oz, done, n);
                move(px, py, pz, done);
                px = nx, py = ny, pz = nz;
            }
            move(px, py, pz, done);
            done = whole;
        }
    }
    // Each index is read before it is written, so each output array may be its own input array, and
    // there is no dependence between iterations (the documented aliasing rule): say so to the
    // compiler, which otherwise gives up on overlap checks of six arrays and leaves the loop
    // scalar.
#if defined(__clang__)
#pragma clang loop vectorize(assume_safety)
#elif defined(__GNUC__)
#pragma GCC ivdep
#endif
    for (std::size_t i = done; i < n; ++i) {
        const T px = x[i], py = y[i], pz = z[i];
        T rx = m00 * px + m01 * py + m02 * pz, ry = m10 * px + m11 * py + m12 * pz,
          rz = m20 * px + m21 * py + m22 * pz;
        if constexpr (Translate) {
            rx += tx;
            ry += ty;
            rz += tz;
        }
        ox[i] = rx;
        oy[i] = ry;
        oz[i] = rz;
    }
}

#if defined(__clang__)
#pragma clang diagnostic pop
#endif

// A float batch of at least minimum_streaming_bytes: streamed where it exceeds the threshold,
// plainly below.
template <bool Translate>
[[gnu::noinline]] void transform_large(const rotation_matrix<float>& m, const vec3<float>& t,
                                       const vec3<float>* input, vec3<float>* output,
                                       std::size_t count) noexcept {
    if (streams_output(count * sizeof(vec3<float>))) {
        transform_streaming<Translate>(m, t, input, output, count);
        return;
    }
    transform_block<Translate>(m, t, input, output, count);
}

// output[i] = m input[i] (+ t when Translate) for i < count: the array-of-structs loop of rotate
// and of the rigid transform (batch/rigid_motions.hpp).
template <bool Translate, class T>
void transform_points(const rotation_matrix<T>& m, const vec3<T>& t, const vec3<T>* input,
                      vec3<T>* output, std::size_t count) noexcept {
    // Where input and output together exceed the last-level cache (streaming_threshold_bytes),
    // the AVX kernels write the points with non-temporal stores. Zen 4 with a 32 MiB L3 (g++ 12,
    // 4M points = 48 MiB each way, medians of 9): streamed 3.5-3.9 ms against 3.9-4.1 plain,
    // streaming copy 3.2-3.8. Builds without them (SSE2 to SSE4.2) store plainly at any size: a
    // block computed into a buffer and streamed afterwards does not overlap its arithmetic with
    // the memory writes, and on the Zen 4 it took 4.0 ms against 3.5 plain (GLM's loop 3.4-3.6;
    // transform 4.6 against 3.8), where a Xeon with a 480 MiB L3 had measured it 1.16x ahead of
    // plain for earlier code (5.7 ms against 6.6); plain runs level with the peers' loops on both.
    // A 4-point SSE kernel with the shuffles spelled out (17 shufps a group) streamed 4.1 ms and
    // ran 0.79x the plain loop in cache. The size is compared with the constant minimum first and
    // the cache size read out of line (transform_large), so that a small batch's path makes no
    // call that returns and g++ sets up no frame for it.
    if constexpr (std::is_same_v<T, float>) {
        if (has_streaming_kernel && count * sizeof(vec3<float>) >= minimum_streaming_bytes) {
            transform_large<Translate>(m, t, input, output, count);
            return;
        }
    }
    // Each point is read before it is written, so output == input is safe here; g++ and clang
    // vectorize this loop (3-way interleaved loads and stores) behind a run-time overlap check.
    transform_block<Translate>(m, t, input, output, count);
}

// The struct-of-arrays loop of rotate and of the rigid transform.
template <bool Translate, class T>
void transform_points(const rotation_matrix<T>& m, const vec3<T>& t, soa_points<const T> input,
                      soa_points<T> output) noexcept {
    if constexpr (std::is_same_v<T, float>) {
        if (streams_output(input.count * 3 * sizeof(float))) {
            // Out of cache: move a block into local arrays, then stream them (as for AoS), from a
            // 64-byte boundary of output.x on (usually that of y and z too: large arrays start at
            // the same offset into a page), so that the blocks cover whole cache lines.
            const std::size_t head = elements_before_line(output.x, input.count);
            transform_block<Translate>(m, t, input.x, input.y, input.z, output.x, output.y,
                                       output.z, head);
            alignas(64) float rx[batch_block];
            alignas(64) float ry[batch_block];
            alignas(64) float rz[batch_block];
            for (std::size_t start = head; start < input.count; start += batch_block) {
                const std::size_t n =
                    input.count - start < batch_block ? input.count - start : batch_block;
                transform_block<Translate>(m, t, input.x + start, input.y + start, input.z + start,
                                           rx, ry, rz, n);
                stream_floats(output.x + start, rx, n);
                stream_floats(output.y + start, ry, n);
                stream_floats(output.z + start, rz, n);
            }
            stream_fence();
            return;
        }
    }
    if (has_wide_lanes<T> && 6 * input.count * sizeof(T) > prefetch_bytes) {
        transform_block<Translate, T, true>(m, t, input.x, input.y, input.z, output.x, output.y,
                                            output.z, input.count);
        return;
    }
    transform_block<Translate>(m, t, input.x, input.y, input.z, output.x, output.y, output.z,
                               input.count);
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_BATCH_DETAIL_TRANSFORM_POINTS_HPP_INCLUDED
