// Mathematical constants, as C++20's <numbers> has them, in every language mode.
#ifndef QUAT_CONSTANTS_HPP_INCLUDED
#define QUAT_CONSTANTS_HPP_INCLUDED

namespace quat {

/// pi in the floating-point type T, correctly rounded (like std::numbers::pi_v<T>).
template <class T>
inline constexpr T pi_v = static_cast<T>(3.14159265358979323846264338327950288419716939937510L);

/// pi as a double (like std::numbers::pi).
inline constexpr double pi = pi_v<double>;

}  // namespace quat

#endif  // QUAT_CONSTANTS_HPP_INCLUDED
