// The 4-float vector every x86-64 build has (SSE2), in GCC/clang vector extensions, with what the
// SSE2, AVX and AVX-512 kernels share on it: loads and stores, lane selects and the lane square
// root. No intrinsics header (interleaved_points_avx.hpp says why).
#ifndef QUAT_BATCH_DETAIL_SSE_LANES_HPP_INCLUDED
#define QUAT_BATCH_DETAIL_SSE_LANES_HPP_INCLUDED

#include <cstring>

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

#if defined(__SSE2__) && defined(__has_builtin)
#if __has_builtin(__builtin_shufflevector)

using float4 = float __attribute__((vector_size(16)));

[[nodiscard]] inline float4 load4(const float* p) noexcept {
    float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline void store4(float* p, float4 v) noexcept { std::memcpy(p, &v, sizeof v); }

// Lane l of a where mask lane l is all ones, of b where it is zero (a blend).
template <class V, class Mask>
[[nodiscard]] inline V select_lanes(Mask mask, V a, V b) noexcept {
    static_assert(sizeof(Mask) == sizeof(V), "one mask lane per lane");
    Mask ai, bi;
    std::memcpy(&ai, &a, sizeof ai);
    std::memcpy(&bi, &b, sizeof bi);
    const Mask bits = (mask & ai) | (~mask & bi);
    V r;
    std::memcpy(&r, &bits, sizeof r);
    return r;
}

// The correctly rounded square root of each lane (sqrtps): a loop of __builtin_sqrtf stays scalar,
// since each call may set errno.
[[nodiscard]] inline float4 sqrt_lanes(float4 x) noexcept { return __builtin_ia32_sqrtps(x); }

#endif
#endif

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_BATCH_DETAIL_SSE_LANES_HPP_INCLUDED
