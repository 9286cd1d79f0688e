// The element-wise batches of float arrays of structs in AVX and AVX-512 builds
// (batch/elementwise.hpp's rotate_each, compose_each and to_quaternion_each), to_quaternion_each
// in SSE2 builds without AVX, and rotate_each and compose_each in SSE4.1 builds without AVX, with
// the shuffles spelled out in GCC/clang vector extensions, as in interleaved_points_avx.hpp (whose
// helpers they use), because no compiler finds these arrangements from a plain loop. Each kernel
// does the elements [0, n - n % 4), [0, n - n % 8) or [0, n - n % 16) and returns how many it did;
// the caller's plain loop does the rest.
#ifndef QUAT_BATCH_DETAIL_INTERLEAVED_ELEMENTS_HPP_INCLUDED
#define QUAT_BATCH_DETAIL_INTERLEAVED_ELEMENTS_HPP_INCLUDED

#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

#include "../../conversions.hpp"
#include "../../detail/math.hpp"
#include "../../quaternion.hpp"
#include "../../rotation_matrix.hpp"
#include "factored_rotation.hpp"
#include "interleaved_points_avx.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

#if defined(__SSE2__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
#if defined(__AVX__)
// sse_lanes.hpp's sqrt_lanes on 8 and 16 lanes (vsqrtps).
[[nodiscard]] inline float8 sqrt_lanes(float8 x) noexcept { return __builtin_ia32_sqrtps256(x); }
#if defined(__AVX512F__)
[[nodiscard]] inline float16 sqrt_lanes(float16 x) noexcept {
    constexpr int current_rounding = 4;  // _MM_FROUND_CUR_DIRECTION
#if defined(__clang__)                   // g++ and clang name the builtin differently
    return __builtin_ia32_sqrtps512(x, current_rounding);
#else
    return __builtin_ia32_sqrtps512_mask(x, x, static_cast<short>(-1), current_rounding);
#endif
}
#endif

#endif

// a, b, c or d: the first whose case holds, d where none does (to_quaternion's if-else chain).
template <class V, class Mask>
[[nodiscard]] inline V select_case(const Mask (&cases)[3], V a, V b, V c, V d) noexcept {
    return select_lanes(cases[0], a, select_lanes(cases[1], b, select_lanes(cases[2], c, d)));
}

// to_quaternion of the matrices whose row-major entries are the lanes of e[0] ... e[8], into q,
// its branches turned into selects: the same four cases, chosen by the same comparisons in the
// same order, and the same arithmetic. False (q unspecified) when some lane's squared norm is
// outside the normal range (not a rotation: zero, NaN, huge), whose matrices the caller converts
// with to_quaternion itself, so that results equal the scalar ones whatever the input.
template <class V>
[[nodiscard]] inline bool quaternions_of_matrices(const V (&e)[9], quaternion<V>& q) noexcept {
    const V m00 = e[0], m01 = e[1], m02 = e[2], m10 = e[3], m11 = e[4], m12 = e[5], m20 = e[6],
            m21 = e[7], m22 = e[8];
    const V trace = m00 + m11 + m22;
    using Mask = decltype(trace < trace);
    const Mask cases[3] = {(trace >= m00) & (trace >= m11) & (trace >= m22),
                           (m00 >= m11) & (m00 >= m22), m11 >= m22};
    const V wx = m21 - m12, wy = m02 - m20, wz = m10 - m01;
    const V xy = m01 + m10, xz = m02 + m20, yz = m12 + m21;
    q = {select_case(cases, 1 + trace, wx, wy, wz),
         select_case(cases, wx, 1 + m00 - m11 - m22, xy, xz),
         select_case(cases, wy, xy, 1 - m00 + m11 - m22, yz),
         select_case(cases, wz, xz, yz, 1 - m00 - m11 + m22)};
    const V squared = squared_norm(q);
    const Mask normal = (squared >= smallest_normal<float>()) & (squared <= largest<float>());
    if (!all_lanes(normal)) return false;
    const V scale = 1 / sqrt_lanes(squared);
    q = q * select_lanes(q.w < 0, -scale, scale);
    return true;
}

// Rows a, b, c, d of a 4x4 matrix, transposed in place: 8 unpacks (the overloads below do the same
// in each 128-bit lane of wider registers). Its own inverse. On 4 quaternions (one a row), it
// separates w, x, y and z.
inline void transpose_in_lanes(float4& a, float4& b, float4& c, float4& d) noexcept {
    const float4 t0 = __builtin_shufflevector(a, b, 0, 4, 1, 5);
    const float4 t1 = __builtin_shufflevector(a, b, 2, 6, 3, 7);
    const float4 t2 = __builtin_shufflevector(c, d, 0, 4, 1, 5);
    const float4 t3 = __builtin_shufflevector(c, d, 2, 6, 3, 7);
    a = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
    b = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
    c = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
    d = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}

