// Non-temporal stores for the batch functions, and the last-level cache size that decides when they
// pay: the one place quat uses x86 non-temporal stores and cpuid.
#ifndef QUAT_BATCH_DETAIL_STREAMING_STORE_HPP_INCLUDED
#define QUAT_BATCH_DETAIL_STREAMING_STORE_HPP_INCLUDED

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__))
#include <cpuid.h>
#elif defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
#include <intrin.h>
#endif

namespace quat {
// Keyed by instruction set (see detail/math.hpp): has_streaming_stores and the code below depend on
// __SSE__, __AVX__ and __AVX512F__, which the key includes.
#include "../../detail/isa_namespace.inc"
namespace detail {

// True where stream_floats writes past the caches (x86 with SSE); elsewhere it is a plain copy.
// The stores are the compilers' builtins, not <xmmintrin.h>'s functions: that header added 102
// million instructions (12 %) to g++ 12's parse of bench/compile_time.sh's unit.
#if defined(__SSE__) && defined(__has_builtin)
#if __has_builtin(__builtin_nontemporal_store) || __has_builtin(__builtin_ia32_movntps)
inline constexpr bool has_streaming_stores = true;
#else
inline constexpr bool has_streaming_stores = false;
#endif
#else
inline constexpr bool has_streaming_stores = false;
#endif

// Floats per non-temporal store: the widest vector of the build. A 64-byte store (AVX-512) fills a
// cache line at once; narrower ones fill it in order, which the write-combining buffer joins.
// Measured on a Zen 4 (4M points, g++ 12, medians of 9): 256-bit stores moved the batch rotate
// 5-15 % faster than 128-bit ones.
#if defined(__AVX512F__) && defined(__has_builtin)
#if __has_builtin(__builtin_nontemporal_store) || __has_builtin(__builtin_ia32_movntps512)
inline constexpr std::size_t stream_width = 16;
#else
inline constexpr std::size_t stream_width = 4;
#endif
#elif defined(__AVX__) && defined(__has_builtin)
#if __has_builtin(__builtin_nontemporal_store) || __has_builtin(__builtin_ia32_movntps256)
inline constexpr std::size_t stream_width = 8;
#else
inline constexpr std::size_t stream_width = 4;
#endif
#else
inline constexpr std::size_t stream_width = 4;
#endif

// One non-temporal store of Width floats (4, or up to stream_width) from `from` (any alignment) to
// `to` (aligned to the store's width) where the target has them (has_streaming_stores), a plain
// copy elsewhere. clang spells every width with one builtin, g++ has one per width.
template <std::size_t Width = stream_width>
inline void stream_vector(float* to, const float* from) noexcept {
    static_assert(Width == 4 || ((Width == 8 || Width == 16) && Width <= stream_width),
                  "a non-temporal store the build has");
    if constexpr (has_streaming_stores) {
        // Spelled out per width: g++ 12 drops a vector_size that depends on a template parameter.
        using vector4 = float __attribute__((vector_size(16)));
        using vector8 = float __attribute__((vector_size(32)));
        using vector16 = float __attribute__((vector_size(64)));
        using vector = std::conditional_t<Width == 16, vector16,
                                          std::conditional_t<Width == 8, vector8, vector4>>;
        vector v;
        std::memcpy(&v, from, sizeof v);
#if defined(__has_builtin)
#if __has_builtin(__builtin_nontemporal_store)
        __builtin_nontemporal_store(v, reinterpret_cast<vector*>(to));
#elif __has_builtin(__builtin_ia32_movntps)
        if constexpr (Width == 16) {
#if defined(__AVX512F__) && __has_builtin(__builtin_ia32_movntps512)
            __builtin_ia32_movntps512(to, v);
#endif
        } else if constexpr (Width == 8) {
#if defined(__AVX__) && __has_builtin(__builtin_ia32_movntps256)
            __builtin_ia32_movntps256(to, v);
#endif
        } else {
            __builtin_ia32_movntps(to, v);
        }
#endif
#endif
    } else {
        std::memcpy(to, from, Width * sizeof(float));
    }
}

// Whether p is a multiple of `bytes` (a power of two): the alignment every streaming path checks.
[[nodiscard]] inline bool is_aligned(const void* p, std::size_t bytes) noexcept {
    return reinterpret_cast<std::uintptr_t>(p) % bytes == 0;
}

// Which way a loop that streams its outputs keeps its loads off the 4K aliases of its pending
// non-temporal stores: a load whose address matches such a store's in the low 12 bits waits for
// it. Going upward, the loads run ahead of the stores, so an output array that lies less than
// `reach` bytes past an input array, modulo 4096, keeps putting loads there; going downward, one
// that lies as far before it. An output array that is an input array (distance 0) is safe.
// Zen 4, struct-of-arrays rotate_each, 4M elements, 16-byte pieces, all outputs the same distance
// past all inputs (harness, medians of 15 interleaved calls): x86-64-v3, 64 to 192 bytes past
// 2.9-7.1 ns an element upward against 1.3-1.5 downward and 1.6-2.0 plainly, and the mirror image
// for distances before; AVX-512, 128 to 384 bytes past 1.8-6.9 against 1.1-1.3 and 1.6-2.3.
enum class sweep { upward, downward, neither };

template <std::size_t Inputs, std::size_t Outputs>
[[nodiscard]] sweep sweep_clear_of_aliasing(const float* const (&inputs)[Inputs],
                                            const float* const (&outputs)[Outputs],
                                            std::uintptr_t reach) noexcept {
    constexpr std::uintptr_t page = 4096;
    bool upward = true, downward = true;
    for (const float* input : inputs) {
        const auto from = reinterpret_cast<std::uintptr_t>(input);
        for (const float* output : outputs) {
            const std::uintptr_t past = (reinterpret_cast<std::uintptr_t>(output) - from) % page;
            upward = upward && (past == 0 || past >= reach);
            downward = downward && (past == 0 || page - past >= reach);
        }
    }
    return upward ? sweep::upward : downward ? sweep::downward : sweep::neither;
}

// Copies n floats to `to` with non-temporal stores where the target has them (x86 SSE), plain
// stores elsewhere: plain stores up to the first address aligned to the store's width, then the
// widest non-temporal stores of the build.
inline void stream_floats(float* to, const float* from, std::size_t n) noexcept {
    std::size_t i = 0;
    if constexpr (has_streaming_stores) {
        constexpr std::size_t bytes = sizeof(float) * stream_width;
        for (; i < n && !is_aligned(to + i, bytes); ++i) to[i] = from[i];
        for (; i + stream_width <= n; i += stream_width) stream_vector(to + i, from + i);
    }
    for (; i < n; ++i) to[i] = from[i];
}

// How many of the count elements at `at` lie before its first 64-byte boundary (at most 16; 16
// or count where no element starts one): the streaming paths store those plainly, so that no
// cache line is written partly by plain and partly by non-temporal stores.
template <class Element>
[[nodiscard]] inline std::size_t elements_before_line(const Element* at,
                                                      std::size_t count) noexcept {
    std::size_t n = 0;
    while (n < 64 / sizeof(float) && n < count && !is_aligned(at + n, 64)) ++n;
    return n;
}

// Makes the streamed stores visible before returning, like ordinary stores.
inline void stream_fence() noexcept {
#if defined(__SSE__) && defined(__has_builtin)
#if __has_builtin(__builtin_ia32_sfence)
    __builtin_ia32_sfence();
#endif
#endif
}

// The size in bytes of the largest cache that cpuid's deterministic cache parameters describe
// (Intel's leaf 4, AMD's leaf 0x8000001D: the same layout; the one that does not apply reads as
// no caches), for the core that asks: on AMD that is its CCX's L3, not the sum over the chip.
// 0 where there is no cpuid or it describes no cache.
inline std::size_t cpuid_largest_cache_bytes() noexcept {
    std::size_t largest = 0;
#if ((defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__))) || \
    (defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86)))
    const unsigned leaves[] = {4u, 0x8000001Du};
    for (const unsigned leaf : leaves) {
        for (unsigned index = 0; index < 16; ++index) {
            unsigned a = 0, b = 0, c = 0, d = 0;
#if defined(_MSC_VER) && !defined(__clang__)
            int r[4] = {};
            __cpuid(r, static_cast<int>(leaf & 0x80000000u));
            if (static_cast<unsigned>(r[0]) < leaf) break;
            __cpuidex(r, static_cast<int>(leaf), static_cast<int>(index));
            a = static_cast<unsigned>(r[0]), b = static_cast<unsigned>(r[1]);
            c = static_cast<unsigned>(r[2]), d = static_cast<unsigned>(r[3]);
#else
            // Returns 0 when the leaf is beyond the processor's maximum.
            if (__get_cpuid_count(leaf, index, &a, &b, &c, &d) == 0) break;
#endif
            static_cast<void>(d);
            if ((a & 31u) == 0) break;     // cache type "null": no more caches
            if ((a & 31u) == 2) continue;  // instruction cache
            const std::size_t ways = (b >> 22) + 1, partitions = ((b >> 12) & 1023u) + 1,
                              line = (b & 4095u) + 1, sets = std::size_t(c) + 1;
            const std::size_t size = ways * partitions * line * sets;
            if (size > largest) largest = size;
        }
        if (largest != 0) break;
    }
#endif
    return largest;
}

