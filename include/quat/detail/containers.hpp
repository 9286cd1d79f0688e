// The arrays quat's functions over many elements accept: any contiguous container or view with
// data() and size() members (std::vector, std::array, std::span), and C arrays.
#ifndef QUAT_DETAIL_CONTAINERS_HPP_INCLUDED
#define QUAT_DETAIL_CONTAINERS_HPP_INCLUDED

#include <cstddef>
#include <type_traits>
#include <utility>

namespace quat {

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

// Paired containers (docs/conventions.md, "Containers that must match"): whether every container
// holds as many elements as the first, which the fits and keyframe paths require, and the length
// all of them hold, the most a batch's container form may read or write.
template <class First, class... Rest>
[[nodiscard]] constexpr bool same_size(const First& first, const Rest&... rest) noexcept {
    return ((detail::size_of(rest) == detail::size_of(first)) && ...);
}
template <class First, class... Rest>
[[nodiscard]] constexpr std::size_t common_size(const First& first, const Rest&... rest) noexcept {
    std::size_t common = detail::size_of(first);
    ((common = detail::size_of(rest) < common ? detail::size_of(rest) : common), ...);
    return common;
}

// The T of a container of Value<T> (quaternion, vec3, rotation_matrix, dual_quaternion): the one
// way quat's container forms name the scalar type of their elements. Not a type for a container of
// anything else, so a container form whose default template argument uses it drops out of overload
// resolution. element_scalar is declared only, for the type of its result.
template <template <class> class Value, class T>
T element_scalar(const Value<T>*) noexcept;
template <template <class> class Value, class Container>
using element_scalar_t =
    decltype(detail::element_scalar<Value>(detail::data_of(std::declval<const Container&>())));

// Enables a container form: Input holds contiguous In, Output contiguous writable Out.
template <class In, class Out, class Input, class Output>
using if_arrays_of = std::enable_if_t<
    std::is_convertible_v<decltype(detail::data_of(std::declval<const Input&>())), const In*> &&
    std::is_convertible_v<decltype(detail::data_of(std::declval<Output&>())), Out*>>;

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_DETAIL_CONTAINERS_HPP_INCLUDED