#if !defined(__AVX__)
// Entry C (row-major) of 4 matrices whose 36 floats lie in 9 registers: matrix k's entry (float
// 9 k + C) lies at position (k + C) % 4 of register (9 k + C) / 4, so two shuffles pair matrices
// 0 and 1, and 2 and 3, and a third joins the pairs in lane order.
template <int C>
[[nodiscard]] inline float4 matrix_entry4(const float4 (&r)[9]) noexcept {
    constexpr int p0 = C % 4, p1 = (1 + C) % 4, p2 = (2 + C) % 4, p3 = (3 + C) % 4;
    const float4 first = __builtin_shufflevector(r[C / 4], r[(9 + C) / 4], p0, p0, 4 + p1, 4 + p1);
    const float4 second =
        __builtin_shufflevector(r[(18 + C) / 4], r[(27 + C) / 4], p2, p2, 4 + p3, 4 + p3);
    return __builtin_shufflevector(first, second, 0, 2, 4, 6);
}

// to_quaternion_each of float matrices [0, n - n % 4) in SSE2 builds without AVX, 4 a step, and how
// many it did: the AVX kernels' conversion on 4 lanes, the entries separated by matrix_entry4 (27
// shuffles), the quaternions joined by a 4x4 transpose (8 unpacks). g++ 12 leaves to_quaternion's
// four-way branch in the plain loop, which random rotations mispredict: at plain x86-64 on a Zen
// 4, 4.90 ns a matrix over 1024 of them, against 3.78 for this kernel and 3.74 for GLM's
// quat_cast loop (quat_bench, medians of 3 runs); SSE2 has no blend, so each select is three.
[[nodiscard]] inline std::size_t to_quaternion_each_interleaved_4(const rotation_matrix<float>* m,
                                                                  quaternion<float>* out,
                                                                  std::size_t n) noexcept {
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {
        const float* s = &m[i](0, 0);
        float4 r[9];
        for (std::size_t j = 0; j < 9; ++j) r[j] = load4(s + 4 * j);
        const float4 entries[9] = {matrix_entry4<0>(r), matrix_entry4<1>(r), matrix_entry4<2>(r),
                                   matrix_entry4<3>(r), matrix_entry4<4>(r), matrix_entry4<5>(r),
                                   matrix_entry4<6>(r), matrix_entry4<7>(r), matrix_entry4<8>(r)};
        quaternion<float4> q;
        if (!quaternions_of_matrices(entries, q)) {
            for (std::size_t j = i; j < i + 4; ++j) out[j] = to_quaternion(m[j]);
            continue;
        }
        transpose_in_lanes(q.w, q.x, q.y, q.z);  // q.w: quaternion 0, q.x: quaternion 1, ...
        float* o = &out[i].w;
        store4(o, q.w);
        store4(o + 4, q.x);
        store4(o + 8, q.y);
        store4(o + 12, q.z);
    }
    return i;
}
#endif
#endif
#endif

#if defined(__AVX__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
// Rows a, b, c, d of the 4x4 matrix in each 128-bit lane, transposed in place: 8 in-lane unpacks.
// Its own inverse. On 4 quaternions a lane (one a row), it separates w, x, y and z.
inline void transpose_in_lanes(float8& a, float8& b, float8& c, float8& d) noexcept {
    // Per lane: t0 = a0 b0 a1 b1, t1 = a2 b2 a3 b3, t2 = c0 d0 c1 d1, t3 = c2 d2 c3 d3.
    const float8 t0 = __builtin_shufflevector(a, b, 0, 8, 1, 9, 4, 12, 5, 13);
    const float8 t1 = __builtin_shufflevector(a, b, 2, 10, 3, 11, 6, 14, 7, 15);
    const float8 t2 = __builtin_shufflevector(c, d, 0, 8, 1, 9, 4, 12, 5, 13);
    const float8 t3 = __builtin_shufflevector(c, d, 2, 10, 3, 11, 6, 14, 7, 15);
    a = __builtin_shufflevector(t0, t2, 0, 1, 8, 9, 4, 5, 12, 13);
    b = __builtin_shufflevector(t0, t2, 2, 3, 10, 11, 6, 7, 14, 15);
    c = __builtin_shufflevector(t1, t3, 0, 1, 8, 9, 4, 5, 12, 13);
    d = __builtin_shufflevector(t1, t3, 2, 3, 10, 11, 6, 7, 14, 15);
}
#if defined(__AVX512F__)
// The same on four 128-bit lanes.
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
#endif

