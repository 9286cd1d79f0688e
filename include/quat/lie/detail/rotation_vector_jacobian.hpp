// Derivatives of the exponential map of rotation vectors: how a rotation vector's rate of change
// turns into an angular velocity, back, and the term its second derivative adds to an angular
// acceleration. For R(t) = R0 exp([r(t)]x) the body angular velocity is J(r) r' and the angular
// acceleration J(r) r'' + (d/dt J(r)) r', with J the right Jacobian of SO(3),
//     J(r) = I - (1 - cos n) / n^2 [r]x + (n - sin n) / n^3 [r]x^2,  n = |r|
// (J. Sola, J. Deray, D. Atchuthan, "A micro Lie theory for state estimation in robotics", 2018,
// eqs. 143-144; F. Bullo, R. Murray, "Proportional derivative control on the Euclidean group",
// 1995). Each coefficient is an analytic function of n^2: near zero, where the closed forms lose
// their digits to cancellation, it is summed from its Taylor series. The same coefficients build
// lie/so3.hpp's and lie/se3.hpp's Jacobians.
//
// Every coefficient takes both n2 = n^2 and n, and reads n only in its closed form, away from zero:
// a dual-number scalar (ceres::Jet) differentiates n = sqrt(n^2) at 0 as 0/0 = NaN, so near zero
// only n2 may be on the differentiated path (as detail::cos_sinc does). The one-argument forms,
// f(n) = f(n n, n), are those paths/rotation_spline.hpp calls.
#ifndef QUAT_LIE_DETAIL_ROTATION_VECTOR_JACOBIAN_HPP_INCLUDED
#define QUAT_LIE_DETAIL_ROTATION_VECTOR_JACOBIAN_HPP_INCLUDED

#include <limits>
#include <type_traits>

#include "../../detail/math.hpp"
#include "../../matrix.hpp"
#include "../../vec3.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

// sum over k >= 0 of term_k, with term_0 = first and term_(k+1) = term_k * ratio(k), until the
// terms no longer change the sum (at most 40 terms; the series here are used where |ratio| < 1/2).
// The series are in x = n^2, term_k = c_k x^k. A user scalar (a dual number) carries derivatives,
// and its comparisons read only the value: near x = 0 the value stops changing after c_0, while
// d term_1 / dx = c_1 is the whole derivative. So a user scalar always takes term_1 and stops only
// when a term no longer changes term_1 (then j term_j / x, its derivative, is below epsilon c_1).
template <class T, class Ratio>
[[nodiscard]] constexpr T power_series(T first, Ratio ratio) noexcept {
    T sum = first, term = first, linear = first;
    for (int k = 0; k < 40; ++k) {
        term = term * ratio(k);
        const T next = sum + term;
        if constexpr (std::is_floating_point_v<T>) {
            if (next == sum) break;
        } else if (k == 0) {
            linear = term;
        } else if (linear + term == linear) {
            break;
        }
        sum = next;
    }
    return sum;
}

/// |r|^2 to pass with n = norm(r) to the coefficients below: n n for a floating-point type (so the
/// results are those of the closed forms written in n, bit for bit), squared_norm(r) for a user
/// scalar, whose derivative at r = 0 must not pass through n = sqrt(0).
template <class T>
[[nodiscard]] constexpr T squared_angle(const vec3<T>& r, T n) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        return n * n;
    } else {
        return squared_norm(r);
    }
}

/// (1 - cos n) / n^2 = (sin(n/2) / (n/2))^2 / 2 = 1/2 - n^2/24 + n^4/720 - ..., with no
/// cancellation at any n. A floating-point type takes sin(n/2) / (n/2), correct to rounding down
/// to the smallest n (and 1 at n = 0); a user scalar takes the series below n = 2, whose
/// derivatives are as accurate as its value (those of sin(h) / h lose epsilon / h^2 relative).
template <class T>
[[nodiscard]] constexpr T one_minus_cos_over_square(T n2, T n) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        // n2 is not read: n2 underflows to 0 only where sin(n/2) / (n/2) rounds to 1 anyway.
        static_cast<void>(n2);
    } else {
        if (n2 < T(4))
            return power_series(T(0.5), [n2](int k) { return -n2 / T((2 * k + 3) * (2 * k + 4)); });
    }
    const T half = n / T(2);
    const T sinc = half == T(0) ? T(1) : detail::sin(half) / half;
    return sinc * sinc / T(2);
}
/// one_minus_cos_over_square(n n, n).
template <class T>
[[nodiscard]] constexpr T one_minus_cos_over_square(T n) noexcept {
    return one_minus_cos_over_square(n * n, n);
}

/// (n - sin n) / n^3 = 1/6 - n^2/120 + n^4/5040 - ...
template <class T>
[[nodiscard]] constexpr T n_minus_sin_over_cube(T n2, T n) noexcept {
    if (n2 >= T(4)) return (n - detail::sin(n)) / (n2 * n);
    return power_series(T(1) / T(6), [n2](int k) { return -n2 / T((2 * k + 4) * (2 * k + 5)); });
}

