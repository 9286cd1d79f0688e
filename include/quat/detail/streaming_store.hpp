// Non-temporal stores for the batch functions: the one place quat uses x86 intrinsics.
#ifndef QUAT_DETAIL_STREAMING_STORE_HPP_INCLUDED
#define QUAT_DETAIL_STREAMING_STORE_HPP_INCLUDED

#include <cstddef>
#include <cstdint>

#if defined(__SSE__) || defined(_M_X64)
#include <xmmintrin.h>
#endif

namespace quat {
// Keyed by instruction set (see detail/math.hpp): has_streaming_stores and the code below depend on
// __SSE__, which the key includes.
#include "isa_namespace.inc"
namespace detail {

// True where stream_floats writes past the caches (x86 with SSE); elsewhere it is a plain copy.
#if defined(__SSE__) || defined(_M_X64)
inline constexpr bool has_streaming_stores = true;
#else
inline constexpr bool has_streaming_stores = false;
#endif

// Copies n floats to `to` with non-temporal stores where the target has them (x86 SSE), plain
// stores elsewhere.
inline void stream_floats(float* to, const float* from, std::size_t n) noexcept {
    std::size_t i = 0;
#if defined(__SSE__) || defined(_M_X64)
    for (; i < n && reinterpret_cast<std::uintptr_t>(to + i) % 16 != 0; ++i) to[i] = from[i];
    for (; i + 4 <= n; i += 4) _mm_stream_ps(to + i, _mm_loadu_ps(from + i));
#endif
    for (; i < n; ++i) to[i] = from[i];
}

// Makes the streamed stores visible before returning, like ordinary stores.
inline void stream_fence() noexcept {
#if defined(__SSE__) || defined(_M_X64)
    _mm_sfence();
#endif
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_DETAIL_STREAMING_STORE_HPP_INCLUDED