[[nodiscard]] inline float8 load8(const float* p) noexcept {
    float8 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
// Entry C (row-major) of 8 matrices, two groups of 4 whose 36 floats each lie in 9 registers, the
// first group in the low 128-bit lanes and the second in the high ones: matrix k's entry (float
// 9 k + C of its group) lies at position (k + C) % 4 of register (9 k + C) / 4, four registers with
// four different positions, so 3 blends and one in-lane permute (none where C % 4 == 0) put it in
// lane k.
template <int C, int... L>
[[nodiscard]] inline float8 matrix_entry8(const float8 (&r)[9],
                                          std::integer_sequence<int, L...>) noexcept {
    constexpr int p0 = C % 4, p1 = (1 + C) % 4, p2 = (2 + C) % 4, p3 = (3 + C) % 4;
    const float8 first =
        __builtin_shufflevector(r[C / 4], r[(9 + C) / 4], (L % 4 == p1 ? 8 + L : L)...);
    const float8 second =
        __builtin_shufflevector(r[(18 + C) / 4], r[(27 + C) / 4], (L % 4 == p3 ? 8 + L : L)...);
    const float8 blended =
        __builtin_shufflevector(first, second, (L % 4 == p2 || L % 4 == p3 ? 8 + L : L)...);
    static_cast<void>(p0);
    return __builtin_shufflevector(blended, blended, (L - L % 4 + (L % 4 + C) % 4)...);
}

// to_quaternion_each of float matrices [0, n - n % 8) in AVX builds, 8 a step, and how many it did:
// the AVX-512 kernel's conversion (below) on 8 lanes, the entries separated by matrix_entry8 (27
// blends and 6 permutes, all in-lane), the quaternions joined by an in-lane transpose. On a Zen 4
// at -march=x86-64-v3 the scalar loop took 4.9 ns a matrix over 1024 random rotations, against 3.6
// for GLM's quat_cast loop: both branch four ways at random.
[[nodiscard]] inline std::size_t to_quaternion_each_interleaved(const rotation_matrix<float>* m,
                                                                quaternion<float>* out,
                                                                std::size_t n) noexcept {
    constexpr auto lanes = std::make_integer_sequence<int, 8>{};
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        const float* s = &m[i](0, 0);
        float8 r[9];
        for (int j = 0; j < 9; ++j) r[j] = load_halves(s + 4 * j, s + 36 + 4 * j);
        const float8 entries[9] = {
            matrix_entry8<0>(r, lanes), matrix_entry8<1>(r, lanes), matrix_entry8<2>(r, lanes),
            matrix_entry8<3>(r, lanes), matrix_entry8<4>(r, lanes), matrix_entry8<5>(r, lanes),
            matrix_entry8<6>(r, lanes), matrix_entry8<7>(r, lanes), matrix_entry8<8>(r, lanes)};
        quaternion<float8> q;
        if (!quaternions_of_matrices(entries, q)) {
            for (std::size_t j = i; j < i + 8; ++j) out[j] = to_quaternion(m[j]);
            continue;
        }
        transpose_in_lanes(q.w, q.x, q.y, q.z);  // lane 0 of q.w: quaternion 0, lane 1: 4, ...
        float* o = &out[i].w;
        store4(o, __builtin_ia32_vextractf128_ps256(q.w, 0));
        store4(o + 4, __builtin_ia32_vextractf128_ps256(q.x, 0));
        store4(o + 8, __builtin_ia32_vextractf128_ps256(q.y, 0));
        store4(o + 12, __builtin_ia32_vextractf128_ps256(q.z, 0));
        store4(o + 16, __builtin_ia32_vextractf128_ps256(q.w, 1));
        store4(o + 20, __builtin_ia32_vextractf128_ps256(q.x, 1));
        store4(o + 24, __builtin_ia32_vextractf128_ps256(q.y, 1));
        store4(o + 28, __builtin_ia32_vextractf128_ps256(q.z, 1));
    }
    return i;
}

