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
// vectorize them (checked with -fopt-info-vec and objdump); the float array-of-structs rotate_each
// of AVX and AVX2 builds spells its shuffles out instead (rotate_each_interleaved below), since
// the compiled loop is bound by its lane-crossing permutes. to_matrix_each and to_quaternion_each
// run the scalar conversions element by element: vectorized versions (blocks of matrices regrouped
// through local arrays, a branch-free to_quaternion) measured slower than these loops for SSE2
// and AVX2 with g++ 12, and 1.2 to 1.6 times faster only with AVX-512 (to_matrix slower there
// with clang 14): g++ has no cheap way to regroup the nine interleaved entries of a matrix. Where
// a result is "the scalar one", it may still differ in the last bit where the compiler fuses
// multiply-adds differently in the two places (-ffp-contract).
//
// Arrays are passed as pointer + count or as contiguous containers (data() and size(), C arrays),
// as in batch/rotations.hpp; the struct-of-arrays views are batch/soa.hpp's. Aliasing: an output
// may be exactly an
// input of its own type (in place) or overlap no input; it may never overlap an input of another
// type. A partial overlap is a precondition violation: QUAT_ASSERT reports it in debug builds (a
// constant number of pointer range comparisons per call); with NDEBUG the values written are
// unspecified. Like all of quat's functions they live in the instruction-set namespace
// (detail/math.hpp).
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
#include "detail/interleaved_points_avx.hpp"
#include "detail/overlap.hpp"
#include "detail/wide_lanes.hpp"
#include "soa.hpp"

