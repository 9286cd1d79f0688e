// The widest vector of float or double lanes an AVX, AVX-512 or AArch64 build has (GCC/clang vector
// extensions, no intrinsics header), for the struct-of-arrays loops of the batch functions. Those
// loops are written with it rather than left to the compiler: g++ 12 vectorizes them too, but peels
// up to a vector's worth of elements one by one to align one of the seven to ten arrays, which in
// rotate_each over 256 float elements cost as much as the vector loop (87 ns against 55 written
// out, AVX-512). Beyond the first-level cache those loops also prefetch their output lines
// (prefetch_outputs).
#ifndef QUAT_BATCH_DETAIL_WIDE_LANES_HPP_INCLUDED
#define QUAT_BATCH_DETAIL_WIDE_LANES_HPP_INCLUDED

#include <cstddef>
#include <cstring>
#include <type_traits>

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

template <class T>
struct wide_lanes {};  // no vector type: the plain loops do all the work

#if defined(__AVX__) || (defined(__aarch64__) && defined(__ARM_NEON))
// Bytes in the widest vector register of the build: AArch64's 16 too, where g++ 12 leaves these
// loops scalar at -O2 (15 scalar multiply-adds for the struct-of-arrays rotate, no vector one).
#if defined(__AVX512F__)
inline constexpr std::size_t wide_bytes = 64;
#elif defined(__AVX__)
inline constexpr std::size_t wide_bytes = 32;
#else
inline constexpr std::size_t wide_bytes = 16;
#endif
template <>
struct wide_lanes<float> {
    using type = float __attribute__((vector_size(wide_bytes)));
};
template <>
struct wide_lanes<double> {
    using type = double __attribute__((vector_size(wide_bytes)));
};
#endif

// True where wide_lanes<T> has a vector type (float and double in AVX and AArch64 builds).
template <class T, class = void>
inline constexpr bool has_wide_lanes = false;
template <class T>
inline constexpr bool has_wide_lanes<T, std::void_t<typename wide_lanes<T>::type>> = true;

template <class T>
using wide_t = typename wide_lanes<T>::type;

template <class T>
inline constexpr std::size_t wide_count = sizeof(wide_t<T>) / sizeof(T);

template <class T>
[[nodiscard]] inline wide_t<T> load_wide(const T* p) noexcept {
    wide_t<T> v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
template <class T>
inline void store_wide(T* p, const wide_t<T>& v) noexcept {
    std::memcpy(p, &v, sizeof v);
}
// Every lane s (a loop the compilers turn into one broadcast; s + a zero vector would turn -0 into
// +0).
template <class T>
[[nodiscard]] inline wide_t<T> broadcast_wide(T s) noexcept {
    wide_t<T> v;
    for (std::size_t lane = 0; lane < wide_count<T>; ++lane) v[lane] = s;
    return v;
}

// Bytes read and written beyond which the struct-of-arrays loops ask for their output lines ahead
// of their stores (prefetch_outputs): the Xeon's 48 KiB first-level cache. Its loops slow down
// past it (rotate over 2730 points: 0.45-0.48 ns a point, the array of structs 0.32); within it
// the requests only cost time (rotate over 1024 points, every line requested: 0.190 against 0.177).
inline constexpr std::size_t prefetch_bytes = std::size_t(48) << 10;

// Asks for the cache lines 1 KiB past element at of three output arrays of count elements (the
// last element's near the end) to be brought into the first-level cache for writing. Three output
// streams outrun the hardware's own prefetching of lines to be written: on an Intel Xeon (family
// 6 model 167, AVX-512) the struct-of-arrays rotate over 16K points took 0.44 ns a point and
// 1.36-1.39 over 1M, against 0.28 and 1.11-1.13 for the array of structs; with the requests 0.28
// and 0.88. rotate_each over 2048 elements: 0.80-0.89, against 0.49-0.65 for the array of structs
// and 0.46-0.54 with the requests. x86 only, where they were measured. A request never faults and
// changes no result.
template <class T>
inline void prefetch_outputs(T* x, T* y, T* z, std::size_t at, std::size_t count) noexcept {
#if defined(__x86_64__) || defined(__i386__)
    constexpr std::size_t distance = 1024 / sizeof(T);
    const std::size_t ahead = count - at > distance ? at + distance : count - 1;
    __builtin_prefetch(x + ahead, 1);
    __builtin_prefetch(y + ahead, 1);
    __builtin_prefetch(z + ahead, 1);
#else
    static_cast<void>(x), static_cast<void>(y), static_cast<void>(z), static_cast<void>(at),
        static_cast<void>(count);
#endif
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_BATCH_DETAIL_WIDE_LANES_HPP_INCLUDED