// Output register J of 8 matrices (floats 4 J ... 4 J + 3 of each group of 4, the first group in
// the low 128-bit lane) from their entries: float f = 4 J + p of a group is entry f % 9 of its
// matrix f / 9, four different entries, so 3 in-lane two-source shuffles join them. The inverse of
// matrix_entry8.
template <int J, int... L>
[[nodiscard]] inline float8 matrix_floats8(const float8 (&e)[9],
                                           std::integer_sequence<int, L...>) noexcept {
    constexpr int c0 = (4 * J) % 9, c1 = (4 * J + 1) % 9, c2 = (4 * J + 2) % 9,
                  c3 = (4 * J + 3) % 9;
    // Lane l = 4 h + p: group h, position p; its matrix (4 J + p) / 9 is lane 4 h + that of e[c_p].
    const float8 first = __builtin_shufflevector(e[c0], e[c1],
                                                 (L % 4 == 0   ? L - L % 4 + (4 * J) / 9
                                                  : L % 4 == 1 ? 8 + L - L % 4 + (4 * J + 1) / 9
                                                               : -1)...);
    const float8 second = __builtin_shufflevector(e[c2], e[c3],
                                                  (L % 4 == 2   ? L - L % 4 + (4 * J + 2) / 9
                                                   : L % 4 == 3 ? 8 + L - L % 4 + (4 * J + 3) / 9
                                                                : -1)...);
    return __builtin_shufflevector(first, second, (L % 4 < 2 ? L : 8 + L)...);
}

// to_matrix_each of float quaternions [0, n - n % 8) in AVX builds, 8 a step, and how many it did:
// the quaternions separated by an in-lane transpose (quaternions 0-3 in the low lanes, 4-7 in the
// high ones), detail::scaled_matrix's arithmetic term for term on 8 lanes, and the 9 entries joined
// into the two groups' 72 floats by matrix_floats8 (27 in-lane shuffles). The compiled loop stores
// the matrices float by float: 2.35 ns a matrix at x86-64-v3 on a Zen 4, level with GLM's and
// Eigen's loops (1.05, 0.97).
[[nodiscard]] inline std::size_t to_matrix_each_interleaved(const quaternion<float>* q,
                                                            rotation_matrix<float>* out,
                                                            std::size_t n) noexcept {
    constexpr auto lanes = std::make_integer_sequence<int, 8>{};
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        const float* r = &q[i].w;
        float8 w = load_halves(r, r + 16), x = load_halves(r + 4, r + 20),
               y = load_halves(r + 8, r + 24), z = load_halves(r + 12, r + 28);
        transpose_in_lanes(w, x, y, z);
        const float8 xs = x + x, ys = y + y, zs = z + z;
        const float8 xx = x * xs, yy = y * ys, zz = z * zs;
        const float8 xy = x * ys, xz = x * zs, yz = y * zs;
        const float8 wx = w * xs, wy = w * ys, wz = w * zs;
        const float8 e[9] = {1 - (yy + zz), xy - wz, xz + wy, xy + wz,      1 - (xx + zz),
                             yz - wx,       xz - wy, yz + wx, 1 - (xx + yy)};
        const float8 floats[9] = {
            matrix_floats8<0>(e, lanes), matrix_floats8<1>(e, lanes), matrix_floats8<2>(e, lanes),
            matrix_floats8<3>(e, lanes), matrix_floats8<4>(e, lanes), matrix_floats8<5>(e, lanes),
            matrix_floats8<6>(e, lanes), matrix_floats8<7>(e, lanes), matrix_floats8<8>(e, lanes)};
        float* o = &out[i](0, 0);
        for (int j = 0; j < 9; ++j) {
            store4(o + 4 * j, __builtin_ia32_vextractf128_ps256(floats[j], 0));
            store4(o + 36 + 4 * j, __builtin_ia32_vextractf128_ps256(floats[j], 1));
        }
    }
    return i;
}

// rotate_each of float elements [0, n - n % 8) in AVX builds, 8 a step, with the shuffles spelled
// out as in interleaved_points_avx.hpp (whose helpers it uses), and returns how many it did. Each
// 128-bit lane holds 4 whole elements (elements 0-3 in the low lanes, 4-7 in the high ones), so
// every shuffle stays in its lane: the quaternions by a 4x4 transpose (8 unpacks), the points in
// and out by 3 permutes and 6 blends each; 26 shuffles per 8 elements where g++ 12 compiles the
// plain loop (and GLM's and Eigen's) with 53-54 lane-crossing permutes, the bound of those loops.
// The arithmetic is rotate_factored's, term for term. out == p is safe: each group is read whole
// before it is written. AVX-512 builds run rotate_each_interleaved_16 below and this kernel for a
// remaining 8. With Stream (out aligned to 16 bytes) the stores are non-temporal, in address order
// as interleaved_points_avx.hpp's transform_interleaved writes them.
template <bool Stream = false>
[[nodiscard]] inline std::size_t rotate_each_interleaved(const float* q, const float* p, float* out,
                                                         std::size_t n) noexcept {
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        const float* r = q + 4 * i;
        float8 w = load_halves(r, r + 16), x = load_halves(r + 4, r + 20),
               y = load_halves(r + 8, r + 24), z = load_halves(r + 12, r + 28);
        transpose_in_lanes(w, x, y, z);
        const float* s = p + 3 * i;
        const float8 a = load_halves(s, s + 12), b = load_halves(s + 4, s + 16),
                     c = load_halves(s + 8, s + 20);
        const float8 vx = swap_1_3(blend_1_5(blend_2_6(a, b), c));
        const float8 vy = swap_pairs(blend_2_6(blend_0_3_4_7(a, b), c));
        const float8 vz = swap_0_2(blend_0_3_4_7(blend_1_5(a, b), c));
        float8 rx, ry, rz;
        rotate_factored_lanes(w, x, y, z, vx, vy, vz, rx, ry, rz);
        const float8 px = swap_1_3(rx), py = swap_pairs(ry), pz = swap_0_2(rz);
        const float8 ra = blend_2_6(blend_1_5(px, py), pz);
        const float8 rb = blend_2_6(blend_1_5(py, pz), px);
        const float8 rc = blend_2_6(blend_1_5(pz, px), py);
        put_points8<Stream>(out + 3 * i, ra, rb, rc);
    }
    return i;
}
#endif
#endif

