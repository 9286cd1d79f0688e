// Whether two arrays overlap: the aliasing preconditions of the functions over many elements
// (batch/rotations.hpp, batch/elementwise.hpp, batch/rigid_motions.hpp), checked by QUAT_ASSERT in
// debug builds.
#ifndef QUAT_BATCH_DETAIL_OVERLAP_HPP_INCLUDED
#define QUAT_BATCH_DETAIL_OVERLAP_HPP_INCLUDED

#include <cstddef>
#include <cstdint>

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

// True when the byte ranges [a, a + a_bytes) and [b, b + b_bytes) do not overlap (an empty range
// overlaps nothing). Compared as integers: relational operators on unrelated pointers are
// unspecified.
[[nodiscard]] inline bool disjoint(const void* a, std::size_t a_bytes, const void* b,
                                   std::size_t b_bytes) noexcept {
    const auto x = reinterpret_cast<std::uintptr_t>(a), y = reinterpret_cast<std::uintptr_t>(b);
    return a_bytes == 0 || b_bytes == 0 || x + a_bytes <= y || y + b_bytes <= x;
}
// True when the two ranges are one and the same (an in-place call) or do not overlap.
[[nodiscard]] inline bool same_or_disjoint(const void* a, std::size_t a_bytes, const void* b,
                                           std::size_t b_bytes) noexcept {
    return (a == b && a_bytes == b_bytes) || disjoint(a, a_bytes, b, b_bytes);
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_BATCH_DETAIL_OVERLAP_HPP_INCLUDED
