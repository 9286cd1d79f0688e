// The array-of-structs rotation of float points in AVX and AVX-512 builds, with the shuffles
// spelled
// out in GCC/clang vector extensions (__builtin_shufflevector, and the vinsertf128/vextractf128
// builtins where g++ would otherwise add port-5 uops), because no compiler finds these arrangements
// from a plain loop. No wide intrinsics header (only streaming_store.hpp's <xmmintrin.h>, for the
// non-temporal stores): <immintrin.h> alone doubled the compile time of a translation unit
// including quat.hpp with -march=native (0.16 s to 0.33 s, g++ 12; 0.17 s with <xmmintrin.h>).
//
// Why: x, y, z interleaved in memory must be separated (de-interleaved) before 8 points can share a
// vector multiply, and joined again after. Compiled from a plain loop, g++ 12 does this with 12
// vpermd, 5 vpermilps and a vinsertf128 per 8 points with -march=x86-64-v3: 18 uops that only
// port 5 of an Intel core runs, 2.25 cycles per point, three times the 9 multiply-adds' own cost
// (GLM's and Eigen's plain loops compile to the same). In transform_interleaved each 128-bit lane
// holds 4 whole points (loaded as 16-byte halves), so every shuffle stays inside a lane: per
// coordinate, two blends (any of ports 0, 1, 5) and one in-lane permute (port 5) take it out, and
// the same permute and two blends put it back. Per 8 points: 6 port-5 permutes, 12 blends, 3 lane
// inserts and 9 multiply-adds, 30 uops over three ports, 1.25 cycles per point.
#ifndef QUAT_BATCH_DETAIL_INTERLEAVED_POINTS_AVX_HPP_INCLUDED
#define QUAT_BATCH_DETAIL_INTERLEAVED_POINTS_AVX_HPP_INCLUDED

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>

#include "../../rotation_matrix.hpp"
#include "../../vec3.hpp"
#include "sse_lanes.hpp"
#include "streaming_store.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

#if defined(__AVX__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)

using float8 = float __attribute__((vector_size(32)));

// 8 floats from two places: 4 at low (the low 128-bit lane) and 4 at high. The high half by the
// vinsertf128 builtin, which takes it straight from memory (a shuffle of two loaded halves costs a
// port-5 uop more per register).
[[nodiscard]] inline float8 load_halves(const float* low, const float* high) noexcept {
    const float4 lower = load4(low);
    return __builtin_ia32_vinsertf128_ps256(
        __builtin_shufflevector(lower, lower, 0, 1, 2, 3, -1, -1, -1, -1), load4(high), 1);
}
// A plain store, or a non-temporal one (p aligned to 16 bytes) when Stream.
template <bool Stream>
inline void put4(float* p, float4 v) noexcept {
    if constexpr (Stream) {
        stream_vector<4>(p, reinterpret_cast<const float*>(&v));
    } else {
        store4(p, v);
    }
}

// 8 points (24 floats) whose lanes hold a0 b0 c0 in the low halves and a1 b1 c1 in the high ones,
// stored in address order (a plain or non-temporal store as put4). Halves taken by the
// vextractf128 builtin (g++ and clang alike), not by a shuffle: g++ merges adjacent shuffled
// halves into 256-bit stores through three vperm2f128 (port 5), which measured 424 ns against
// 359 ns at 1024 points.
template <bool Stream>
inline void put_points8(float* o, float8 a, float8 b, float8 c) noexcept {
    put4<Stream>(o, __builtin_ia32_vextractf128_ps256(a, 0));
    put4<Stream>(o + 4, __builtin_ia32_vextractf128_ps256(b, 0));
    put4<Stream>(o + 8, __builtin_ia32_vextractf128_ps256(c, 0));
    put4<Stream>(o + 12, __builtin_ia32_vextractf128_ps256(a, 1));
    put4<Stream>(o + 16, __builtin_ia32_vextractf128_ps256(b, 1));
    put4<Stream>(o + 20, __builtin_ia32_vextractf128_ps256(c, 1));
}

