// The rotation group SO(3) as a Lie group, for estimation and optimization: exp and log
// between unit quaternions and rotation vectors, the Jacobians of SO(3), and the group operations
// with their Jacobians. Convention (J. Sola, J. Deray, D. Atchuthan, "A micro Lie theory for state
// estimation in robotics", 2018; the manif library's): the Jacobian of f at X is
//     J = d (f(X (+) tau) (-) f(X)) / d tau  at tau = 0,
// with the right (local) plus and minus, X (+) tau = X exp(tau) and Y (-) X = log(X^-1 Y); where an
// input or output is a vector, plain + and -. Jacobians are optional out-parameters (nullptr skips
// them; the pointers' types are not deduced, so that a literal nullptr converts), after the
// inputs; the left operations plus_left and minus_left change the operation, not the convention of
// their Jacobians. docs/lie-groups.md compares Sophus, GTSAM and Barfoot.
#ifndef QUAT_LIE_SO3_HPP_INCLUDED
#define QUAT_LIE_SO3_HPP_INCLUDED

#include <type_traits>

#include "../config.hpp"
#include "../conversions.hpp"
#include "../detail/math.hpp"
#include "../matrix.hpp"
#include "../quaternion.hpp"
#include "../vec3.hpp"
#include "detail/rotation_vector_jacobian.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
namespace detail {

/// a I + b [w]x + c [w]x^2 as a matrix, with [w]x^2 = w w^T - n2 I (n2 = |w|^2).
template <class T>
[[nodiscard]] constexpr ::quat::matrix<T, 3, 3> skew_series(const vec3<T>& w, T n2, T a, T b,
                                                            T c) noexcept {
    const T diagonal = a - c * n2;
    const T bx = b * w.x, by = b * w.y, bz = b * w.z;
    const T cxy = c * w.x * w.y, cxz = c * w.x * w.z, cyz = c * w.y * w.z;
    return {{{diagonal + c * w.x * w.x, cxy - bz, cxz + by},
             {cxy + bz, diagonal + c * w.y * w.y, cyz - bx},
             {cxz - by, cyz + bx, diagonal + c * w.z * w.z}}};
}

}  // namespace detail
}  // inline namespace isa_...

// so3 holds the instruction-set key inside it, as se3 does (which must: its twist type stays
// outside the key like every value type), so that quat::so3 and quat::se3 name one namespace each.
namespace so3 {
#include "../detail/isa_namespace.inc"

/// The skew matrix [w]x of w: hat(w) v = cross(w, v).
template <class T>
[[nodiscard]] constexpr matrix3<T> hat(const vec3<T>& w) noexcept {
    const T zero(0);
    return {{{zero, -w.z, w.y}, {w.z, zero, -w.x}, {-w.y, w.x, zero}}};
}

/// The vector w of the skew matrix [w]x, the inverse of hat. A matrix that is not skew gives the
/// vector of its skew part (m - m^T) / 2.
template <class T>
[[nodiscard]] constexpr vec3<T> vee(const matrix3<T>& m) noexcept {
    return vec3<T>{m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1)} * T(0.5);
}

/// The right Jacobian of SO(3), Jr(w) = I - (1 - cos n)/n^2 [w]x + (n - sin n)/n^3 [w]x^2 (n =
/// |w|): exp(w + d) = exp(w) exp(Jr(w) d) to first order. Any w; series near 0 (a dual-number
/// scalar gets finite derivatives at w = 0).
template <class T>
[[nodiscard]] constexpr matrix3<T> right_jacobian(const vec3<T>& w) noexcept {
    const detail::right_jacobian_coefficients<T> k =
        detail::right_jacobian_coefficients_of(w, false);
    return detail::skew_series(w, squared_norm(w), T(1), -k.a, k.b);
}

/// The left Jacobian Jl(w) = Jr(-w) = R(w) Jr(w): exp(w + d) = exp(Jl(w) d) exp(w). Any w.
template <class T>
[[nodiscard]] constexpr matrix3<T> left_jacobian(const vec3<T>& w) noexcept {
    const detail::right_jacobian_coefficients<T> k =
        detail::right_jacobian_coefficients_of(w, false);
    return detail::skew_series(w, squared_norm(w), T(1), k.a, k.b);
}

