// The 24 Euler conventions as a compile-time list, for tests that check each one.
#pragma once

#include <cstddef>
#include <utility>

#include <quat/euler.hpp>

namespace quat::test {

inline constexpr sequence all_sequences[] = {
    sequence::xyz, sequence::xzy, sequence::yxz, sequence::yzx, sequence::zxy, sequence::zyx,
    sequence::xyx, sequence::xzx, sequence::yxy, sequence::yzy, sequence::zxz, sequence::zyz};

template <class T, class F, std::size_t... N>
void for_each_convention(F&& f, std::index_sequence<N...>) {
    (f(euler<T, all_sequences[N], frame::intrinsic>{}), ...);
    (f(euler<T, all_sequences[N], frame::extrinsic>{}), ...);
}

/// Calls f(euler<T, S, F>{}) for all 24 conventions: 12 sequences, intrinsic then extrinsic.
template <class T, class F>
void for_each_convention(F&& f) {
    for_each_convention<T>(std::forward<F>(f), std::make_index_sequence<12>{});
}

}  // namespace quat::test
