// The rigid motions SE(3) as a Lie group: exp and log between unit dual quaternions and twists,
// SE(3)'s Jacobians, and the group operations with their Jacobians, in lie/so3.hpp's convention (J.
// Sola, J. Deray, D. Atchuthan, "A micro Lie theory for state estimation in robotics", 2018;
// manif's): J = d (f(X exp(tau)) (-) f(X)) / d tau at tau = 0 with the right plus and minus,
// Jacobians as optional out-parameters named J_out_in, after the inputs in their order; every plus
// and minus takes the element first. A twist is (rho, omega), linear part first as in Sophus and
// manif; exp(rho, omega) is the motion x -> exp(omega) x + Jl(omega) rho. The Jacobians' Q block is
// T. Barfoot, "State Estimation for Robotics", 2017, eq. 7.86 (Sola et al. eq. 180).
// docs/lie-groups.md compares the conventions of Sophus, manif, GTSAM and Barfoot.
#ifndef QUAT_LIE_SE3_HPP_INCLUDED
#define QUAT_LIE_SE3_HPP_INCLUDED

#include "../config.hpp"
#include "../detail/math.hpp"
#include "../matrix.hpp"
#include "../quaternion.hpp"
#include "../rigid/dual_quaternion.hpp"
#include "../rigid/homogeneous_matrix.hpp"
#include "../vec3.hpp"
#include "detail/rotation_vector_jacobian.hpp"
#include "so3.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
namespace detail {

/// Barfoot's Q(rho, omega), the upper right block of SE(3)'s left Jacobian: with P = [rho]x,
/// W = [omega]x, n = |omega|,
///     Q = P/2 + c1 (WP + PW + WPW) + c2 (WWP + PWW - 3 WPW) + c3 (WPWW + WWPW),
/// c1 = (n - sin n)/n^3, c2 = (n^2 + 2 cos n - 2)/(2 n^4), c3 = (2n - 3 sin n + n cos n)/(2 n^5),
/// each a series in n^2 near 0. The products reduce to outer products, with d = omega . rho:
/// [a]x [b]x = b a^T - (a . b) I gives WP = rho omega^T - d I, PW = omega rho^T - d I,
/// WPW = -d W (W omega = 0), WWP + PWW - 3 WPW = [omega x (omega x rho) + d omega]x
/// = [2 d omega - n^2 rho]x and WPWW + WWPW = -2 d W^2 = -2 d (omega omega^T - n^2 I):
///     Q = [(1/2 - c2 n^2) rho + (2 c2 - c1) d omega]x + c1 (rho omega^T + omega rho^T)
///         - 2 c3 d omega omega^T + 2 d (c3 n^2 - c1) I.
template <class T>
[[nodiscard]] constexpr matrix3<T> se3_q_block(const vec3<T>& rho, const vec3<T>& omega) noexcept {
    const T n = norm(omega), n2 = squared_angle(omega, n);
    const T c1 = n_minus_sin_over_cube(n2, n), c2 = cosine_remainder_coefficient(n2, n);
    const T c3 = quintic_coefficient(n2, n) * T(-0.5);
    const T d = dot(omega, rho);
    const vec3<T> k = rho * (T(0.5) - c2 * n2) + omega * ((c2 + c2 - c1) * d);
    const T diagonal = T(2) * d * (c3 * n2 - c1), e = T(-2) * c3 * d;
    const T r[3] = {rho.x, rho.y, rho.z}, w[3] = {omega.x, omega.y, omega.z};
    matrix3<T> q = so3::hat(k);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            q(i, j) = q(i, j) + c1 * (r[i] * w[j] + w[i] * r[j]) + e * w[i] * w[j];
        q(i, i) = q(i, i) + diagonal;
    }
    return q;
}

/// The inverse of a unit dual quaternion: both parts conjugated, exact for |real| = 1 and
/// dot(real, dual) = 0 (the product's dual part is then r d* + d r* = 2 dot(r, d) = 0).
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> rigid_inverse(const dual_quaternion<T>& x) noexcept {
    return {conjugate(x.real), conjugate(x.dual)};
}