/// Jr(w)^-1 = I + [w]x / 2 + (1/n^2 - (1 + cos n)/(2 n sin n)) [w]x^2. Precondition: |w| < 2 pi
/// (Jr is singular at 2 pi; beyond, the result is finite but not the inverse).
template <class T>
[[nodiscard]] constexpr matrix3<T> right_jacobian_inverse(const vec3<T>& w) noexcept {
    const detail::right_jacobian_coefficients<T> k =
        detail::right_jacobian_coefficients_of(w, true);
    return detail::skew_series(w, squared_norm(w), T(1), T(0.5), k.c);
}

/// Jl(w)^-1 = Jr(-w)^-1 = I - [w]x / 2 + (1/n^2 - (1 + cos n)/(2 n sin n)) [w]x^2.
/// Precondition: |w| < 2 pi, as right_jacobian_inverse.
template <class T>
[[nodiscard]] constexpr matrix3<T> left_jacobian_inverse(const vec3<T>& w) noexcept {
    const detail::right_jacobian_coefficients<T> k =
        detail::right_jacobian_coefficients_of(w, true);
    return detail::skew_series(w, squared_norm(w), T(1), T(-0.5), k.c);
}

/// The adjoint of q, Ad(q) = R(q): q exp(w) = exp(R w) q. Precondition: unit q.
template <class T>
[[nodiscard]] constexpr matrix3<T> adjoint(const quaternion<T>& q) noexcept {
    return to_matrix3(to_matrix(q));
}

/// exp(w) = from_rotation_vector(w), the rotation by |w| about w / |w|; *jacobian = Jr(w).
/// Any finite w; NaN in w gives NaN.
template <class T>
[[nodiscard]] constexpr quaternion<T> exp(
    const vec3<T>& w, detail::type_identity_t<matrix3<T>>* jacobian = nullptr) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        // from_rotation_vector(w) and right_jacobian(w) from one sincos of the half angle.
        const detail::cos_and_sinc<T> half = detail::half_angle_of(w);
        if (jacobian != nullptr) {
            const T n = norm(w);
            const detail::right_jacobian_coefficients<T> k =
                detail::right_jacobian_coefficients_of(n * n, n, half, false);
            *jacobian = detail::skew_series(w, squared_norm(w), T(1), -k.a, k.b);
        }
        const T scale = half.sinc * T(0.5);
        return {half.cos, w.x * scale, w.y * scale, w.z * scale};
    } else {
        if (jacobian != nullptr) *jacobian = right_jacobian(w);
        return from_rotation_vector(w);
    }
}

/// log(q) = to_rotation_vector(q), angle in [0, pi], q and -q alike; *jacobian = Jr(log q)^-1.
/// Precondition for the Jacobian: unit q (the value accepts any non-zero scale of q).
template <class T>
[[nodiscard]] constexpr vec3<T> log(
    const quaternion<T>& q, detail::type_identity_t<matrix3<T>>* jacobian = nullptr) noexcept {
    const vec3<T> w = to_rotation_vector(q);
    // Not q's own half-angle cosine and sine in place of right_jacobian_inverse's sincos: they
    // belong to q's angle, not to the rounded |w|, and measure 2.7 epsilon against 1.6 (double).
    if (jacobian != nullptr) *jacobian = right_jacobian_inverse(w);
    return w;
}

/// a * b; *d_a = R(b)^T, *d_b = I. Precondition: unit a and b.
template <class T>
[[nodiscard]] constexpr quaternion<T> compose(
    const quaternion<T>& a, const quaternion<T>& b,
    detail::type_identity_t<matrix3<T>>* d_a = nullptr,
    detail::type_identity_t<matrix3<T>>* d_b = nullptr) noexcept {
    if (d_a != nullptr) *d_a = transpose(adjoint(b));
    if (d_b != nullptr) *d_b = matrix3<T>::identity();
    return a * b;
}

/// q^-1 = conjugate(q); *d = -R(q). Precondition: unit q.
template <class T>
[[nodiscard]] constexpr quaternion<T> inverse(
    const quaternion<T>& q, detail::type_identity_t<matrix3<T>>* d = nullptr) noexcept {
    if (d != nullptr) *d = -adjoint(q);
    return conjugate(q);
}

