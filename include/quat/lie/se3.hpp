// The rigid motions SE(3) as a Lie group: exp and log between unit dual quaternions and
// twists, SE(3)'s Jacobians, and the group operations with their Jacobians, in so3.hpp's convention
// (J. Sola, J. Deray, D. Atchuthan, "A micro Lie theory for state estimation in robotics", 2018;
// manif's): J = d (f(X exp(tau)) (-) f(X)) / d tau at tau = 0 with the right plus and minus,
// Jacobians as optional out-parameters. A twist is (rho, omega), linear part first as in Sophus and
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
[[nodiscard]] constexpr ::quat::matrix<T, 3, 3> se3_q_block(const vec3<T>& rho,
                                                            const vec3<T>& omega) noexcept {
    const T n = norm(omega), n2 = squared_angle(omega, n);
    const T c1 = n_minus_sin_over_cube(n2, n), c2 = cosine_remainder_coefficient(n2, n);
    const T c3 = quintic_coefficient(n2, n) * T(-0.5);
    const T d = dot(omega, rho);
    const vec3<T> k = rho * (T(0.5) - c2 * n2) + omega * ((c2 + c2 - c1) * d);
    const T diagonal = T(2) * d * (c3 * n2 - c1), e = T(-2) * c3 * d;
    const T r[3] = {rho.x, rho.y, rho.z}, w[3] = {omega.x, omega.y, omega.z};
    ::quat::matrix<T, 3, 3> q = so3::hat(k);
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
[[nodiscard]] constexpr ::quat::matrix<T, 6, 6> upper_block_triangular(
    const ::quat::matrix<T, 3, 3>& a, const ::quat::matrix<T, 3, 3>& b) noexcept {
    ::quat::matrix<T, 6, 6> m = ::quat::matrix<T, 6, 6>::zero();
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

/// The rotation matrix of a unit dual quaternion, as a matrix3.
template <class T>
[[nodiscard]] constexpr matrix3<T> rotation_matrix_of(const dual_quaternion<T>& x) noexcept {
    return so3::adjoint(x.real);
}

/// The adjoint Ad(X) = [[R, [t]x R], [0, R]] (twists linear first): X exp(d) = exp(Ad(X) d) X.
/// Precondition: unit X.
template <class T>
[[nodiscard]] constexpr matrix6<T> adjoint(const dual_quaternion<T>& x) noexcept {
    const matrix3<T> r = rotation_matrix_of(x);
    return quat::detail::upper_block_triangular(r, so3::hat(translation_of(x)) * r);
}

/// The inverse motion of a unit X: both parts conjugated, exact for unit X (dot(real, dual) = 0);
/// *d = -Ad(X).
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> inverse(
    const dual_quaternion<T>& x, quat::detail::type_identity_t<matrix6<T>>* d = nullptr) noexcept {
    if (d != nullptr) *d = -adjoint(x);
    return quat::detail::rigid_inverse(x);
}

/// exp(t): the motion x -> exp(omega) x + Jl(omega) rho as a unit dual quaternion; *jacobian =
/// Jr(t). Any finite twist; a NaN or infinite component gives NaN in every component.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> exp(
    const twist<T>& t, quat::detail::type_identity_t<matrix6<T>>* jacobian = nullptr) noexcept {
    // Jl(omega) = Jr(omega)^T ([omega]x is skew, [omega]x^2 symmetric): the translation needs Jr
    // even when the Jacobian is not asked for.
    matrix3<T> jr{};
    const quaternion<T> rotation = so3::exp(t.angular, &jr);
    if (jacobian != nullptr)
        *jacobian = quat::detail::upper_block_triangular(
            jr, quat::detail::se3_q_block(-t.linear, -t.angular));
    const dual_quaternion<T> motion = to_dual_quaternion(rotation, transpose(jr) * t.linear);
    if constexpr (std::is_floating_point_v<T>) {
        // A bad linear part leaves the rotation finite; half a result would pass for an answer.
        if (!quat::detail::is_finite(t.linear) || !quat::detail::is_finite(t.angular))
            return {quat::detail::nan_quaternion<T>(), quat::detail::nan_quaternion<T>()};
    }
    return motion;
}

/// log(X): the twist with |omega| in [0, pi] whose exp is X (X and -X alike); *jacobian =
/// Jr(log X)^-1. Precondition: unit X.
template <class T>
[[nodiscard]] constexpr twist<T> log(
    const dual_quaternion<T>& x,
    quat::detail::type_identity_t<matrix6<T>>* jacobian = nullptr) noexcept {
    // Jl(omega)^-1 = (Jr(omega)^-1)^T ([omega]x is skew, [omega]x^2 symmetric).
    matrix3<T> a{};
    const vec3<T> omega = so3::log(x.real, &a);
    const twist<T> t{transpose(a) * translation_of(x), omega};
    if (jacobian != nullptr)
        *jacobian = quat::detail::upper_block_triangular(
            a, -(a * quat::detail::se3_q_block(-t.linear, -t.angular) * a));
    return t;
}

/// log of the rigid motion m = [R t; 0 1]: log(to_dual_quaternion(m)), with the same Jacobian (one
/// group element, two forms; to_homogeneous(exp(t)) is the other way). Precondition: m rigid.
template <class T>
[[nodiscard]] constexpr twist<T> log(
    const homogeneous_matrix<T>& m,
    quat::detail::type_identity_t<matrix6<T>>* jacobian = nullptr) noexcept {
    return log(to_dual_quaternion(m), jacobian);
}

/// a * b (b first); *d_a = Ad(b)^-1, *d_b = I. Precondition: unit a and b.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> compose(
    const dual_quaternion<T>& a, const dual_quaternion<T>& b,
    quat::detail::type_identity_t<matrix6<T>>* d_a = nullptr,
    quat::detail::type_identity_t<matrix6<T>>* d_b = nullptr) noexcept {
    if (d_a != nullptr) *d_a = adjoint(quat::detail::rigid_inverse(b));
    if (d_b != nullptr) *d_b = matrix6<T>::identity();
    return a * b;
}