// Blends of a and b lane by lane (mask bit i set: element i from b), as vblendps encodes them.
[[nodiscard]] inline float8 blend_2_6(float8 a, float8 b) noexcept {
    return __builtin_shufflevector(a, b, 0, 1, 10, 3, 4, 5, 14, 7);
}
[[nodiscard]] inline float8 blend_1_5(float8 a, float8 b) noexcept {
    return __builtin_shufflevector(a, b, 0, 9, 2, 3, 4, 13, 6, 7);
}
[[nodiscard]] inline float8 blend_0_3_4_7(float8 a, float8 b) noexcept {
    return __builtin_shufflevector(a, b, 8, 1, 2, 11, 12, 5, 6, 15);
}
// In-lane permutes, each its own inverse: (0 3 2 1), (1 0 3 2), (2 1 0 3) in each half.
[[nodiscard]] inline float8 swap_1_3(float8 v) noexcept {
    return __builtin_shufflevector(v, v, 0, 3, 2, 1, 4, 7, 6, 5);
}
[[nodiscard]] inline float8 swap_pairs(float8 v) noexcept {
    return __builtin_shufflevector(v, v, 1, 0, 3, 2, 5, 4, 7, 6);
}
[[nodiscard]] inline float8 swap_0_2(float8 v) noexcept {
    return __builtin_shufflevector(v, v, 2, 1, 0, 3, 6, 5, 4, 7);
}

// Rotates (and translates when Translate) points [0, n - n % 8) of the float array `in`, three
// floats a point, into `out`, and returns how many it did. out == in is safe: each group of 8
// points is read whole before it is written. The sums are m00 x + m01 y + m02 z in that order, as
// the scalar loop has them (contracted into FMAs alike where the target has them). With Stream the
// stores are non-temporal (out aligned to 16 bytes): the 16-byte pieces of a group are written in
// address order, so the write-combining buffers fill whole lines, and the memory writes overlap
// the loads and arithmetic of the next groups, which a computed block streamed afterwards does not
// (4M points on a Zen 4: 3.2-3.5 ms against 3.5-3.8 through a buffer; streaming copy 3.2-3.3).
template <bool Translate, bool Stream = false>
[[nodiscard]] inline std::size_t transform_interleaved(const rotation_matrix<float>& m,
                                                       const vec3<float>& t, const float* in,
                                                       float* out, std::size_t n) noexcept {
    auto splat = [](float s) noexcept { return float8{s, s, s, s, s, s, s, s}; };
    const float8 m00 = splat(m(0, 0)), m01 = splat(m(0, 1)), m02 = splat(m(0, 2)),
                 m10 = splat(m(1, 0)), m11 = splat(m(1, 1)), m12 = splat(m(1, 2)),
                 m20 = splat(m(2, 0)), m21 = splat(m(2, 1)), m22 = splat(m(2, 2));
    const float8 tx = splat(t.x), ty = splat(t.y), tz = splat(t.z);
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        const float* p = in + 3 * i;
        // Per lane (points 0-3 low, 4-7 high): a = x0 y0 z0 x1, b = y1 z1 x2 y2, c = z2 x3 y3 z3.
        const float8 a = load_halves(p, p + 12), b = load_halves(p + 4, p + 16),
                     c = load_halves(p + 8, p + 20);
        // The blends gather a coordinate in a rotated order (x0 x3 x2 x1, y1 y0 y3 y2,
        // z2 z1 z0 z3); the permutes put it in order, and later back.
        const float8 x = swap_1_3(blend_1_5(blend_2_6(a, b), c));
        const float8 y = swap_pairs(blend_2_6(blend_0_3_4_7(a, b), c));
        const float8 z = swap_0_2(blend_0_3_4_7(blend_1_5(a, b), c));
        float8 rx = m00 * x + m01 * y + m02 * z;
        float8 ry = m10 * x + m11 * y + m12 * z;
        float8 rz = m20 * x + m21 * y + m22 * z;
        if constexpr (Translate) {
            rx += tx;
            ry += ty;
            rz += tz;
        }
        const float8 px = swap_1_3(rx), py = swap_pairs(ry), pz = swap_0_2(rz);
        const float8 ra = blend_2_6(blend_1_5(px, py), pz);
        const float8 rb = blend_2_6(blend_1_5(py, pz), px);
        const float8 rc = blend_2_6(blend_1_5(pz, px), py);
        put_points8<Stream>(out + 3 * i, ra, rb, rc);
    }
    return i;
}

#if defined(__AVX512F__)

using float16 = float __attribute__((vector_size(64)));