/// [[a, b], [0, a]] from 3x3 blocks.
template <class T>
[[nodiscard]] constexpr matrix6<T> upper_block_triangular(const matrix3<T>& a,
                                                          const matrix3<T>& b) noexcept {
    matrix6<T> m = matrix6<T>::zero();
    set_block(m, 0, 0, a);
    set_block(m, 0, 3, b);
    set_block(m, 3, 3, a);
    return m;
}

}  // namespace detail
}  // inline namespace isa_...

namespace se3 {

/// A twist, the tangent of SE(3): (linear, angular) = (rho, omega), exp(twist) the motion
/// x -> exp(omega) x + Jl(omega) rho. As 6 numbers (to_vector) linear first, as Sophus and manif
/// order them; GTSAM's Pose3 puts the angular part first (swap the halves, and the blocks of its
/// 6x6 matrices).
template <class T>
struct twist {
    vec3<T> linear;   ///< rho
    vec3<T> angular;  ///< omega, a rotation vector
};

#include "../detail/isa_namespace.inc"

/// Component-wise sum.
template <class T>
[[nodiscard]] constexpr twist<T> operator+(const twist<T>& a, const twist<T>& b) noexcept {
    return {a.linear + b.linear, a.angular + b.angular};
}
/// Component-wise difference.
template <class T>
[[nodiscard]] constexpr twist<T> operator-(const twist<T>& a, const twist<T>& b) noexcept {
    return {a.linear - b.linear, a.angular - b.angular};
}
/// Negation: exp(-t) = exp(t)^-1.
template <class T>
[[nodiscard]] constexpr twist<T> operator-(const twist<T>& a) noexcept {
    return {-a.linear, -a.angular};
}
/// Every component times s (exp(s t) moves s times as far along the same screw).
template <class T>
[[nodiscard]] constexpr twist<T> operator*(const twist<T>& a,
                                           quat::detail::type_identity_t<T> s) noexcept {
    return {a.linear * s, a.angular * s};
}
/// Every component times s.
template <class T>
[[nodiscard]] constexpr twist<T> operator*(quat::detail::type_identity_t<T> s,
                                           const twist<T>& a) noexcept {
    return a * s;
}

/// The twist as a column (rho, omega): linear part first.
template <class T>
[[nodiscard]] constexpr matrix<T, 6, 1> to_vector(const twist<T>& t) noexcept {
    return {
        {{t.linear.x}, {t.linear.y}, {t.linear.z}, {t.angular.x}, {t.angular.y}, {t.angular.z}}};
}
/// The twist of the column (rho, omega), the inverse of to_vector.
template <class T>
[[nodiscard]] constexpr twist<T> to_twist(const matrix<T, 6, 1>& v) noexcept {
    return {{v(0, 0), v(1, 0), v(2, 0)}, {v(3, 0), v(4, 0), v(5, 0)}};
}

/// The 4x4 matrix [[ [omega]x, rho ], [0, 0]] of the twist, the Lie algebra element.
template <class T>
[[nodiscard]] constexpr matrix<T, 4, 4> hat(const twist<T>& t) noexcept {
    matrix<T, 4, 4> m = matrix<T, 4, 4>::zero();
    set_block(m, 0, 0, so3::hat(t.angular));
    set_block(m, 0, 3, matrix<T, 3, 1>{{{t.linear.x}, {t.linear.y}, {t.linear.z}}});
    return m;
}
/// The twist of a 4x4 Lie algebra element, the inverse of hat: the vector of the skew part of the
/// upper left block, and the upper right column (the last row is not read).
template <class T>
[[nodiscard]] constexpr twist<T> vee(const matrix<T, 4, 4>& m) noexcept {
    return {{m(0, 3), m(1, 3), m(2, 3)}, so3::vee(block<3, 3>(m, 0, 0))};
}

/// SE(3)'s left Jacobian [[Jl(omega), Q(rho, omega)], [0, Jl(omega)]]: exp(t + d) =
/// exp(Jl(t) d) exp(t) to first order. Any twist; series near omega = 0.
template <class T>
[[nodiscard]] constexpr matrix6<T> left_jacobian(const twist<T>& t) noexcept {
    return quat::detail::upper_block_triangular(so3::left_jacobian(t.angular),
                                                quat::detail::se3_q_block(t.linear, t.angular));
}
/// SE(3)'s right Jacobian Jr(t) = Jl(-t) = [[Jr(omega), Q(-rho, -omega)], [0, Jr(omega)]]:
/// exp(t + d) = exp(t) exp(Jr(t) d) to first order. Any twist.
template <class T>
[[nodiscard]] constexpr matrix6<T> right_jacobian(const twist<T>& t) noexcept {
    return quat::detail::upper_block_triangular(so3::right_jacobian(t.angular),
                                                quat::detail::se3_q_block(-t.linear, -t.angular));
}
/// Jl(t)^-1 = [[A, -A Q A], [0, A]] with A = Jl(omega)^-1. Precondition: |omega| < 2 pi.
template <class T>
[[nodiscard]] constexpr matrix6<T> left_jacobian_inverse(const twist<T>& t) noexcept {
    const matrix3<T> a = so3::left_jacobian_inverse(t.angular);
    return quat::detail::upper_block_triangular(
        a, -(a * quat::detail::se3_q_block(t.linear, t.angular) * a));
}
/// Jr(t)^-1 = Jl(-t)^-1. Precondition: |omega| < 2 pi.
template <class T>
[[nodiscard]] constexpr matrix6<T> right_jacobian_inverse(const twist<T>& t) noexcept {
    return left_jacobian_inverse(-t);
}

/// R(x), x's rotation, as a matrix3: not a rotation_matrix, whose home is
/// to_matrix(rotation_of(x)). so3::adjoint(x.real) is the same 3x3 block for Jacobians.
template <class T>
[[deprecated(
    "use to_matrix(rotation_of(x)) for the rotation_matrix, or so3::adjoint(x.real) for the "
    "matrix3 Jacobian block")]] [[nodiscard]] constexpr matrix3<T>
rotation_matrix_of(const dual_quaternion<T>& x) noexcept {
    return so3::adjoint(x.real);
}

/// The adjoint Ad(X) = [[R, [t]x R], [0, R]] (twists linear first): X exp(d) = exp(Ad(X) d) X.
/// Precondition: unit X.
template <class T>
[[nodiscard]] constexpr matrix6<T> adjoint(const dual_quaternion<T>& x) noexcept {
    const matrix3<T> r = so3::adjoint(x.real);
    return quat::detail::upper_block_triangular(r, so3::hat(translation_of(x)) * r);
}

/// i = X^-1, both parts conjugated, exact for unit X (dot(real, dual) = 0); *J_i_x = -Ad(X).
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> inverse(
    const dual_quaternion<T>& x,
    quat::detail::type_identity_t<matrix6<T>>* J_i_x = nullptr) noexcept {
    if (J_i_x != nullptr) *J_i_x = -adjoint(x);
    return quat::detail::rigid_inverse(x);
}

/// x = exp(t): the motion p -> exp(omega) p + Jl(omega) rho as a unit dual quaternion;
/// *J_x_t = Jr(t). Any finite twist; a NaN or infinite component gives NaN in every component.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> exp(
    const twist<T>& t, quat::detail::type_identity_t<matrix6<T>>* J_x_t = nullptr) noexcept {
    // Jl(omega) = Jr(omega)^T ([omega]x is skew, [omega]x^2 symmetric): the translation needs Jr
    // even when the Jacobian is not asked for.
    matrix3<T> jr{};
    const quaternion<T> rotation = so3::exp(t.angular, &jr);
    if (J_x_t != nullptr)
        *J_x_t = quat::detail::upper_block_triangular(
            jr, quat::detail::se3_q_block(-t.linear, -t.angular));
    const dual_quaternion<T> motion = to_dual_quaternion(rotation, transpose(jr) * t.linear);
    if constexpr (std::is_floating_point_v<T>) {
        // A bad linear part leaves the rotation finite; half a result would pass for an answer.
        if (!quat::detail::is_finite(t.linear) || !quat::detail::is_finite(t.angular))
            return {quat::detail::nan_quaternion<T>(), quat::detail::nan_quaternion<T>()};
    }
    return motion;
}