/// rotate(q, v) = R v; *d_q = -R [v]x, *d_v = R. Precondition: unit q.
template <class T>
[[nodiscard]] constexpr vec3<T> act(const quaternion<T>& q, const vec3<T>& v,
                                    detail::type_identity_t<matrix3<T>>* d_q = nullptr,
                                    detail::type_identity_t<matrix3<T>>* d_v = nullptr) noexcept {
    if (d_q != nullptr || d_v != nullptr) {
        const matrix3<T> r = adjoint(q);
        if (d_q != nullptr) *d_q = -(r * hat(v));
        if (d_v != nullptr) *d_v = r;
    }
    return rotate(q, v);
}

/// x^-1 y, the motion from x to y in x's frame; *d_x = -R(x^-1 y)^T, *d_y = I. Unit x and y.
template <class T>
[[nodiscard]] constexpr quaternion<T> between(
    const quaternion<T>& x, const quaternion<T>& y,
    detail::type_identity_t<matrix3<T>>* d_x = nullptr,
    detail::type_identity_t<matrix3<T>>* d_y = nullptr) noexcept {
    const quaternion<T> d = conjugate(x) * y;
    if (d_x != nullptr) *d_x = -transpose(adjoint(d));
    if (d_y != nullptr) *d_y = matrix3<T>::identity();
    return d;
}

/// x (+) w = x exp(w); *d_x = R(exp w)^T, *d_w = Jr(w). Precondition: unit x.
template <class T>
[[nodiscard]] constexpr quaternion<T> plus(
    const quaternion<T>& x, const vec3<T>& w, detail::type_identity_t<matrix3<T>>* d_x = nullptr,
    detail::type_identity_t<matrix3<T>>* d_w = nullptr) noexcept {
    const quaternion<T> e = exp(w, d_w);
    if (d_x != nullptr) *d_x = transpose(adjoint(e));
    return x * e;
}

/// y (-) x = log(x^-1 y), angle in [0, pi]; *d_y = Jr(t)^-1, *d_x = -Jl(t)^-1 for t the result.
/// Precondition: unit x and y.
template <class T>
[[nodiscard]] constexpr vec3<T> minus(const quaternion<T>& y, const quaternion<T>& x,
                                      detail::type_identity_t<matrix3<T>>* d_y = nullptr,
                                      detail::type_identity_t<matrix3<T>>* d_x = nullptr) noexcept {
    const vec3<T> t = log(conjugate(x) * y, d_y);
    if (d_x != nullptr) *d_x = -left_jacobian_inverse(t);
    return t;
}

/// exp(w) x, the left plus; *d_w = R(x)^T Jr(w), *d_x = I (right-convention Jacobians, as
/// everywhere here). Precondition: unit x.
template <class T>
[[nodiscard]] constexpr quaternion<T> plus_left(
    const vec3<T>& w, const quaternion<T>& x, detail::type_identity_t<matrix3<T>>* d_w = nullptr,
    detail::type_identity_t<matrix3<T>>* d_x = nullptr) noexcept {
    if (d_w != nullptr) *d_w = transpose(adjoint(x)) * right_jacobian(w);
    if (d_x != nullptr) *d_x = matrix3<T>::identity();
    return from_rotation_vector(w) * x;
}

/// log(y x^-1), the left minus, angle in [0, pi]; *d_y = Jr(t)^-1 R(x), *d_x = -Jr(t)^-1 R(x) for t
/// the result (right-convention Jacobians). Precondition: unit x and y.
template <class T>
[[nodiscard]] constexpr vec3<T> minus_left(
    const quaternion<T>& y, const quaternion<T>& x,
    detail::type_identity_t<matrix3<T>>* d_y = nullptr,
    detail::type_identity_t<matrix3<T>>* d_x = nullptr) noexcept {
    const vec3<T> t = to_rotation_vector(y * conjugate(x));
    if (d_y != nullptr || d_x != nullptr) {
        const matrix3<T> j = right_jacobian_inverse(t) * adjoint(x);
        if (d_y != nullptr) *d_y = j;
        if (d_x != nullptr) *d_x = -j;
    }
    return t;
}

}  // inline namespace isa_...
}  // namespace so3

}  // namespace quat

#endif  // QUAT_LIE_SO3_HPP_INCLUDED
