// The array-of-structs rotation of float points in AArch64 builds: 4 points a step through the
// structure load and store that separate and join x, y and z (ld3/st3). g++ 12 emits the same
// instructions for the plain loop at -O3, but leaves the loop scalar at -O2: 3 loads, 9
// multiply-adds and 3 stores a point, where this kernel takes 11 instructions for 4 points
// (a static count; speed on AArch64 is not measured here).
#ifndef QUAT_BATCH_DETAIL_INTERLEAVED_POINTS_NEON_HPP_INCLUDED
#define QUAT_BATCH_DETAIL_INTERLEAVED_POINTS_NEON_HPP_INCLUDED

#include <cstddef>

#include "../../rotation_matrix.hpp"
#include "../../vec3.hpp"

#if defined(__aarch64__) && defined(__ARM_NEON)
#include <arm_neon.h>
#endif

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

// Rotates (and translates when Translate) points [0, n - n % 4) of the float array `in`, three
// floats a point, into `out`, and returns how many it did (0 outside AArch64). The sums are the
// scalar loop's, m00 x + m01 y + m02 z in that order. out == in is safe: each group is loaded
// before it is stored.
template <bool Translate>
[[nodiscard]] inline std::size_t transform_interleaved_neon(
    const rotation_matrix<float>& m, const vec3<float>& t, const float* in,
    // NOLINTNEXTLINE(readability-non-const-parameter): AArch64 builds write it
    float* out, std::size_t n) noexcept {
    std::size_t i = 0;
#if defined(__aarch64__) && defined(__ARM_NEON)
    const float32x4_t m00 = vdupq_n_f32(m(0, 0)), m01 = vdupq_n_f32(m(0, 1)),
                      m02 = vdupq_n_f32(m(0, 2)), m10 = vdupq_n_f32(m(1, 0)),
                      m11 = vdupq_n_f32(m(1, 1)), m12 = vdupq_n_f32(m(1, 2)),
                      m20 = vdupq_n_f32(m(2, 0)), m21 = vdupq_n_f32(m(2, 1)),
                      m22 = vdupq_n_f32(m(2, 2));
    const float32x4_t tx = vdupq_n_f32(t.x), ty = vdupq_n_f32(t.y), tz = vdupq_n_f32(t.z);
    for (; i + 4 <= n; i += 4) {
        const float32x4x3_t p = vld3q_f32(in + 3 * i);
        float32x4x3_t r;
        r.val[0] = m00 * p.val[0] + m01 * p.val[1] + m02 * p.val[2];
        r.val[1] = m10 * p.val[0] + m11 * p.val[1] + m12 * p.val[2];
        r.val[2] = m20 * p.val[0] + m21 * p.val[1] + m22 * p.val[2];
        if constexpr (Translate) {
            r.val[0] += tx;
            r.val[1] += ty;
            r.val[2] += tz;
        }
        vst3q_f32(out + 3 * i, r);
    }
#else
    static_cast<void>(m), static_cast<void>(t), static_cast<void>(in), static_cast<void>(out),
        static_cast<void>(n);  // unused outside AArch64
#endif
    return i;
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_BATCH_DETAIL_INTERLEAVED_POINTS_NEON_HPP_INCLUDED
