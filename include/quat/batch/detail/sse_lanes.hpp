// The 4-float vector every x86-64 build has (SSE2), in GCC/clang vector extensions, with what the
// SSE2, AVX and AVX-512 kernels share on it: loads and stores, lane selects and the lane square
// root. No intrinsics header (interleaved_points_avx.hpp says why).
#ifndef QUAT_BATCH_DETAIL_SSE_LANES_HPP_INCLUDED
#define QUAT_BATCH_DETAIL_SSE_LANES_HPP_INCLUDED

#include <cstddef>
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

// Whether every lane of a comparison's mask is set: a reduction without a branch per lane, by one
// movmskps on 4 lanes (g++ 12 extracts and ands them one by one: 9 instructions in place of 2).
template <class Mask>
[[nodiscard]] inline bool all_lanes(Mask mask) noexcept {
    if constexpr (sizeof(Mask) == sizeof(float4)) {
        float4 bits;
        std::memcpy(&bits, &mask, sizeof bits);
        return __builtin_ia32_movmskps(bits) == 0xF;
    } else {
        int clear = 0;
        for (std::size_t l = 0; l < sizeof(Mask) / sizeof(mask[0]); ++l) clear |= ~mask[l];
        return clear == 0;
    }
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