// The quaternion loads and stores and the compose_each kernel of every x86 build with kernels
// (the transposes above: 4 lanes in SSE2 builds, 8 and 16 with AVX and AVX-512).
#if defined(__SSE2__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
// As many quaternions as V has lanes (4, 8 or 16), as w, x, y and z of V each, element
// each_element(l) in lane l (16 lanes; with 4 in order, with 8 in whatever order), and back: a
// quaternion is one 128-bit lane, so this is a 4x4 transpose in each.
template <class V>
[[nodiscard]] inline quaternion<V> load_quaternions(const float* q) noexcept {
    constexpr std::size_t lanes = sizeof(V) / sizeof(float);
    quaternion<V> r;
    std::memcpy(&r.w, q, sizeof r.w);
    std::memcpy(&r.x, q + lanes, sizeof r.x);
    std::memcpy(&r.y, q + 2 * lanes, sizeof r.y);
    std::memcpy(&r.z, q + 3 * lanes, sizeof r.z);
    transpose_in_lanes(r.w, r.x, r.y, r.z);
    return r;
}
// With Stream (out aligned to V's size) the four stores are non-temporal.
template <bool Stream = false, class V>
inline void store_quaternions(float* out, quaternion<V> r) noexcept {
    constexpr std::size_t lanes = sizeof(V) / sizeof(float);
    transpose_in_lanes(r.w, r.x, r.y, r.z);
    // Spelled out, not a loop over pointers to the four: with that loop g++ 12 kept them in memory
    // in x86-64-v3 builds (compose_each 1024: 0.80x GLM's loop against 1.41x).
    if constexpr (Stream) {
        stream_vector<lanes>(out, reinterpret_cast<const float*>(&r.w));
        stream_vector<lanes>(out + lanes, reinterpret_cast<const float*>(&r.x));
        stream_vector<lanes>(out + 2 * lanes, reinterpret_cast<const float*>(&r.y));
        stream_vector<lanes>(out + 3 * lanes, reinterpret_cast<const float*>(&r.z));
    } else {
        std::memcpy(out, &r.w, sizeof r.w);
        std::memcpy(out + lanes, &r.x, sizeof r.x);
        std::memcpy(out + 2 * lanes, &r.y, sizeof r.y);
        std::memcpy(out + 3 * lanes, &r.z, sizeof r.z);
    }
}

// compose_each of float elements [0, n - n % L) for V of L = 8 lanes in AVX builds and 4 in SSE4.1
// builds without AVX, and how many it did: operator* itself on L lanes, between in-lane
// transposes of L quaternions (L / 4 in each register, in whatever lane order: a and b alike, and
// the transpose back restores it): 24 unpacks and 16 multiplies per L products. The plain loop,
// as g++ 12 compiles it at -march=x86-64-v3, took as long as GLM's (0.89 us per 1024 against
// 0.91); this kernel 0.60 (Zen 4, a harness, CPU time). At x86-64-v2 g++ 12 vectorizes the plain
// loop into one slower than its scalar SSE2 code (Xeon: 1.67 ns a product against 1.33; Eigen's
// loop 1.36). Output may be a or b: each group is read whole before it is written. With Stream (out
// aligned to V's size) the stores are non-temporal.
template <class V, bool Stream = false>
[[nodiscard]] inline std::size_t compose_each_interleaved(const float* a, const float* b,
                                                          float* out, std::size_t n) noexcept {
    constexpr std::size_t lanes = sizeof(V) / sizeof(float);
    std::size_t i = 0;
    for (; i + lanes <= n; i += lanes)
        store_quaternions<Stream>(out + 4 * i,
                                  load_quaternions<V>(a + 4 * i) * load_quaternions<V>(b + 4 * i));
    return i;
}