/// quartic_coefficient's closed form, for n >= 2, given a = one_minus_cos_over_square(n2, n) and
/// sin n.
template <class T>
[[nodiscard]] constexpr T quartic_closed_form(T n2, T n, T a, T sin_n) noexcept {
    return (T(2) * n2 * a - n * sin_n) / (n2 * n2);
}

/// (2 (1 - cos n) - n sin n) / n^4 = 1/12 - n^2/180 + n^4/6720 - ...
template <class T>
[[nodiscard]] constexpr T quartic_coefficient(T n2, T n) noexcept {
    if (n2 >= T(4))
        return quartic_closed_form(n2, n, one_minus_cos_over_square(n2, n), detail::sin(n));
    return power_series(T(1) / T(12), [n2](int j) {
        const int k = j + 2;
        return -n2 * T(k) / T((k - 1) * (2 * k + 1) * (2 * k + 2));
    });
}

/// (3 sin n - n cos n - 2n) / n^5 = -1/60 + n^2/1260 - n^4/60480 + ... (scipy 1.10 writes the
/// second term n^2/12604 in its series branch; at its switch, n < 1e-4, that changes nothing).
template <class T>
[[nodiscard]] constexpr T quintic_coefficient(T n2, T n) noexcept {
    if (n2 >= T(9)) return (T(3) * detail::sin(n) - n * detail::cos(n) - T(2) * n) / (n2 * n2 * n);
    return power_series(T(-1) / T(60), [n2](int j) {
        const int k = j + 2;
        return -n2 * T(k) / T((k - 1) * (2 * k + 2) * (2 * k + 3));
    });
}

/// (n^2 + 2 cos n - 2) / (2 n^4) = (1/2 - (1 - cos n) / n^2) / n^2 = 1/24 - n^2/720 + n^4/40320
/// - ...: the third coefficient of SE(3)'s Q block (T. Barfoot, "State Estimation for Robotics",
/// 2017, eq. 7.86). The closed form cancels by at most 3.4 times where it is used (n >= 2).
template <class T>
[[nodiscard]] constexpr T cosine_remainder_coefficient(T n2, T n) noexcept {
    if (n2 >= T(4)) return (T(0.5) - one_minus_cos_over_square(n2, n)) / n2;
    return power_series(T(1) / T(24), [n2](int j) {
        const int k = j + 2;  // term_k = (-1)^k n^(2k - 4) / (2k)!
        return -n2 / T((2 * k + 1) * (2 * k + 2));
    });
}

/// (1 - (n/2) cot(n/2)) / n^2 = 1/n^2 - (1 + cos n) / (2 n sin n) = 1/12 + n^2/720 + ..., the
/// [r]x^2 coefficient of J(r)^-1, as quartic_coefficient / (2 one_minus_cos_over_square): both
/// free of cancellation. For n < 2 pi.
template <class T>
[[nodiscard]] constexpr T inverse_jacobian_coefficient(T n2, T n) noexcept {
    // a once: the closed form of the quartic coefficient needs it too (a sine saved past n = 2).
    const T a = one_minus_cos_over_square(n2, n);
    const T quartic =
        n2 >= T(4) ? quartic_closed_form(n2, n, a, detail::sin(n)) : quartic_coefficient(n2, n);
    return quartic / (T(2) * a);
}
/// inverse_jacobian_coefficient(n n, n).
template <class T>
[[nodiscard]] constexpr T inverse_jacobian_coefficient(T n) noexcept {
    return inverse_jacobian_coefficient(n * n, n);
}

/// a I + b [r]x + c [r]x^2 as a matrix, with [r]x v = r x v and [r]x^2 = r r^T - |r|^2 I: the shape
/// of every Jr, Jl and inverse here (lie/so3.hpp) and of the blocks of rotation_spline's solve.
template <class T>
[[nodiscard]] constexpr matrix3<T> skew_polynomial(const vec3<T>& r, T a, T b, T c) noexcept {
    const T diagonal = a - c * squared_norm(r);
    const T bx = b * r.x, by = b * r.y, bz = b * r.z;
    const T cxy = c * r.x * r.y, cxz = c * r.x * r.z, cyz = c * r.y * r.z;
    return {{{diagonal + c * r.x * r.x, cxy - bz, cxz + by},
             {cxy + bz, diagonal + c * r.y * r.y, cyz - bx},
             {cxz - by, cyz + bx, diagonal + c * r.z * r.z}}};
}

/// The coefficients of Jr = I - a [r]x + b [r]x^2 and of Jr^-1 = I + [r]x / 2 + c [r]x^2.
template <class T>
struct right_jacobian_coefficients {
    T a, b, c;
};

