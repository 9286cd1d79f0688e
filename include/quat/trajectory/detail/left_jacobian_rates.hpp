// The left Jacobian of SO(3) along a moving rotation vector, and its first two time derivatives,
// applied to a vector: what a translation written in twist coordinates needs. For the motion
// exp(xi(t)) of a twist xi = (rho, omega) the position is p = Jl(omega) rho, so
//     p' = Jl rho' + (Jl)' rho,   p'' = Jl rho'' + 2 (Jl)' rho' + (Jl)'' rho.
// With m = |omega|^2 and W = [omega]x, Jl(omega) = I + A(m) W + B(m) W^2 (J. Sola, J. Deray,
// D. Atchuthan, "A micro Lie theory for state estimation in robotics", 2018, eq. 145), where
//     A = (1 - cos n) / n^2,   dA/dm = -(2 (1 - cos n) - n sin n) / (2 n^4),
//     B = (n - sin n) / n^3,   dB/dm = (3 sin n - n cos n - 2n) / (2 n^5),
// (lie/detail/rotation_vector_jacobian.hpp's coefficients) and, differentiated once more in m,
//     d2A/dm2 = (8 - 8 cos n - 5 n sin n + n^2 cos n) / (4 n^6) = 1/360 - m/6720 + ...,
//     d2B/dm2 = (n^2 sin n + 7 n cos n + 8 n - 15 sin n) / (4 n^7) = 1/2520 - m/60480 + ...
// each summed from its Taylor series below n = 3, where the closed forms cancel.
#ifndef QUAT_TRAJECTORY_DETAIL_LEFT_JACOBIAN_RATES_HPP_INCLUDED
#define QUAT_TRAJECTORY_DETAIL_LEFT_JACOBIAN_RATES_HPP_INCLUDED

#include "../../detail/math.hpp"
#include "../../lie/detail/rotation_vector_jacobian.hpp"
#include "../../vec3.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

/// d2A/dm2 at m = n^2 (see the file comment): the series below n = 3, sum over k >= 2 of
/// (-1)^k k (k - 1) m^(k-2) / (2k + 2)!.
template <class T>
[[nodiscard]] constexpr T one_minus_cos_second_derivative(T n2, T n) noexcept {
    if (n2 >= T(9)) {
        const T c = detail::cos(n), s = detail::sin(n);
        return (T(8) - T(8) * c - T(5) * n * s + n2 * c) / (T(4) * n2 * n2 * n2);
    }
    return power_series(T(1) / T(360), [n2](int j) {
        return -n2 * T(j + 3) / T((j + 1) * (2 * j + 7) * (2 * j + 8));
    });
}

/// d2B/dm2 at m = n^2: the series below n = 3, sum over k >= 2 of (-1)^k k (k - 1) m^(k-2) /
/// (2k + 3)!.
template <class T>
[[nodiscard]] constexpr T n_minus_sin_second_derivative(T n2, T n) noexcept {
    if (n2 >= T(9)) {
        const T c = detail::cos(n), s = detail::sin(n);
        return (n2 * s + T(7) * n * c + T(8) * n - T(15) * s) / (T(4) * n2 * n2 * n2 * n);
    }
    return power_series(T(1) / T(2520), [n2](int j) {
        return -n2 * T(j + 3) / T((j + 1) * (2 * j + 8) * (2 * j + 9));
    });
}

/// Jl(omega(t)) and its first two time derivatives at one t, ready to apply to vectors: omega
/// with rate omega1 and second derivative omega2, and the coefficients of the file comment.
template <class T>
struct left_jacobian_rates {
    vec3<T> omega, omega1, omega2;
    T a, b, a1, b1, a2, b2, m1, m2;

    /// Jl x, (d/dt Jl) x and (d2/dt2 Jl) x for a fixed x.
    struct terms {
        vec3<T> value, rate, second;
    };

    [[nodiscard]] constexpr terms operator()(const vec3<T>& x) const noexcept {
        // W x, W^2 x and their derivatives for fixed x.
        const vec3<T> wx = cross(omega, x), w1x = cross(omega1, x), w2x = cross(omega2, x);
        const vec3<T> wwx = cross(omega, wx);
        const vec3<T> wwx1 = cross(omega1, wx) + cross(omega, w1x);
        const vec3<T> wwx2 = cross(omega2, wx) + cross(omega1, w1x) * T(2) + cross(omega, w2x);
        return {x + wx * a + wwx * b, wx * (a1 * m1) + w1x * a + wwx * (b1 * m1) + wwx1 * b,
                wx * (a2 * m1 * m1 + a1 * m2) + w1x * (T(2) * a1 * m1) + w2x * a +
                    wwx * (b2 * m1 * m1 + b1 * m2) + wwx1 * (T(2) * b1 * m1) + wwx2 * b};
    }
};

/// The rates of Jl along omega(t) with derivatives omega1 and omega2. Any finite omega.
template <class T>
[[nodiscard]] constexpr left_jacobian_rates<T> left_jacobian_rates_of(
    const vec3<T>& omega, const vec3<T>& omega1, const vec3<T>& omega2) noexcept {
    const T n = norm(omega), n2 = squared_angle(omega, n);
    return {omega,
            omega1,
            omega2,
            one_minus_cos_over_square(n2, n),
            n_minus_sin_over_cube(n2, n),
            quartic_coefficient(n2, n) * T(-0.5),
            quintic_coefficient(n2, n) * T(0.5),
            one_minus_cos_second_derivative(n2, n),
            n_minus_sin_second_derivative(n2, n),
            T(2) * dot(omega, omega1),
            T(2) * (dot(omega1, omega1) + dot(omega, omega2))};
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_DETAIL_LEFT_JACOBIAN_RATES_HPP_INCLUDED
