// The rotation group SO(3) as a Lie group, for estimation and optimization: exp and log
// between unit quaternions and rotation vectors, the Jacobians of SO(3), and the group operations
// with their Jacobians. Convention (J. Sola, J. Deray, D. Atchuthan, "A micro Lie theory for state
// estimation in robotics", 2018; the manif library's): the Jacobian of f at X is
//     J = d (f(X (+) tau) (-) f(X)) / d tau  at tau = 0,
// with the right (local) plus and minus, X (+) tau = X exp(tau) and Y (-) X = log(X^-1 Y); where an
// input or output is a vector, plain + and -. Jacobians are optional out-parameters (nullptr skips
// them; the pointers' types are not deduced, so that a literal nullptr converts), after the
// inputs and in their order, named J_out_in (J_c_a for c = compose(a, b)); every plus and minus
// takes the element first and the tangent second. The left operations plus_left and minus_left
// change the operation, not the convention of their Jacobians. docs/conventions.md lists the names;
// docs/lie-groups.md compares Sophus, GTSAM and Barfoot.
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
    return detail::skew_polynomial(w, T(1), -k.a, k.b);
}

/// The left Jacobian Jl(w) = Jr(-w) = R(w) Jr(w): exp(w + d) = exp(Jl(w) d) exp(w). Any w.
template <class T>
[[nodiscard]] constexpr matrix3<T> left_jacobian(const vec3<T>& w) noexcept {
    const detail::right_jacobian_coefficients<T> k =
        detail::right_jacobian_coefficients_of(w, false);
    return detail::skew_polynomial(w, T(1), k.a, k.b);
}

/// Jr(w)^-1 = I + [w]x / 2 + (1/n^2 - (1 + cos n)/(2 n sin n)) [w]x^2. Precondition: |w| < 2 pi
/// (Jr is singular at 2 pi; beyond, the result is finite but not the inverse).
template <class T>
[[nodiscard]] constexpr matrix3<T> right_jacobian_inverse(const vec3<T>& w) noexcept {
    const detail::right_jacobian_coefficients<T> k =
        detail::right_jacobian_coefficients_of(w, true);
    return detail::skew_polynomial(w, T(1), T(0.5), k.c);
}

/// Jl(w)^-1 = Jr(-w)^-1 = I - [w]x / 2 + (1/n^2 - (1 + cos n)/(2 n sin n)) [w]x^2.
/// Precondition: |w| < 2 pi, as right_jacobian_inverse.
template <class T>
[[nodiscard]] constexpr matrix3<T> left_jacobian_inverse(const vec3<T>& w) noexcept {
    const detail::right_jacobian_coefficients<T> k =
        detail::right_jacobian_coefficients_of(w, true);
    return detail::skew_polynomial(w, T(1), T(-0.5), k.c);
}

/// The adjoint of q, Ad(q) = R(q): q exp(w) = exp(R w) q. The entries of to_matrix(q), as the
/// matrix3 that Jacobians chain with. Precondition: unit q.
template <class T>
[[nodiscard]] constexpr matrix3<T> adjoint(const quaternion<T>& q) noexcept {
    QUAT_ASSERT(detail::is_near_unit(q), "quat::so3::adjoint: q is not a unit quaternion");
    return detail::scaled_matrix<matrix3>(q, q.x + q.x, q.y + q.y, q.z + q.z);
}

/// q = exp(w) = from_rotation_vector(w), the rotation by |w| about w / |w|; *J_q_w = Jr(w).
/// Any finite w; NaN in w gives NaN.
template <class T>
[[nodiscard]] constexpr quaternion<T> exp(
    const vec3<T>& w, detail::type_identity_t<matrix3<T>>* J_q_w = nullptr) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        // from_rotation_vector(w) and right_jacobian(w) from one sincos of the half angle.
        const detail::cos_and_sinc<T> half = detail::half_angle_of(w);
        if (J_q_w != nullptr) {
            const T n = norm(w);
            const detail::right_jacobian_coefficients<T> k =
                detail::right_jacobian_coefficients_of(n * n, n, half, false);
            *J_q_w = detail::skew_polynomial(w, T(1), -k.a, k.b);
        }
        const T scale = half.sinc * T(0.5);
        return {half.cos, w.x * scale, w.y * scale, w.z * scale};
    } else {
        if (J_q_w != nullptr) *J_q_w = right_jacobian(w);
        return from_rotation_vector(w);
    }
}