#if defined(__SSE4_1__) && !defined(__AVX__)
// interleaved_points_avx.hpp's blends (blendps) and in-lane permutes on one 128-bit lane.
[[nodiscard]] inline float4 blend_2(float4 a, float4 b) noexcept {
    return __builtin_shufflevector(a, b, 0, 1, 6, 3);
}
[[nodiscard]] inline float4 blend_1(float4 a, float4 b) noexcept {
    return __builtin_shufflevector(a, b, 0, 5, 2, 3);
}
[[nodiscard]] inline float4 blend_0_3(float4 a, float4 b) noexcept {
    return __builtin_shufflevector(a, b, 4, 1, 2, 7);
}
[[nodiscard]] inline float4 swap_1_3(float4 v) noexcept {
    return __builtin_shufflevector(v, v, 0, 3, 2, 1);
}
[[nodiscard]] inline float4 swap_pairs(float4 v) noexcept {
    return __builtin_shufflevector(v, v, 1, 0, 3, 2);
}
[[nodiscard]] inline float4 swap_0_2(float4 v) noexcept {
    return __builtin_shufflevector(v, v, 2, 1, 0, 3);
}

// rotate_each of float elements [0, n - n % 4) in SSE4.1 builds without AVX, 4 a step, and how
// many it did: the AVX kernel (rotate_each_interleaved) on one 128-bit lane, 14 shuffles and 12
// blends per 4 elements. g++ 12 vectorizes GLM's and Eigen's loops at x86-64-v2, and they ran
// ahead of the struct-of-arrays blocks that SSE2 builds run (Xeon, 1024 elements: 1.52-1.54 ns an
// element against 1.73). out == p is safe: each group is read whole before it is written.
[[nodiscard]] inline std::size_t rotate_each_interleaved_4(const float* q, const float* p,
                                                           float* out, std::size_t n) noexcept {
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {
        const float* r = q + 4 * i;
        float4 w = load4(r), x = load4(r + 4), y = load4(r + 8), z = load4(r + 12);
        transpose_in_lanes(w, x, y, z);
        const float* s = p + 3 * i;
        const float4 a = load4(s), b = load4(s + 4), c = load4(s + 8);
        const float4 vx = swap_1_3(blend_1(blend_2(a, b), c));
        const float4 vy = swap_pairs(blend_2(blend_0_3(a, b), c));
        const float4 vz = swap_0_2(blend_0_3(blend_1(a, b), c));
        float4 rx, ry, rz;
        rotate_factored_lanes(w, x, y, z, vx, vy, vz, rx, ry, rz);
        const float4 px = swap_1_3(rx), py = swap_pairs(ry), pz = swap_0_2(rz);
        store4(out + 3 * i, blend_2(blend_1(px, py), pz));
        store4(out + 3 * i + 4, blend_2(blend_1(py, pz), px));
        store4(out + 3 * i + 8, blend_2(blend_1(pz, px), py));
    }
    return i;
}
#endif

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
// it is written. With Stream (out aligned to 64 bytes) each register of results is one
// non-temporal store of a whole cache line.
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
// The lane of output float g's element.
[[nodiscard]] constexpr int result_lane(int g) noexcept { return each_lane(g / 3); }

