// The product of many factors in four interleaved chains: compose over an array of quaternions
// (batch/rotations.hpp) and of dual quaternions (batch/rigid_motions.hpp).
#ifndef QUAT_BATCH_DETAIL_CHAINED_PRODUCT_HPP_INCLUDED
#define QUAT_BATCH_DETAIL_CHAINED_PRODUCT_HPP_INCLUDED

#include <cstddef>

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

// The number of chains: enough for a CPU to overlap the products (each waits on its predecessor).
inline constexpr std::size_t product_chains = 4;

// The four chains of chained_product for types whose four running products the compiler keeps in
// registers as they are (quaternions): chain[j] = f[j run] f[j run + 1] ... f[j run + run - 1]. A
// type that needs another layout (dual quaternions, batch/rigid_motions.hpp) gives chained_product
// a class with the same static member.
template <class Value>
struct chain_values {
    static constexpr void run_products(const Value* f, std::size_t run,
                                       Value (&chain)[product_chains]) noexcept {
        Value acc[product_chains] = {Value::identity(), Value::identity(), Value::identity(),
                                     Value::identity()};
        for (std::size_t i = 0; i < run; ++i)
            for (std::size_t j = 0; j < product_chains; ++j) acc[j] = acc[j] * f[j * run + i];
        for (std::size_t j = 0; j < product_chains; ++j) chain[j] = acc[j];
    }
};

// The product f[0] f[1] ... f[count - 1] (f[count - 1] applies first); identity when count == 0.
// Four runs of consecutive factors are multiplied in interleaved, independent chains and the four
// partial products joined at the end, so the CPU overlaps four products instead of waiting on each:
// the same product as the left-to-right loop by associativity, rounded differently. Never inlined:
// g++ fuses multiply-adds differently in different callers (-ffp-contract=fast), and one copy keeps
// compose(factors) and compose(pointer, count) equal to the last bit.
template <class Value, class Chains = chain_values<Value>>
[[nodiscard, gnu::noinline]] constexpr Value chained_product(const Value* f,
                                                             std::size_t count) noexcept {
    constexpr std::size_t lanes = product_chains;
    if (count < 4 * lanes) {  // too short to win back the three products that join the chains
        Value product = Value::identity();
        for (std::size_t i = 0; i < count; ++i) product = product * f[i];
        return product;
    }
    const std::size_t run = count / lanes;
    Value chain[lanes] = {};
    Chains::run_products(f, run, chain);
    // The factors beyond the four runs join the last chain.
    for (std::size_t i = lanes * run; i < count; ++i) chain[lanes - 1] = chain[lanes - 1] * f[i];
    return (chain[0] * chain[1]) * (chain[2] * chain[3]);
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_BATCH_DETAIL_CHAINED_PRODUCT_HPP_INCLUDED