namespace quat {
#include "../detail/isa_namespace.inc"
namespace detail {

// rotate(q, v) is M v with M = I + s (w [u]x + [u]x^2), u = (x, y, z), s = 4 - 2 |q|^2 (2 / |q|^2
// to first order). Applied without forming M, as v + s (w t + u x t) with t = u x v: 24 operations
// instead of 45, the same tolerance of |q| near 1, other roundings: over 200000 random pairs it
// differs from rotate(q, v) by at most 4.2 eps |v| per component (float and double, g++ and clang,
// SSE2 to AVX-512) and from the exact rotation by 4.2 eps |v|, against 3.3 for rotate(q, v).
// The arithmetic of rotate_factored on any lanes: a scalar, or a vector of GCC/clang vector
// extensions for the kernels that vectorize by hand, so every path rounds alike.
template <class V>
constexpr void rotate_factored_lanes(V w, V x, V y, V z, V vx, V vy, V vz, V& rx, V& ry,
                                     V& rz) noexcept {
    const V n2 = w * w + x * x + y * y + z * z;
    const V scale = 4 - (n2 + n2);
    const V tx = y * vz - z * vy, ty = z * vx - x * vz, tz = x * vy - y * vx;
    rx = vx + (tx * w + (y * tz - z * ty)) * scale;
    ry = vy + (ty * w + (z * tx - x * tz)) * scale;
    rz = vz + (tz * w + (x * ty - y * tx)) * scale;
}

template <class T>
[[nodiscard]] constexpr vec3<T> rotate_factored(const quaternion<T>& q, const vec3<T>& v) noexcept {
    vec3<T> r{};
    rotate_factored_lanes(q.w, q.x, q.y, q.z, v.x, v.y, v.z, r.x, r.y, r.z);
    return r;
}

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

template <class T>
void rotate_each_soa(soa_quaternions<const T> q, soa_points<const T> p,
                     soa_points<T> output) noexcept {
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
            store_wide(output.x + at, rx);
            store_wide(output.y + at, ry);
            store_wide(output.z + at, rz);
        };
        const std::size_t whole = p.count - p.count % lanes;  // as in detail::transform_block
        if (whole != 0) {
            element current = load(0);
            for (; done + lanes < whole; done += lanes) {
                const element next = load(done + lanes);
                turn(current, done);
                current = next;
            }
            turn(current, done);
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

#if defined(__AVX__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
// rotate_each of float elements [0, n - n % 8) in AVX builds, 8 a step, with the shuffles spelled
// out as in interleaved_points_avx.hpp (whose helpers it uses), and returns how many it did. Each
// 128-bit lane holds 4 whole elements (elements 0-3 in the low lanes, 4-7 in the high ones), so
// every shuffle stays in its lane: the quaternions by a 4x4 transpose (8 unpacks), the points in
// and out by 3 permutes and 6 blends each; 26 shuffles per 8 elements where g++ 12 compiles the
// plain loop (and GLM's and Eigen's) with 53-54 lane-crossing permutes, the bound of those loops.
// The arithmetic is rotate_factored's, term for term. out == p is safe: each group is read whole
// before it is written. AVX-512 builds run rotate_each_interleaved_16 below and this kernel for a
// remaining 8.
[[nodiscard]] inline std::size_t rotate_each_interleaved(const float* q, const float* p, float* out,
                                                         std::size_t n) noexcept {
    auto load = [](const float* low, const float* high) noexcept {
        const float4 lower = load4(low);
        return __builtin_ia32_vinsertf128_ps256(
            __builtin_shufflevector(lower, lower, 0, 1, 2, 3, -1, -1, -1, -1), load4(high), 1);
    };
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        const float* r = q + 4 * i;
        const float8 e0 = load(r, r + 16), e1 = load(r + 4, r + 20), e2 = load(r + 8, r + 24),
                     e3 = load(r + 12, r + 28);
        // Per lane: t0 = w0 w1 x0 x1, t1 = y0 y1 z0 z1, t2 = w2 w3 x2 x3, t3 = y2 y3 z2 z3.
        const float8 t0 = __builtin_shufflevector(e0, e1, 0, 8, 1, 9, 4, 12, 5, 13);
        const float8 t1 = __builtin_shufflevector(e0, e1, 2, 10, 3, 11, 6, 14, 7, 15);
        const float8 t2 = __builtin_shufflevector(e2, e3, 0, 8, 1, 9, 4, 12, 5, 13);
        const float8 t3 = __builtin_shufflevector(e2, e3, 2, 10, 3, 11, 6, 14, 7, 15);
        const float8 w = __builtin_shufflevector(t0, t2, 0, 1, 8, 9, 4, 5, 12, 13);
        const float8 x = __builtin_shufflevector(t0, t2, 2, 3, 10, 11, 6, 7, 14, 15);
        const float8 y = __builtin_shufflevector(t1, t3, 0, 1, 8, 9, 4, 5, 12, 13);
        const float8 z = __builtin_shufflevector(t1, t3, 2, 3, 10, 11, 6, 7, 14, 15);
        const float* s = p + 3 * i;
        const float8 a = load(s, s + 12), b = load(s + 4, s + 16), c = load(s + 8, s + 20);
        const float8 vx = swap_1_3(blend_1_5(blend_2_6(a, b), c));
        const float8 vy = swap_pairs(blend_2_6(blend_0_3_4_7(a, b), c));
        const float8 vz = swap_0_2(blend_0_3_4_7(blend_1_5(a, b), c));
        float8 rx, ry, rz;
        rotate_factored_lanes(w, x, y, z, vx, vy, vz, rx, ry, rz);
        const float8 px = swap_1_3(rx), py = swap_pairs(ry), pz = swap_0_2(rz);
        const float8 ra = blend_2_6(blend_1_5(px, py), pz);
        const float8 rb = blend_2_6(blend_1_5(py, pz), px);
        const float8 rc = blend_2_6(blend_1_5(pz, px), py);
        float* o = out + 3 * i;
        store4(o, __builtin_ia32_vextractf128_ps256(ra, 0));
        store4(o + 4, __builtin_ia32_vextractf128_ps256(rb, 0));
        store4(o + 8, __builtin_ia32_vextractf128_ps256(rc, 0));
        store4(o + 12, __builtin_ia32_vextractf128_ps256(ra, 1));
        store4(o + 16, __builtin_ia32_vextractf128_ps256(rb, 1));
        store4(o + 20, __builtin_ia32_vextractf128_ps256(rc, 1));
    }
    return i;
}
#endif
#endif

#if defined(__AVX512F__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
// rotate_each of float elements [0, n - n % 16) in AVX-512 builds, 16 a step, and how many it did.
// A quaternion is one 128-bit lane, so the 4x4 transpose that separates w, x, y and z of 16 of them
// (4 registers) is 8 in-lane unpacks; it leaves element each_element(l) in lane l, not element l.
// The points are separated into that same lane order, and their results joined back from it, by
// two-source permutes (vpermt2ps) of any order: 2 per coordinate each way. 20 shuffles per 16
// elements, where g++ 12 compiles the plain loop with 4 times as many lane-crossing permutes. The
// arithmetic is rotate_factored's, term for term. out == p is safe: each group is read whole before
// it is written.
[[nodiscard]] constexpr int each_element(int lane) noexcept { return lane / 4 + 4 * (lane % 4); }
[[nodiscard]] constexpr int each_lane(int element) noexcept {
    return 4 * (element % 4) + element / 4;
}
// Float f (0-47) of a group of points, as a shuffle index into the pair (a, b) and then into the
// pair (that result, c): lanes whose float is in c keep their place in the first step.
[[nodiscard]] constexpr int first_of_pair(int f) noexcept { return f < 32 ? f : 0; }
[[nodiscard]] constexpr int second_of_pair(int f, int lane) noexcept {
    return f < 32 ? lane : f - 16;
}
// Coordinate k of lane l's point, and the lane of output float g's element.
[[nodiscard]] constexpr int point_float(int lane, int k) noexcept {
    return 3 * each_element(lane) + k;
}
[[nodiscard]] constexpr int result_lane(int g) noexcept { return each_lane(g / 3); }

// Coordinate K of the 16 points in registers a, b, c, in each_element's lane order.
template <int K, int... L>
[[nodiscard]] inline float16 gather_coordinate(float16 a, float16 b, float16 c,
                                               std::integer_sequence<int, L...>) noexcept {
    const float16 ab = __builtin_shufflevector(a, b, first_of_pair(point_float(L, K))...);
    return __builtin_shufflevector(ab, c, second_of_pair(point_float(L, K), L)...);
}
// Output register R (floats 16 R ... 16 R + 15 of the group) from the coordinates in lane order.
template <int R, int... L>
[[nodiscard]] inline float16 join_coordinates(float16 x, float16 y, float16 z,
                                              std::integer_sequence<int, L...>) noexcept {
    const float16 xy =
        __builtin_shufflevector(x, y,
                                ((16 * R + L) % 3 == 0   ? result_lane(16 * R + L)
                                 : (16 * R + L) % 3 == 1 ? 16 + result_lane(16 * R + L)
                                                         : L)...);
    return __builtin_shufflevector(xy, z,
                                   ((16 * R + L) % 3 == 2 ? 16 + result_lane(16 * R + L) : L)...);
}

// Rows a, b, c, d of the 4x4 matrix in each 128-bit lane, transposed in place: 8 in-lane unpacks.
// Its own inverse.
inline void transpose_in_lanes(float16& a, float16& b, float16& c, float16& d) noexcept {
    const float16 t0 =
        __builtin_shufflevector(a, b, 0, 16, 1, 17, 4, 20, 5, 21, 8, 24, 9, 25, 12, 28, 13, 29);
    const float16 t1 =
        __builtin_shufflevector(a, b, 2, 18, 3, 19, 6, 22, 7, 23, 10, 26, 11, 27, 14, 30, 15, 31);
    const float16 t2 =
        __builtin_shufflevector(c, d, 0, 16, 1, 17, 4, 20, 5, 21, 8, 24, 9, 25, 12, 28, 13, 29);
    const float16 t3 =
        __builtin_shufflevector(c, d, 2, 18, 3, 19, 6, 22, 7, 23, 10, 26, 11, 27, 14, 30, 15, 31);
    a = __builtin_shufflevector(t0, t2, 0, 1, 16, 17, 4, 5, 20, 21, 8, 9, 24, 25, 12, 13, 28, 29);
    b = __builtin_shufflevector(t0, t2, 2, 3, 18, 19, 6, 7, 22, 23, 10, 11, 26, 27, 14, 15, 30, 31);
    c = __builtin_shufflevector(t1, t3, 0, 1, 16, 17, 4, 5, 20, 21, 8, 9, 24, 25, 12, 13, 28, 29);
    d = __builtin_shufflevector(t1, t3, 2, 3, 18, 19, 6, 7, 22, 23, 10, 11, 26, 27, 14, 15, 30, 31);
}
// 16 quaternions (64 floats) as w, x, y and z of 16 lanes each, element each_element(l) in lane l,
// and back: a quaternion is one 128-bit lane, so this is a 4x4 transpose in each.
[[nodiscard]] inline quaternion<float16> load_quaternions16(const float* q) noexcept {
    quaternion<float16> r{load16(q), load16(q + 16), load16(q + 32), load16(q + 48)};
    transpose_in_lanes(r.w, r.x, r.y, r.z);
    return r;
}
inline void store_quaternions16(float* out, quaternion<float16> r) noexcept {
    transpose_in_lanes(r.w, r.x, r.y, r.z);
    std::memcpy(out, &r.w, sizeof r.w);
    std::memcpy(out + 16, &r.x, sizeof r.x);
    std::memcpy(out + 32, &r.y, sizeof r.y);
    std::memcpy(out + 48, &r.z, sizeof r.z);
}

// compose_each of float elements [0, n - n % 16) in AVX-512 builds, and how many it did: operator*
// itself on 16 lanes, between two transposes in and one out (24 in-lane unpacks and 16 multiplies
// per 16 products, where g++ 12 compiles the plain loop with lane-crossing permutes). Output may be
// a or b: each group is read whole before it is written.
[[nodiscard]] inline std::size_t compose_each_interleaved_16(const float* a, const float* b,
                                                             float* out, std::size_t n) noexcept {
    std::size_t i = 0;
    for (; i + 16 <= n; i += 16)
        store_quaternions16(out + 4 * i,
                            load_quaternions16(a + 4 * i) * load_quaternions16(b + 4 * i));
    return i;
}

[[nodiscard]] inline std::size_t rotate_each_interleaved_16(const float* q, const float* p,
                                                            float* out, std::size_t n) noexcept {
    constexpr auto lanes = std::make_integer_sequence<int, 16>{};
    std::size_t i = 0;
    for (; i + 16 <= n; i += 16) {
        const quaternion<float16> r = load_quaternions16(q + 4 * i);
        const float16 w = r.w, x = r.x, y = r.y, z = r.z;
        const float* s = p + 3 * i;
        const float16 a = load16(s), b = load16(s + 16), c = load16(s + 32);
        const float16 vx = gather_coordinate<0>(a, b, c, lanes);
        const float16 vy = gather_coordinate<1>(a, b, c, lanes);
        const float16 vz = gather_coordinate<2>(a, b, c, lanes);
        float16 rx, ry, rz;
        rotate_factored_lanes(w, x, y, z, vx, vy, vz, rx, ry, rz);
        const float16 ra = join_coordinates<0>(rx, ry, rz, lanes);
        const float16 rb = join_coordinates<1>(rx, ry, rz, lanes);
        const float16 rc = join_coordinates<2>(rx, ry, rz, lanes);
        float* o = out + 3 * i;
        std::memcpy(o, &ra, sizeof ra);
        std::memcpy(o + 16, &rb, sizeof rb);
        std::memcpy(o + 32, &rc, sizeof rc);
    }
    return i;
}
#endif
#endif

template <class T>
void rotate_each_aos(const quaternion<T>* rotations, const vec3<T>* points, vec3<T>* output,
                     std::size_t count) noexcept {
    // No non-temporal stores beyond the caches, unlike batch/rotations.hpp's rotate: over 4M
    // elements they measured the same as plain stores in AVX-512 builds (13.9-14.1 ms against
    // 13.8-14.5 ms; GLM's loop 13.3-13.7, memcpy of the same bytes 11.7-12.9) and slower with AVX2.
#if defined(__AVX__)
    std::size_t done = 0;
#if defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
    if constexpr (std::is_same_v<T, float>) {
        static_assert(sizeof(quaternion<float>) == 4 * sizeof(float) &&
                          sizeof(vec3<float>) == 3 * sizeof(float),
                      "packed quaternions and points");
#if defined(__AVX512F__)
        if (count >= 16)
            done = rotate_each_interleaved_16(&rotations[0].w, &points[0].x, &output[0].x, count);
#endif
        if (count - done >= 8)
            done += rotate_each_interleaved(&rotations[done].w, &points[done].x, &output[done].x,
                                            count - done);
    }
#endif
#endif
    rotate_each_loop(rotations + done, points + done, output + done, count - done);
#else
    rotate_each_blocks(rotations, points, output, count);
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
    std::size_t done = 0;
#if defined(__AVX512F__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
    if constexpr (std::is_same_v<T, float>) {
        static_assert(sizeof(quaternion<float>) == 4 * sizeof(float), "packed quaternions");
        if (count >= 16)
            done = detail::compose_each_interleaved_16(&a[0].w, &b[0].w, &output[0].w, count);
    }
#endif
#endif
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
    for (std::size_t i = 0; i < count; ++i) {
        const quaternion<T> r = q[i];
        output[i] = detail::scaled_matrix(r, r.x + r.x, r.y + r.y, r.z + r.z);
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
    for (std::size_t i = 0; i < count; ++i) output[i] = to_quaternion(m[i]);
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