/// t = log(X): the twist with |omega| in [0, pi] whose exp is X (X and -X alike);
/// *J_t_x = Jr(t)^-1. Precondition: unit X.
template <class T>
[[nodiscard]] constexpr twist<T> log(
    const dual_quaternion<T>& x,
    quat::detail::type_identity_t<matrix6<T>>* J_t_x = nullptr) noexcept {
    // Jl(omega)^-1 = (Jr(omega)^-1)^T ([omega]x is skew, [omega]x^2 symmetric).
    matrix3<T> a{};
    const vec3<T> omega = so3::log(x.real, &a);
    const twist<T> t{transpose(a) * translation_of(x), omega};
    if (J_t_x != nullptr)
        *J_t_x = quat::detail::upper_block_triangular(
            a, -(a * quat::detail::se3_q_block(-t.linear, -t.angular) * a));
    return t;
}

/// log of the rigid motion m = [R t; 0 1]: log(to_dual_quaternion(m)), with the same Jacobian
/// *J_t_m (one group element, two forms; to_homogeneous(exp(t)) is the other way). Precondition:
/// m rigid.
template <class T>
[[nodiscard]] constexpr twist<T> log(
    const homogeneous_matrix<T>& m,
    quat::detail::type_identity_t<matrix6<T>>* J_t_m = nullptr) noexcept {
    return log(to_dual_quaternion(m), J_t_m);
}