/// w = log(q) = to_rotation_vector(q), angle in [0, pi], q and -q alike; *J_w_q = Jr(w)^-1.
/// Precondition for the Jacobian: unit q (the value accepts any non-zero scale of q).
template <class T>
[[nodiscard]] constexpr vec3<T> log(const quaternion<T>& q,
                                    detail::type_identity_t<matrix3<T>>* J_w_q = nullptr) noexcept {
    const vec3<T> w = to_rotation_vector(q);
    // Not q's own half-angle cosine and sine in place of right_jacobian_inverse's sincos: they
    // belong to q's angle, not to the rounded |w|, and measure 2.7 epsilon against 1.6 (double).
    if (J_w_q != nullptr) *J_w_q = right_jacobian_inverse(w);
    return w;
}

/// c = a * b; *J_c_a = R(b)^T, *J_c_b = I. Precondition: unit a and b.
template <class T>
[[nodiscard]] constexpr quaternion<T> compose(
    const quaternion<T>& a, const quaternion<T>& b,
    detail::type_identity_t<matrix3<T>>* J_c_a = nullptr,
    detail::type_identity_t<matrix3<T>>* J_c_b = nullptr) noexcept {
    if (J_c_a != nullptr) *J_c_a = transpose(adjoint(b));
    if (J_c_b != nullptr) *J_c_b = matrix3<T>::identity();
    return a * b;
}

/// i = q^-1 = conjugate(q); *J_i_q = -R(q). Precondition: unit q.
template <class T>
[[nodiscard]] constexpr quaternion<T> inverse(
    const quaternion<T>& q, detail::type_identity_t<matrix3<T>>* J_i_q = nullptr) noexcept {
    if (J_i_q != nullptr) *J_i_q = -adjoint(q);
    return conjugate(q);
}

/// u = rotate(q, v) = R v; *J_u_q = -R [v]x, *J_u_v = R. Precondition: unit q.
template <class T>
[[nodiscard]] constexpr vec3<T> act(const quaternion<T>& q, const vec3<T>& v,
                                    detail::type_identity_t<matrix3<T>>* J_u_q = nullptr,
                                    detail::type_identity_t<matrix3<T>>* J_u_v = nullptr) noexcept {
    if (J_u_q != nullptr || J_u_v != nullptr) {
        const matrix3<T> r = adjoint(q);
        if (J_u_q != nullptr) *J_u_q = -(r * hat(v));
        if (J_u_v != nullptr) *J_u_v = r;
    }
    return rotate(q, v);
}

/// d = x^-1 y, the motion from x to y in x's frame; *J_d_x = -R(d)^T, *J_d_y = I. Unit x and y.
template <class T>
[[nodiscard]] constexpr quaternion<T> between(
    const quaternion<T>& x, const quaternion<T>& y,
    detail::type_identity_t<matrix3<T>>* J_d_x = nullptr,
    detail::type_identity_t<matrix3<T>>* J_d_y = nullptr) noexcept {
    const quaternion<T> d = conjugate(x) * y;
    if (J_d_x != nullptr) *J_d_x = -transpose(adjoint(d));
    if (J_d_y != nullptr) *J_d_y = matrix3<T>::identity();
    return d;
}

/// y = x (+) w = x exp(w); *J_y_x = R(exp w)^T, *J_y_w = Jr(w). Precondition: unit x.
template <class T>
[[nodiscard]] constexpr quaternion<T> plus(
    const quaternion<T>& x, const vec3<T>& w, detail::type_identity_t<matrix3<T>>* J_y_x = nullptr,
    detail::type_identity_t<matrix3<T>>* J_y_w = nullptr) noexcept {
    const quaternion<T> e = exp(w, J_y_w);
    if (J_y_x != nullptr) *J_y_x = transpose(adjoint(e));
    return x * e;
}