/// transform(X, p) = R p + t; *d_x = [R, -R [p]x] (3x6), *d_p = R. Precondition: unit X.
template <class T>
[[nodiscard]] constexpr vec3<T> act(
    const dual_quaternion<T>& x, const vec3<T>& p,
    quat::detail::type_identity_t<matrix<T, 3, 6>>* d_x = nullptr,
    quat::detail::type_identity_t<matrix3<T>>* d_p = nullptr) noexcept {
    if (d_x != nullptr || d_p != nullptr) {
        const matrix3<T> r = rotation_matrix_of(x);
        if (d_x != nullptr) {
            set_block(*d_x, 0, 0, r);
            set_block(*d_x, 0, 3, -(r * so3::hat(p)));
        }
        if (d_p != nullptr) *d_p = r;
    }
    return transform(x, p);
}

/// x^-1 y, the motion from x to y in x's frame; *d_x = -Ad(x^-1 y)^-1, *d_y = I. Unit x and y.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> between(
    const dual_quaternion<T>& x, const dual_quaternion<T>& y,
    quat::detail::type_identity_t<matrix6<T>>* d_x = nullptr,
    quat::detail::type_identity_t<matrix6<T>>* d_y = nullptr) noexcept {
    const dual_quaternion<T> d = quat::detail::rigid_inverse(x) * y;
    if (d_x != nullptr) *d_x = -adjoint(quat::detail::rigid_inverse(d));
    if (d_y != nullptr) *d_y = matrix6<T>::identity();
    return d;
}

/// x (+) t = x exp(t); *d_x = Ad(exp t)^-1, *d_t = Jr(t). Precondition: unit x.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> plus(
    const dual_quaternion<T>& x, const twist<T>& t,
    quat::detail::type_identity_t<matrix6<T>>* d_x = nullptr,
    quat::detail::type_identity_t<matrix6<T>>* d_t = nullptr) noexcept {
    const dual_quaternion<T> e = exp(t, d_t);
    if (d_x != nullptr) *d_x = adjoint(quat::detail::rigid_inverse(e));
    return x * e;
}

/// y (-) x = log(x^-1 y); *d_y = Jr(t)^-1, *d_x = -Jl(t)^-1 for t the result. Unit x and y.
template <class T>
[[nodiscard]] constexpr twist<T> minus(
    const dual_quaternion<T>& y, const dual_quaternion<T>& x,
    quat::detail::type_identity_t<matrix6<T>>* d_y = nullptr,
    quat::detail::type_identity_t<matrix6<T>>* d_x = nullptr) noexcept {
    const twist<T> t = log(quat::detail::rigid_inverse(x) * y, d_y);
    if (d_x != nullptr) *d_x = -left_jacobian_inverse(t);
    return t;
}

/// exp(t) x, the left plus; *d_t = Ad(x)^-1 Jr(t), *d_x = I (right-convention Jacobians, as
/// everywhere here). Precondition: unit x.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> plus_left(
    const twist<T>& t, const dual_quaternion<T>& x,
    quat::detail::type_identity_t<matrix6<T>>* d_t = nullptr,
    quat::detail::type_identity_t<matrix6<T>>* d_x = nullptr) noexcept {
    if (d_t != nullptr) *d_t = adjoint(quat::detail::rigid_inverse(x)) * right_jacobian(t);
    if (d_x != nullptr) *d_x = matrix6<T>::identity();
    return exp(t) * x;
}

/// log(y x^-1), the left minus; *d_y = Jr(t)^-1 Ad(x), *d_x = -Jr(t)^-1 Ad(x) for t the result
/// (right-convention Jacobians). Precondition: unit x and y.
template <class T>
[[nodiscard]] constexpr twist<T> minus_left(
    const dual_quaternion<T>& y, const dual_quaternion<T>& x,
    quat::detail::type_identity_t<matrix6<T>>* d_y = nullptr,
    quat::detail::type_identity_t<matrix6<T>>* d_x = nullptr) noexcept {
    const twist<T> t = log(y * quat::detail::rigid_inverse(x));
    if (d_y != nullptr || d_x != nullptr) {
        const matrix6<T> j = right_jacobian_inverse(t) * adjoint(x);
        if (d_y != nullptr) *d_y = j;
        if (d_x != nullptr) *d_x = -j;
    }
    return t;
}

}  // inline namespace isa_...
}  // namespace se3

}  // namespace quat

#endif  // QUAT_LIE_SE3_HPP_INCLUDED
