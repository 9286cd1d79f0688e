// Bitwise equality for the tests that promise "the same operations, not merely equal values" (a
// spelling against its long form): the objects' bytes compared, so -0 differs from 0 and a NaN
// equals only the same NaN. For the library's value types, which have no padding.
#pragma once

#include <array>
#include <cstring>
#include <type_traits>

namespace quat::test {

/// True when a and b hold the same bits.
template <class V>
bool same_bits(const V& a, const V& b) {
    static_assert(std::is_trivially_copyable_v<V>, "compares object representations");
    std::array<unsigned char, sizeof(V)> x{}, y{};
    std::memcpy(x.data(), &a, sizeof(V));
    std::memcpy(y.data(), &b, sizeof(V));
    return x == y;
}

}  // namespace quat::test
