// The arrays quat's functions over many elements accept: any contiguous container or view with
// data() and size() members (std::vector, std::array, std::span), and C arrays.
#ifndef QUAT_DETAIL_CONTAINERS_HPP_INCLUDED
#define QUAT_DETAIL_CONTAINERS_HPP_INCLUDED

#include <cstddef>
#include <utility>

namespace quat {

template <class T>
struct quaternion;

#include "isa_namespace.inc"
namespace detail {

// std::data and std::size without <iterator>, which alone adds about 0.18 s (g++ 12 -O2) to every
// translation unit that includes quat.hpp: half its compile time.
template <class Container>
[[nodiscard]] constexpr auto data_of(Container& c) noexcept -> decltype(c.data()) {
    return c.data();
}
template <class T, std::size_t N>
[[nodiscard]] constexpr T* data_of(T (&array)[N]) noexcept {
    return array;
}
template <class Container>
[[nodiscard]] constexpr auto size_of(const Container& c) noexcept -> decltype(c.size()) {
    return c.size();
}
template <class T, std::size_t N>
[[nodiscard]] constexpr std::size_t size_of(const T (&)[N]) noexcept {
    return N;
}

// The T of a container of quaternion<T>: declared only, for the type of its data.
template <class T>
T quaternion_scalar(const quaternion<T>*) noexcept;
template <class Rotations>
using quaternion_scalar_t =
    decltype(detail::quaternion_scalar(detail::data_of(std::declval<const Rotations&>())));

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_DETAIL_CONTAINERS_HPP_INCLUDED