/// c = a * b (b first); *J_c_a = Ad(b)^-1, *J_c_b = I. Precondition: unit a and b.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> compose(
    const dual_quaternion<T>& a, const dual_quaternion<T>& b,
    quat::detail::type_identity_t<matrix6<T>>* J_c_a = nullptr,
    quat::detail::type_identity_t<matrix6<T>>* J_c_b = nullptr) noexcept {
    if (J_c_a != nullptr) *J_c_a = adjoint(quat::detail::rigid_inverse(b));
    if (J_c_b != nullptr) *J_c_b = matrix6<T>::identity();
    return a * b;
}

/// u = transform(X, p) = R p + t; *J_u_x = [R, -R [p]x] (3x6), *J_u_p = R. Precondition: unit X.
template <class T>
[[nodiscard]] constexpr vec3<T> act(
    const dual_quaternion<T>& x, const vec3<T>& p,
    quat::detail::type_identity_t<matrix<T, 3, 6>>* J_u_x = nullptr,
    quat::detail::type_identity_t<matrix3<T>>* J_u_p = nullptr) noexcept {
    if (J_u_x != nullptr || J_u_p != nullptr) {
        const matrix3<T> r = so3::adjoint(x.real);
        if (J_u_x != nullptr) {
            set_block(*J_u_x, 0, 0, r);
            set_block(*J_u_x, 0, 3, -(r * so3::hat(p)));
        }
        if (J_u_p != nullptr) *J_u_p = r;
    }
    return transform(x, p);
}

/// d = x^-1 y, the motion from x to y in x's frame; *J_d_x = -Ad(d)^-1, *J_d_y = I. Unit x and y.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> between(
    const dual_quaternion<T>& x, const dual_quaternion<T>& y,
    quat::detail::type_identity_t<matrix6<T>>* J_d_x = nullptr,
    quat::detail::type_identity_t<matrix6<T>>* J_d_y = nullptr) noexcept {
    const dual_quaternion<T> d = quat::detail::rigid_inverse(x) * y;
    if (J_d_x != nullptr) *J_d_x = -adjoint(quat::detail::rigid_inverse(d));
    if (J_d_y != nullptr) *J_d_y = matrix6<T>::identity();
    return d;
}