// Every third float of the 48 in registers a, b, c, from float K on: lane l gets float 3 n(l) + K,
// where n(l) = l in natural order and each_element(l) otherwise (two two-source permutes).
template <int K, bool Natural, int... L>
[[nodiscard]] inline float16 every_third(float16 a, float16 b, float16 c,
                                         std::integer_sequence<int, L...>) noexcept {
    const float16 ab =
        __builtin_shufflevector(a, b, first_of_pair(3 * (Natural ? L : each_element(L)) + K)...);
    return __builtin_shufflevector(ab, c,
                                   second_of_pair(3 * (Natural ? L : each_element(L)) + K, L)...);
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

// compose_each of float elements [0, n - n % 16) in AVX-512 builds, and how many it did: operator*
// itself on 16 lanes, between two transposes in and one out (24 in-lane unpacks and 16 multiplies
// per 16 products, where g++ 12 compiles the plain loop with lane-crossing permutes). Output may be
// a or b: each group is read whole before it is written.
// With Stream (out aligned to 64 bytes) each register is one non-temporal store of a cache line.
template <bool Stream = false>
[[nodiscard]] inline std::size_t compose_each_interleaved_16(const float* a, const float* b,
                                                             float* out, std::size_t n) noexcept {
    std::size_t i = 0;
    for (; i + 16 <= n; i += 16)
        store_quaternions<Stream>(out + 4 * i, load_quaternions<float16>(a + 4 * i) *
                                                   load_quaternions<float16>(b + 4 * i));
    return i;
}

template <bool Stream = false>
[[nodiscard]] inline std::size_t rotate_each_interleaved_16(const float* q, const float* p,
                                                            float* out, std::size_t n) noexcept {
    constexpr auto lanes = std::make_integer_sequence<int, 16>{};
    std::size_t i = 0;
    for (; i + 16 <= n; i += 16) {
        const quaternion<float16> r = load_quaternions<float16>(q + 4 * i);
        const float16 w = r.w, x = r.x, y = r.y, z = r.z;
        const float* s = p + 3 * i;
        const float16 a = load16(s), b = load16(s + 16), c = load16(s + 32);
        const float16 vx = every_third<0, false>(a, b, c, lanes);
        const float16 vy = every_third<1, false>(a, b, c, lanes);
        const float16 vz = every_third<2, false>(a, b, c, lanes);
        float16 rx, ry, rz;
        rotate_factored_lanes(w, x, y, z, vx, vy, vz, rx, ry, rz);
        const float16 ra = join_coordinates<0>(rx, ry, rz, lanes);
        const float16 rb = join_coordinates<1>(rx, ry, rz, lanes);
        const float16 rc = join_coordinates<2>(rx, ry, rz, lanes);
        float* o = out + 3 * i;
        if constexpr (Stream) {
            stream_vector<16>(o, reinterpret_cast<const float*>(&ra));
            stream_vector<16>(o + 16, reinterpret_cast<const float*>(&rb));
            stream_vector<16>(o + 32, reinterpret_cast<const float*>(&rc));
        } else {
            std::memcpy(o, &ra, sizeof ra);
            std::memcpy(o + 16, &rb, sizeof rb);
            std::memcpy(o + 32, &rc, sizeof rc);
        }
    }
    return i;
}
// Entry (R, c) of 16 matrices from the columns of their rows (column[g][c]: column c of rows
// 16 g ... 16 g + 15, row 3 e + r being row r of matrix e), element each_element(l) in lane l.
template <int R>
[[nodiscard]] inline float16 matrix_entry(const float16 (&column)[3][3], int c) noexcept {
    return every_third<R, false>(column[0][c], column[1][c], column[2][c],
                                 std::make_integer_sequence<int, 16>{});
}

// to_quaternion_each of float matrices [0, n - n % 16) in AVX-512 builds, 16 a step, and how many
// it did: to_quaternion's arithmetic on 16 lanes, its branches turned into selects. The scalar loop
// is branchy (which of four cases, then the sign of w), and a branch taken at random costs more
// than the conversion: over 1024 random rotations it took 3.0 or 5.0 ns a matrix (Zen 5) with what
// the predictor had learnt, as GLM's quat_cast does; this kernel takes neither branch. The 9
// entries of 16 matrices (9 registers) are separated in two rounds of every_third (rows of 3, then
// every third row): 36 permutes; the quaternions leave through store_quaternions. A group with a
// squared norm outside the normal range (not a rotation: zero, NaN, huge) is converted by
// to_quaternion itself, element by element, so results equal the scalar ones whatever the input.
[[nodiscard]] inline std::size_t to_quaternion_each_interleaved_16(const rotation_matrix<float>* m,
                                                                   quaternion<float>* out,
                                                                   std::size_t n) noexcept {
    constexpr auto lanes = std::make_integer_sequence<int, 16>{};
    std::size_t i = 0;
    for (; i + 16 <= n; i += 16) {
        const float* s = &m[i](0, 0);
        // Column c of rows 16 g ... 16 g + 15 (row 3 e + r is row r of matrix e).
        float16 column[3][3];
        for (int g = 0; g < 3; ++g) {
            const float16 a = load16(s + 48 * g), b = load16(s + 48 * g + 16),
                          c = load16(s + 48 * g + 32);
            column[g][0] = every_third<0, true>(a, b, c, lanes);
            column[g][1] = every_third<1, true>(a, b, c, lanes);
            column[g][2] = every_third<2, true>(a, b, c, lanes);
        }
        const float16 entries[9] = {
            matrix_entry<0>(column, 0), matrix_entry<0>(column, 1), matrix_entry<0>(column, 2),
            matrix_entry<1>(column, 0), matrix_entry<1>(column, 1), matrix_entry<1>(column, 2),
            matrix_entry<2>(column, 0), matrix_entry<2>(column, 1), matrix_entry<2>(column, 2)};
        quaternion<float16> q;
        if (!quaternions_of_matrices(entries, q)) {
            for (std::size_t j = i; j < i + 16; ++j) out[j] = to_quaternion(m[j]);
            continue;
        }
        store_quaternions(&out[i].w, q);
    }
    return i;
}
#endif
#endif

// The leading elements that the kernels above do where the build has them (AVX, g++ 12 or clang;
// 16 a step with AVX-512, then 8), and how many: 0 elsewhere and for other scalars. The callers'
// plain loops do the rest. The kernels read quaternions, points and matrices as packed floats.
static_assert(sizeof(quaternion<float>) == 4 * sizeof(float) &&
                  sizeof(vec3<float>) == 3 * sizeof(float) &&
                  sizeof(rotation_matrix<float>) == 9 * sizeof(float),
              "packed quaternions, points and matrices");

// With Stream (output aligned to 64 bytes) the stores are non-temporal.
template <bool Stream = false, class T>
[[nodiscard]] inline std::size_t compose_each_kernels([[maybe_unused]] const quaternion<T>* a,
                                                      [[maybe_unused]] const quaternion<T>* b,
                                                      [[maybe_unused]] quaternion<T>* output,
                                                      [[maybe_unused]] std::size_t n) noexcept {
    std::size_t done = 0;
#if defined(__AVX__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
    if constexpr (std::is_same_v<T, float>) {
#if defined(__AVX512F__)
        if constexpr (!Stream || stream_width == 16)
            if (n >= 16)
                done = compose_each_interleaved_16<Stream>(&a[0].w, &b[0].w, &output[0].w, n);
#endif
        if constexpr (!Stream || stream_width >= 8)
            if (n - done >= 8)
                done += compose_each_interleaved<float8, Stream>(&a[done].w, &b[done].w,
                                                                 &output[done].w, n - done);
    }
#endif
#endif
#if defined(__SSE4_1__) && !defined(__AVX__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
    if constexpr (std::is_same_v<T, float> && !Stream)
        if (n >= 4)  // an empty batch may come as null pointers, whose members are not formed
            done = compose_each_interleaved<float4>(&a[0].w, &b[0].w, &output[0].w, n);
#endif
#endif
    return done;
}

// With Stream (output aligned to 64 bytes) the stores are non-temporal.
template <bool Stream = false, class T>
[[nodiscard]] inline std::size_t rotate_each_kernels(
    [[maybe_unused]] const quaternion<T>* rotations, [[maybe_unused]] const vec3<T>* points,
    [[maybe_unused]] vec3<T>* output, [[maybe_unused]] std::size_t n) noexcept {
    std::size_t done = 0;
#if defined(__AVX__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
    if constexpr (std::is_same_v<T, float>) {
#if defined(__AVX512F__)
        if constexpr (!Stream || stream_width == 16)
            if (n >= 16)
                done = rotate_each_interleaved_16<Stream>(&rotations[0].w, &points[0].x,
                                                          &output[0].x, n);
#endif
        if (n - done >= 8)
            done += rotate_each_interleaved<Stream>(&rotations[done].w, &points[done].x,
                                                    &output[done].x, n - done);
    }
#endif
#endif
#if defined(__SSE4_1__) && !defined(__AVX__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
    if constexpr (std::is_same_v<T, float> && !Stream)
        if (n >= 4)  // as in compose_each_kernels above
            done = rotate_each_interleaved_4(&rotations[0].w, &points[0].x, &output[0].x, n);
#endif
#endif
    return done;
}

template <class T>
[[nodiscard]] inline std::size_t to_matrix_each_kernels([[maybe_unused]] const quaternion<T>* q,
                                                        [[maybe_unused]] rotation_matrix<T>* output,
                                                        [[maybe_unused]] std::size_t n) noexcept {
    std::size_t done = 0;
#if defined(__AVX__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
    if constexpr (std::is_same_v<T, float>) {
        if (n >= 8) done = to_matrix_each_interleaved(q, output, n);
    }
#endif
#endif
    return done;
}

template <class T>
[[nodiscard]] inline std::size_t to_quaternion_each_kernels(
    [[maybe_unused]] const rotation_matrix<T>* m, [[maybe_unused]] quaternion<T>* output,
    [[maybe_unused]] std::size_t n) noexcept {
    std::size_t done = 0;
#if defined(__AVX__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
    if constexpr (std::is_same_v<T, float>) {
#if defined(__AVX512F__)
        if (n >= 16) done = to_quaternion_each_interleaved_16(m, output, n);
#endif
        if (n - done >= 8)
            done += to_quaternion_each_interleaved(m + done, output + done, n - done);
    }
#endif
#endif
#if defined(__SSE2__) && !defined(__AVX__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
    if constexpr (std::is_same_v<T, float>) done = to_quaternion_each_interleaved_4(m, output, n);
#endif
#endif
    return done;
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_BATCH_DETAIL_INTERLEAVED_ELEMENTS_HPP_INCLUDED