/// a, b and c (c only when `inverse` is set) at n = |r|, n2 = n n, for a floating-point T, from
/// half = cos_sinc(|r|^2 / 4, n / 2), the one sincos that from_rotation_vector computes too: a =
/// sinc^2 / 2 (one_minus_cos_over_square's form), sin n = n sinc cos in the closed forms past
/// n = 2, the series below.
template <class T>
[[nodiscard]] constexpr right_jacobian_coefficients<T> right_jacobian_coefficients_of(
    T n2, T n, const cos_and_sinc<T>& half, bool inverse) noexcept {
    static_assert(std::is_floating_point_v<T>, "a user scalar takes the series in n^2");
    const T a = half.sinc * half.sinc / T(2);
    if (n2 >= T(4)) {
        const T sin_n = n * half.sinc * half.cos;
        return {a, (n - sin_n) / (n2 * n),
                inverse ? quartic_closed_form(n2, n, a, sin_n) / (T(2) * a) : T(0)};
    }
    return {a, n_minus_sin_over_cube(n2, n),
            inverse ? quartic_coefficient(n2, n) / (T(2) * a) : T(0)};
}

/// The half angle's cosine and sinc of the rotation vector r, from_rotation_vector's expression:
/// so3::exp and the Jacobians share it, bit for bit.
template <class T>
[[nodiscard]] constexpr cos_and_sinc<T> half_angle_of(const vec3<T>& r) noexcept {
    return cos_sinc(squared_norm(r) * T(0.25), norm(r) * T(0.5));
}

/// Jr(r)'s coefficients a and b, or with `inverse` Jr(r)^-1's c: the one path every Jr and Jr^-1 of
/// lie/so3.hpp, lie/se3.hpp and paths/rotation_spline.hpp takes. A floating-point T takes the half
/// angle (above); a user scalar the functions in n^2 above, whose derivatives are finite at r = 0.
template <class T>
[[nodiscard]] constexpr right_jacobian_coefficients<T> right_jacobian_coefficients_of(
    const vec3<T>& r, bool inverse) noexcept {
    const T n = norm(r), n2 = squared_angle(r, n);
    if constexpr (std::is_floating_point_v<T>) {
        return right_jacobian_coefficients_of(n2, n, half_angle_of(r), inverse);
    } else {
        if (inverse) return {T(0), T(0), inverse_jacobian_coefficient(n2, n)};
        return {one_minus_cos_over_square(n2, n), n_minus_sin_over_cube(n2, n), T(0)};
    }
}

/// J(r) v: the body angular velocity of R0 exp([r]x) when r changes at the rate v.
template <class T>
[[nodiscard]] constexpr vec3<T> right_jacobian(const vec3<T>& r, const vec3<T>& v) noexcept {
    const right_jacobian_coefficients<T> k = right_jacobian_coefficients_of(r, false);
    const vec3<T> c = cross(r, v);
    return v - c * k.a + cross(r, c) * k.b;
}

/// n_minus_sin_over_cube, quartic_coefficient and quintic_coefficient at one |r|: a solve that
/// evaluates right_jacobian_rate at a fixed r many times computes them once (they are most of its
/// cost: each is a series or a sine).
template <class T>
struct jacobian_rate_coefficients {
    T cubic, quartic, quintic;
};

/// The coefficients at n = |r|, n2 = |r|^2.
template <class T>
[[nodiscard]] constexpr jacobian_rate_coefficients<T> jacobian_rate_coefficients_of(T n2,
                                                                                    T n) noexcept {
    return {n_minus_sin_over_cube(n2, n), quartic_coefficient(n2, n), quintic_coefficient(n2, n)};
}
/// jacobian_rate_coefficients_of(n n, n).
template <class T>
[[nodiscard]] constexpr jacobian_rate_coefficients<T> jacobian_rate_coefficients_of(T n) noexcept {
    return jacobian_rate_coefficients_of(n * n, n);
}

/// (d/dt J(r)) v for r changing at the rate v, with k the coefficients at |r|.
template <class T>
[[nodiscard]] constexpr vec3<T> right_jacobian_rate(
    const vec3<T>& r, const vec3<T>& v, const jacobian_rate_coefficients<T>& k) noexcept {
    const vec3<T> c = cross(r, v);
    return (c * k.quartic + cross(r, c) * k.quintic) * dot(r, v) + cross(v, c) * k.cubic;
}

/// (d/dt J(r)) v for r changing at the rate v: the part of the angular acceleration that is
/// quadratic in v.
template <class T>
[[nodiscard]] constexpr vec3<T> right_jacobian_rate(const vec3<T>& r, const vec3<T>& v) noexcept {
    const T n = norm(r);
    return right_jacobian_rate(r, v, jacobian_rate_coefficients_of(squared_angle(r, n), n));
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_LIE_DETAIL_ROTATION_VECTOR_JACOBIAN_HPP_INCLUDED