/// w = y (-) x = log(x^-1 y), angle in [0, pi]; *J_w_y = Jr(w)^-1, *J_w_x = -Jl(w)^-1.
/// Precondition: unit x and y.
template <class T>
[[nodiscard]] constexpr vec3<T> minus(
    const quaternion<T>& y, const quaternion<T>& x,
    detail::type_identity_t<matrix3<T>>* J_w_y = nullptr,
    detail::type_identity_t<matrix3<T>>* J_w_x = nullptr) noexcept {
    const vec3<T> w = to_rotation_vector(conjugate(x) * y);
    if (J_w_y != nullptr || J_w_x != nullptr) {
        // Jr^-1 and Jl^-1 share their coefficients (they differ in the sign of [w]x): computed
        // once, the two are what right_ and left_jacobian_inverse return, bit for bit.
        const detail::right_jacobian_coefficients<T> k =
            detail::right_jacobian_coefficients_of(w, true);
        if (J_w_y != nullptr) *J_w_y = detail::skew_polynomial(w, T(1), T(0.5), k.c);
        if (J_w_x != nullptr) *J_w_x = -detail::skew_polynomial(w, T(1), T(-0.5), k.c);
    }
    return w;
}

/// y = exp(w) x, the left plus, element first as in plus; *J_y_x = I, *J_y_w = R(x)^T Jr(w)
/// (right-convention Jacobians, as everywhere here). Precondition: unit x.
template <class T>
[[nodiscard]] constexpr quaternion<T> plus_left(
    const quaternion<T>& x, const vec3<T>& w, detail::type_identity_t<matrix3<T>>* J_y_x = nullptr,
    detail::type_identity_t<matrix3<T>>* J_y_w = nullptr) noexcept {
    if (J_y_w != nullptr) *J_y_w = transpose(adjoint(x)) * right_jacobian(w);
    if (J_y_x != nullptr) *J_y_x = matrix3<T>::identity();
    return from_rotation_vector(w) * x;
}

/// plus_left with the tangent first, the order before 1.1.0: plus_left(x, w) with the Jacobians in
/// this call's order (*J_y_w, then *J_y_x). Kept until 2.0.0 so that code written for 1.0 compiles.
template <class T>
[[deprecated("use plus_left(x, w): element first")]] [[nodiscard]] constexpr quaternion<T>
plus_left(const vec3<T>& w, const quaternion<T>& x,
          detail::type_identity_t<matrix3<T>>* J_y_w = nullptr,
          detail::type_identity_t<matrix3<T>>* J_y_x = nullptr) noexcept {
    return plus_left(x, w, J_y_x, J_y_w);
}

/// w = y (-)left x = log(y x^-1), the left minus, angle in [0, pi]; *J_w_y = Jr(w)^-1 R(x),
/// *J_w_x = -Jr(w)^-1 R(x) (right-convention Jacobians). Precondition: unit x and y.
template <class T>
[[nodiscard]] constexpr vec3<T> minus_left(
    const quaternion<T>& y, const quaternion<T>& x,
    detail::type_identity_t<matrix3<T>>* J_w_y = nullptr,
    detail::type_identity_t<matrix3<T>>* J_w_x = nullptr) noexcept {
    const vec3<T> w = to_rotation_vector(y * conjugate(x));
    if (J_w_y != nullptr || J_w_x != nullptr) {
        const matrix3<T> j = right_jacobian_inverse(w) * adjoint(x);
        if (J_w_y != nullptr) *J_w_y = j;
        if (J_w_x != nullptr) *J_w_x = -j;
    }
    return w;
}

}  // inline namespace isa_...
}  // namespace so3

}  // namespace quat

#endif  // QUAT_LIE_SO3_HPP_INCLUDED