// The threshold where no cache size can be read, and the largest any cache size sets: 16 MiB of
// output, which a Zen 4's 32 MiB L3 sets itself. A last-level cache of hundreds of MiB, a server
// part's shared by its many cores, keeps far less of one core's data than its size says: on an
// Intel Xeon whose cpuid reports 480 MiB (2 vCPUs), 4M points in quat_bench (three runs of
// 7 repetitions) took 1.56-1.66 ns a point streamed against 2.69-2.74 plainly (struct of arrays),
// rotate_each 2.63-2.70 against 3.18-3.20, compose_each 2.85-2.88 against 3.66-3.71; from 256K
// points streaming was ahead there too (a harness: 1.1-1.6 against 1.5-2.9), at 64K behind (2.3-2.6
// against 1.3-1.4). Not lower than 16 MiB: the Zen 4 was not measured streaming smaller outputs.
inline constexpr std::size_t largest_streaming_threshold = std::size_t(16) << 20;

// No output smaller than this is streamed, whatever the cache size says: it stays in any
// x86 core's L2.
inline constexpr std::size_t minimum_streaming_bytes = std::size_t(128) << 10;

// The last-level cache size in bytes, read once from cpuid (0 where it does not answer). Not from
// sysconf, whose L3 figure virtual machines may invent (320 MiB on a Zen 4 guest whose cpuid and
// lscpu say 32 MiB), and which would bring <unistd.h>'s names into every user's code: streaming
// happens only on x86, where cpuid is always there.
inline std::size_t last_level_cache_bytes() noexcept {
    static const std::size_t bytes = cpuid_largest_cache_bytes();
    return bytes;
}

// The batch functions stream an output of at least this many bytes. The rule: stream when the
// data one call touches, input and output (twice the output), exceeds the last-level cache, so
// the output cannot stay cached for a next pass anyway and a plain store's read for ownership of
// each line only adds a third to the memory traffic; below that plain stores, which leave the
// result in cache. Never above largest_streaming_threshold (also the threshold without a cache
// size), never below minimum_streaming_bytes.
inline std::size_t streaming_threshold_bytes() noexcept {
    const std::size_t cache = last_level_cache_bytes();
    const std::size_t half = cache == 0 || cache / 2 > largest_streaming_threshold
                                 ? largest_streaming_threshold
                                 : cache / 2;
    return half < minimum_streaming_bytes ? minimum_streaming_bytes : half;
}

// Whether an output of this many bytes is streamed; the constant first, so that a small batch does
// not ask for the cache size.
[[nodiscard]] inline bool streams_output(std::size_t bytes) noexcept {
    return has_streaming_stores && bytes >= minimum_streaming_bytes &&
           bytes >= streaming_threshold_bytes();
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_BATCH_DETAIL_STREAMING_STORE_HPP_INCLUDED