/// y = x (+) t = x exp(t); *J_y_x = Ad(exp t)^-1, *J_y_t = Jr(t). Precondition: unit x.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> plus(
    const dual_quaternion<T>& x, const twist<T>& t,
    quat::detail::type_identity_t<matrix6<T>>* J_y_x = nullptr,
    quat::detail::type_identity_t<matrix6<T>>* J_y_t = nullptr) noexcept {
    const dual_quaternion<T> e = exp(t, J_y_t);
    if (J_y_x != nullptr) *J_y_x = adjoint(quat::detail::rigid_inverse(e));
    return x * e;
}

/// t = y (-) x = log(x^-1 y); *J_t_y = Jr(t)^-1, *J_t_x = -Jl(t)^-1. Unit x and y.
template <class T>
[[nodiscard]] constexpr twist<T> minus(
    const dual_quaternion<T>& y, const dual_quaternion<T>& x,
    quat::detail::type_identity_t<matrix6<T>>* J_t_y = nullptr,
    quat::detail::type_identity_t<matrix6<T>>* J_t_x = nullptr) noexcept {
    const twist<T> t = log(quat::detail::rigid_inverse(x) * y, J_t_y);
    if (J_t_x != nullptr) *J_t_x = -left_jacobian_inverse(t);
    return t;
}

/// y = exp(t) x, the left plus, element first as in plus; *J_y_x = I, *J_y_t = Ad(x)^-1 Jr(t)
/// (right-convention Jacobians, as everywhere here). Precondition: unit x.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> plus_left(
    const dual_quaternion<T>& x, const twist<T>& t,
    quat::detail::type_identity_t<matrix6<T>>* J_y_x = nullptr,
    quat::detail::type_identity_t<matrix6<T>>* J_y_t = nullptr) noexcept {
    if (J_y_t != nullptr) *J_y_t = adjoint(quat::detail::rigid_inverse(x)) * right_jacobian(t);
    if (J_y_x != nullptr) *J_y_x = matrix6<T>::identity();
    return exp(t) * x;
}

/// plus_left with the tangent first, the order before 1.1.0: plus_left(x, t) with the Jacobians in
/// this call's order (*J_y_t, then *J_y_x). Kept until 2.0.0 so that code written for 1.0 compiles.
template <class T>
[[deprecated("use plus_left(x, t): element first")]] [[nodiscard]] constexpr dual_quaternion<T>
plus_left(const twist<T>& t, const dual_quaternion<T>& x,
          quat::detail::type_identity_t<matrix6<T>>* J_y_t = nullptr,
          quat::detail::type_identity_t<matrix6<T>>* J_y_x = nullptr) noexcept {
    return plus_left(x, t, J_y_x, J_y_t);
}

/// t = y (-)left x = log(y x^-1), the left minus; *J_t_y = Jr(t)^-1 Ad(x), *J_t_x = -Jr(t)^-1 Ad(x)
/// (right-convention Jacobians). Precondition: unit x and y.
template <class T>
[[nodiscard]] constexpr twist<T> minus_left(
    const dual_quaternion<T>& y, const dual_quaternion<T>& x,
    quat::detail::type_identity_t<matrix6<T>>* J_t_y = nullptr,
    quat::detail::type_identity_t<matrix6<T>>* J_t_x = nullptr) noexcept {
    const twist<T> t = log(y * quat::detail::rigid_inverse(x));
    if (J_t_y != nullptr || J_t_x != nullptr) {
        const matrix6<T> j = right_jacobian_inverse(t) * adjoint(x);
        if (J_t_y != nullptr) *J_t_y = j;
        if (J_t_x != nullptr) *J_t_x = -j;
    }
    return t;
}

}  // inline namespace isa_...
}  // namespace se3

}  // namespace quat

#endif  // QUAT_LIE_SE3_HPP_INCLUDED