[[nodiscard]] inline float16 load16(const float* p) noexcept {
    float16 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// The points before the first one whose floats start on a 64-byte boundary of `in` (at most 15:
// 12 k bytes meet every multiple of 4 modulo 64); 0 when `in` is not 4-byte aligned, since no point
// of it starts a line. In closed form rather than a search, which cost up to 15 dependent steps:
// 12 k = -offset (mod 64) <=> 3 k = -offset / 4 (mod 16) <=> k = 11 (16 - offset / 4) (mod 16),
// since 3 * 11 = 1 (mod 16).
[[nodiscard]] inline std::size_t points_before_line(const float* in) noexcept {
    const std::size_t offset = reinterpret_cast<std::uintptr_t>(in) % 64;
    if (offset % 4 != 0) return 0;
    return (11 * (16 - offset / 4)) % 16;
}

// Where entry (row, column) of m (column 3: t_row) lies in the pair of registers that
// transform_interleaved_16 holds them in: m's first eight entries, then m(2, 2), t.x, t.y, t.z.
[[nodiscard]] constexpr int entry_lane(int row, int column) noexcept {
    return column == 3 ? 17 + row : row == 2 && column == 2 ? 16 : 3 * row + column;
}

// The two gathers of transform_interleaved_16 bring each lane the other two coordinates of its
// point: an x lane gets y, then z; a y lane z, then x; a z lane y, then x. So gather 0 never reads
// an x and gather 1 never a y, and the lanes holding those are free for a neighbour's floats.
[[nodiscard]] constexpr int gathered_coordinate(int gather, int k) noexcept {
    return gather == 0 ? (k == 1 ? 2 : 1) : (k == 0 ? 2 : 0);
}

// Register R's lanes (lane l: coordinate k = (R + l) % 3) of the coefficient of term Term:
// m(k, k) for the lane's own coordinate (Term 0), m(k, c) for the coordinate c that gather
// Term - 1 brings (Term 1, 2), and t_k (Term 3).
template <int R, int Term, int... L>
[[nodiscard]] inline float16 coefficient_lanes(float16 low, float16 high,
                                               std::integer_sequence<int, L...>) noexcept {
    return __builtin_shufflevector(
        low, high,
        entry_lane((R + L) % 3, Term == 0   ? (R + L) % 3
                                : Term == 3 ? 3
                                            : gathered_coordinate(Term - 1, (R + L) % 3))...);
}

// A register's coefficients of its own coordinate, of the two gathers and of t.
struct register_coefficients {
    float16 own, first, second, offset;
};

template <int R>
[[nodiscard]] inline register_coefficients coefficients_of(float16 low, float16 high) noexcept {
    constexpr auto lanes = std::make_integer_sequence<int, 16>{};
    return {coefficient_lanes<R, 0>(low, high, lanes), coefficient_lanes<R, 1>(low, high, lanes),
            coefficient_lanes<R, 2>(low, high, lanes), coefficient_lanes<R, 3>(low, high, lanes)};
}

// x with lane Lane replaced by lane From of y.
template <int Lane, int From, int... L>
[[nodiscard]] inline float16 with_lane(float16 x, float16 y,
                                       std::integer_sequence<int, L...>) noexcept {
    return __builtin_shufflevector(x, y, (L == Lane ? 16 + From : L)...);
}

// Where gather G of register R finds float g (0-47) of the group in the register it permutes: its
// own floats (16 R to 16 R + 15) in their lanes, and the neighbours' floats where the kernel put
// them (register 0: y5 and z5 in lanes 0 and 1; register 1: x5 in lane 15, z10 in lane 2 for
// gather 0 and lane 0 for gather 1; register 2: y10 in lane 13 and x10 in lane 14).
template <int R, int G>
[[nodiscard]] constexpr int source_lane(int g) noexcept {
    if (g / 16 == R) return g % 16;
    if (R == 0) return g - 16;
    if (R == 1) return g == 15 ? 15 : G == 0 ? 2 : 0;
    return g == 31 ? 13 : 14;
}

// Gather G of register R: each lane's coordinate gathered_coordinate(G, k) of its own point.
template <int R, int G, int... L>
[[nodiscard]] inline float16 gather(float16 source, std::integer_sequence<int, L...>) noexcept {
    return __builtin_shufflevector(
        source, source,
        source_lane<R, G>(3 * ((16 * R + L) / 3) + gathered_coordinate(G, (R + L) % 3))...);
}

// Register R of a group's results: x times m's diagonal (t added first when Translate), plus the
// two gathers of the other coordinates from their sources times their coefficients.
template <int R, bool Translate>
[[nodiscard]] inline float16 moved_register(const register_coefficients& k, float16 x,
                                            float16 source0, float16 source1) noexcept {
    constexpr auto lanes = std::make_integer_sequence<int, 16>{};
    float16 r;
    if constexpr (Translate) r = k.offset + k.own * x;
    else r = k.own * x;
    r += k.first * gather<R, 0>(source0, lanes);
    return r + k.second * gather<R, 1>(source1, lanes);
}

// 16 points (48 floats, registers a, b, c) a step, without separating the coordinates: float g of
// a group is coordinate k = g % 3 of point g / 3, and its result is m(k, k) times that float, plus
// m(k, c) times each other coordinate c of its point (+ t_k, added first). So each register of
// results is the register itself times a coefficient register, plus two gathers of the other
// coordinates, lane by lane, times theirs: the coefficients repeat m's entries with period 3. A
// gather permutes one register: the floats a register's points keep in a neighbour (points 5 and
// 10 straddle two registers) are first blended into lanes that the gather does not read, after a
// move within their 128-bit lane where their own lane is read. Per 16 points: 6 one-source
// permutes, 5 blends, 2 masked in-lane moves and 9 multiply-adds.
//
// Why: a Zen 4 core runs a 512-bit two-source permute (vpermt2ps) at about 1.5 times the cost of a
// one-source one, and both on the pipes of the multiply-adds, while blends and in-lane moves run
// beside them (instruction loops: 9 multiply-adds take 9.0 cycles, 15.3 with 6 two-source and 3
// one-source permutes, 12.0 with 9 one-source ones, 9.0-9.1 with 6 blends or 6 in-lane shuffles).
// Gathering x, y and z for each register (9 permutes, 6 of them two-source, then 9 multiply-adds
// and 3 additions, as g++ 12 compiles GLM's mat4 loop) took 0.265-0.285 ns a point to transform
// 1024 points against 0.214-0.254 for this form, and 0.233-0.298 to rotate them against
// 0.224-0.271 (six layouts of input and output, medians of 21 interleaved calls).
//
// A 64-byte access that straddles two cache lines costs a Zen 4 core two, and with arrays only
// 16-byte aligned three accesses in four straddle; straddling loads cost more than straddling
// stores, so from 1024 points on the groups start `in` on a line and the stores fall where `out`
// puts them. Shifting each group's results into line-aligned stores (3 more permutes) measured
// slower than the straddling stores: 1024 points 170 ns against 157 with `out` off its line.
//
// Every point goes through this kernel, so its results do not depend on where a point falls or on
// whether the call is in place: out of place, the first 16 points as they lie, the groups from the
// input's first 64-byte boundary on (from 1024 points; below, every 16 points), and the last 16,
// which may write some points again (the same values). In place, groups every 16 points, and the
// last 16 from a copy of their input taken before any is overwritten. The coefficients are formed
// once for all of them: 64 points took 0.44 ns a point with the runs of groups each forming its
// own, twice the plain loop. Returns how many points it did: n from 16 points on, else 0.
template <bool Translate>
[[nodiscard]] inline std::size_t transform_interleaved_16(const rotation_matrix<float>& m,
                                                          const vec3<float>& t, const float* in,
                                                          float* out, std::size_t n) noexcept {
    if (n < 16) return 0;
    // Lane l of register r is float 16 r + l of the group: coordinate (16 r + l) % 3, that is
    // (r + l) % 3. The coefficients are permutes of two registers: m's first eight entries, read
    // as one 32-byte load, and m(2, 2) with t. Built from the twelve scalars instead, the entries
    // took g++ 12 some forty shuffles: 64 points 20.8 ns against 17.7 (Zen 4).
    float8 head;
    std::memcpy(&head, &m.elements, sizeof head);
    const float16 low =
        __builtin_shufflevector(head, head, 0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7);
    const float16 high = {m(2, 2), t.x, t.y, t.z, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    constexpr auto lanes = std::make_integer_sequence<int, 16>{};
    const register_coefficients coefficient[3] = {coefficients_of<0>(low, high),
                                                  coefficients_of<1>(low, high),
                                                  coefficients_of<2>(low, high)};
    // The groups start at 0, then every 16 points, out of place from the input's first line on
    // when there are 1024 points or more (below, the extra group costs more than the straddling
    // loads save; Zen 5, input 16 bytes past a line: 64 points 12.4 ns against 14.3 aligned, 1024
    // points 148 against 149, 4096 points 654 against 641), and last at n - 16. One loop body, not
    // a lambda called per group: in a large translation unit g++ 12 left such a lambda out of line,
    // reloading the coefficients at every call (64 points in quat_bench took 0.67 ns a point
    // against 0.25 for a plain loop). Nor a loop over runs of groups kept as (input, output,
    // count): g++ 12 then left the kernel out of line (16 points 16.8 ns against 12.4, Zen 4).
    const bool in_place = in == out;
    const std::size_t line = in_place || n < 1024 ? 0 : points_before_line(in);
    // In place, the last 16 points overlap the group before them, which overwrites their input,
    // so they are moved from a copy taken first.
    float last[48];
    const bool from_copy = in_place && n % 16 != 0;
    if (from_copy) std::memcpy(last, in + 3 * (n - 16), sizeof last);
    for (std::size_t start = 0;;) {
        const float* p = from_copy && start + 16 == n ? last : in + 3 * start;
        const float16 a = load16(p), b = load16(p + 16), c = load16(p + 32);
        // What each gather permutes: register 0 with y5 and z5 (b's lanes 0 and 1) in its x0 and
        // y0 lanes; register 1 with z10 (c's lane 0) moved to its x6 lane, or with x5 and z10 in
        // its y10 and y5 lanes; register 2 with y10 moved to its x15 lane, or with x10 in its y15
        // lane.
        const float16 b_from_c =
            __builtin_shufflevector(c, c, 0, 0, 0, 0, 4, 4, 4, 4, 8, 8, 8, 8, 12, 12, 12, 12);
        const float16 c_from_b =
            __builtin_shufflevector(b, b, 3, 3, 3, 3, 7, 7, 7, 7, 11, 11, 11, 11, 15, 15, 15, 15);
        const float16 a0 = with_lane<0, 0>(a, b, lanes), a1 = with_lane<1, 1>(a, b, lanes);
        const float16 b0 = with_lane<2, 2>(b, b_from_c, lanes);
        const float16 b1 = with_lane<0, 0>(with_lane<15, 15>(b, a, lanes), c, lanes);
        const float16 c0 = with_lane<13, 13>(c, c_from_b, lanes);
        const float16 c1 = with_lane<14, 14>(c, b, lanes);
        const float16 ra = moved_register<0, Translate>(coefficient[0], a, a0, a1);
        const float16 rb = moved_register<1, Translate>(coefficient[1], b, b0, b1);
        const float16 rc = moved_register<2, Translate>(coefficient[2], c, c0, c1);
        std::memcpy(out + 3 * start, &ra, sizeof ra);
        std::memcpy(out + 3 * start + 16, &rb, sizeof rb);
        std::memcpy(out + 3 * start + 32, &rc, sizeof rc);
        std::size_t next = start < line ? line : start + 16;
        if (next + 16 > n) {
            if (start + 16 == n) return n;
            next = n - 16;
        }
        start = next;
    }
}

#endif  // __AVX512F__
#endif  // __has_builtin(__builtin_shufflevector)
#endif  // __AVX__ && __has_builtin

// Whether the kernels above are in this build, and so can stream their results straight from
// their registers (transform_interleaved_floats with Stream).
#if defined(__AVX__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
inline constexpr bool has_streaming_kernel = true;
#else
inline constexpr bool has_streaming_kernel = false;
#endif
#else
inline constexpr bool has_streaming_kernel = false;
#endif

// Rotates (and translates when Translate) the leading points of `in` (three floats each) into
// `out` with the kernels above where the build has them (AVX, g++ 12 or clang), and returns how
// many it did, leaving fewer than 8 to the caller (AVX-512 builds do all of n >= 16 points out of
// place); 0 elsewhere. With Stream (out aligned to 16
// bytes) the stores are non-temporal, by the 8-point kernel in AVX-512 builds too: out of cache
// the arithmetic is not the bound.
template <bool Translate, bool Stream = false>
[[nodiscard]] inline std::size_t transform_interleaved_floats(
    const rotation_matrix<float>& m, const vec3<float>& t, const float* in,
    // NOLINTNEXTLINE(readability-non-const-parameter): AVX builds write it
    float* out, std::size_t n) noexcept {
    std::size_t done = 0;
#if defined(__AVX__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)
#if defined(__AVX512F__)
    if constexpr (!Stream) {
        done = transform_interleaved_16<Translate>(m, t, in, out, n);
        if (done == n) return done;
    }
#endif
    done += transform_interleaved<Translate, Stream>(m, t, in + 3 * done, out + 3 * done, n - done);
#endif
#endif
    static_cast<void>(m), static_cast<void>(t), static_cast<void>(in), static_cast<void>(out),
        static_cast<void>(n);  // unused where no kernel applies
    return done;
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_BATCH_DETAIL_INTERLEAVED_POINTS_AVX_HPP_INCLUDED
