// Mathematical constants, as C++20's <numbers> has them, in every language mode, and conversions
// between degrees and radians. The constants live in quat::numbers, nested as the standard's are in
// std::numbers, so `using namespace quat;` brings in no `pi` to collide with a user's own: after
// it, write `numbers::pi`. radians and degrees are functions in quat itself, as GLM's are in glm.
#ifndef QUAT_CONSTANTS_HPP_INCLUDED
#define QUAT_CONSTANTS_HPP_INCLUDED

#include <type_traits>

#include "detail/math.hpp"

namespace quat {
namespace numbers {

/// pi in the floating-point type T, correctly rounded (like std::numbers::pi_v<T>).
template <class T>
inline constexpr T pi_v = static_cast<T>(3.14159265358979323846264338327950288419716939937510L);

/// pi as a double (like std::numbers::pi).
inline constexpr double pi = pi_v<double>;

}  // namespace numbers

#include "detail/isa_namespace.inc"
namespace detail {

/// pi / 180 in R. For float and double, computed in long double and rounded to R once: the
/// correctly rounded factor. A user scalar gets R(pi) / R(180).
template <class R>
[[nodiscard]] constexpr R radians_per_degree() noexcept {
    if constexpr (std::is_floating_point_v<R>) {
        return static_cast<R>(numbers::pi_v<long double> / 180.0L);
    } else {
        return detail::pi<R>() / R(180);
    }
}

/// 180 / pi in R, rounded as radians_per_degree.
template <class R>
[[nodiscard]] constexpr R degrees_per_radian() noexcept {
    if constexpr (std::is_floating_point_v<R>) {
        return static_cast<R>(180.0L / numbers::pi_v<long double>);
    } else {
        return R(180) / detail::pi<R>();
    }
}

}  // namespace detail

/// degrees * (pi / 180), the factor rounded once to the result type: float in, float out; an
/// integer gives a double (as std::sin does). GLM's glm::radians, and equal to it for double.
/// Not exact: radians(180.0) is pi to within an ulp, and degrees(radians(x)) may differ from x in
/// the last place.
template <class A>
[[nodiscard]] constexpr detail::real_t<A> radians(A angle_degrees) noexcept {
    using R = detail::real_t<A>;
    return static_cast<R>(angle_degrees) * detail::radians_per_degree<R>();
}

/// radians * (180 / pi), the factor rounded once to the result type: float in, float out; an
/// integer gives a double. GLM's glm::degrees.
template <class A>
[[nodiscard]] constexpr detail::real_t<A> degrees(A angle_radians) noexcept {
    using R = detail::real_t<A>;
    return static_cast<R>(angle_radians) * detail::degrees_per_radian<R>();
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_CONSTANTS_HPP_INCLUDED
