// Sums over many elements in blocks: the fits (fitting/) and the geodesic means (lie/) add up
// thousands to millions of terms, and a plain running sum loses digits as it grows.
#ifndef QUAT_DETAIL_SUMMATION_HPP_INCLUDED
#define QUAT_DETAIL_SUMMATION_HPP_INCLUDED

#include <cstddef>

namespace quat {

#include "isa_namespace.inc"
namespace detail {

// The sums run over the input in blocks of this many elements, each block from zero, then add the
// blocks' sums: rounding errors grow with the block length plus the number of blocks instead of
// with the count.
inline constexpr std::size_t summation_block = 256;

/// Calls block(start, end) for [0, count) cut into consecutive pieces of at most summation_block
/// elements, in order: each caller sums a piece from zero, then adds the pieces' sums.
template <class Block>
constexpr void for_each_block(std::size_t count, Block block) noexcept {
    for (std::size_t start = 0; start < count; start += summation_block)
        block(start, count - start < summation_block ? count : start + summation_block);
}

// sum term(i) weight(i) and sum weight(i) over i in [0, count), in blocks.
template <class Value, class T>
struct weighted_sum {
    Value sum;
    T total;
};

// `zero` is Value's zero; term(i) returns a Value, weight(i) a T, and Value supports + and * T.
template <class T, class Value, class Term, class Weight>
[[nodiscard]] constexpr weighted_sum<Value, T> blocked_weighted_sum(std::size_t count,
                                                                    const Value& zero, Term term,
                                                                    Weight weight) noexcept {
    weighted_sum<Value, T> result{zero, T(0)};
    for_each_block(count, [&](std::size_t start, std::size_t end) {
        Value block = zero;
        T block_total = T(0);
        for (std::size_t i = start; i < end; ++i) {
            const T w = weight(i);
            block = block + term(i) * w;
            block_total = block_total + w;
        }
        result.sum = result.sum + block;
        result.total = result.total + block_total;
    });
    return result;
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_DETAIL_SUMMATION_HPP_INCLUDED
