// Opt-in Ceres Solver support (not included by quat.hpp; needs Ceres's headers and library): two
// ceres::Manifold classes with analytic Jacobians, a pose-graph edge as a ceres::CostFunction
// (relative_pose_cost, lie/relative_pose.hpp's errors with analytic Jacobians), and functions that
// read a cost functor's parameter blocks (`const T*`, T double or ceres::Jet) as quat types and
// write quat types back.
//
// Parameter-block layouts (scalar FIRST, quat's order, the memory layout of
// ceres::QuaternionManifold
// and ceres/rotation.h; NOT Eigen's x, y, z, w, and not g2o's x, y, z, qx, qy, qz, qw, which put
// the
// scalar last: convert such data when reading it):
//   rotation: 4 numbers  w, x, y, z                      (quaternion_manifold)
//   pose:     7 numbers  w, x, y, z, tx, ty, tz          (pose_manifold): rotation then translation
//   twist:    6 numbers  linear x, y, z, angular x, y, z (se3::twist, the pose manifold's tangent)
//
// Both manifolds perturb on the right, as quat's so3/se3 functions (Sola et al., "A micro Lie
// theory for state estimation in robotics", 2018): Plus(x, d) = x exp(d), Minus(y, x) = log(x^-1
// y),
// so a tangent step is expressed in the body frame of x. Minus keeps the sign of the quaternion
// x^-1 y (angle up to 2 pi), so that Plus(x, Minus(y, x)) is the block y itself, as Ceres's
// manifold invariants require; so3::minus and se3::minus take the shortest path instead.
// ceres::QuaternionManifold perturbs on the left with half the angle, exp(d) * x: the same
// manifold with the same minima, its tangent d_ceres = R(x) d / 2 for quaternion_manifold's d.
#ifndef QUAT_INTEROP_CERES_HPP_INCLUDED
#define QUAT_INTEROP_CERES_HPP_INCLUDED

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>

#include <ceres/manifold.h>
#include <ceres/sized_cost_function.h>

#include "../constants.hpp"
#include "../conversions.hpp"
#include "../lie/relative_pose.hpp"
#include "../lie/se3.hpp"
#include "../lie/so3.hpp"
#include "../quaternion.hpp"
#include "../rigid/dual_quaternion.hpp"
#include "../vec3.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
/// The quaternion p[0] + p[1] i + p[2] j + p[3] k (w, x, y, z) of a rotation block. T is the cost
/// functor's scalar (double or ceres::Jet). Precondition: p points at 4 numbers.
template <class T>
[[nodiscard]] constexpr quaternion<T> quaternion_from_parameters(const T* p) noexcept {
    return {p[0], p[1], p[2], p[3]};
}

/// The vector (p[0], p[1], p[2]). Precondition: p points at 3 numbers.
template <class T>
[[nodiscard]] constexpr vec3<T> vec3_from_parameters(const T* p) noexcept {
    return {p[0], p[1], p[2]};
}

/// The rigid motion x -> R x + t of a pose block w, x, y, z, tx, ty, tz: rotation p[0..3] first,
/// then translation p[4..6] (to_dual_quaternion). Precondition: p points at 7 numbers whose first
/// four are a unit quaternion (pose_manifold keeps them so).
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> pose_from_parameters(const T* p) noexcept {
    return to_dual_quaternion(quaternion_from_parameters(p), vec3_from_parameters(p + 4));
}

/// The twist of a 6-number tangent block, linear part first (se3::twist's order).
template <class T>
[[nodiscard]] constexpr se3::twist<T> twist_from_parameters(const T* p) noexcept {
    return {vec3_from_parameters(p), vec3_from_parameters(p + 3)};
}

/// Writes q as w, x, y, z to p[0..3].
template <class T>
constexpr void write_parameters(const quaternion<T>& q, T* p) noexcept {
    p[0] = q.w;
    p[1] = q.x;
    p[2] = q.y;
    p[3] = q.z;
}

/// Writes v as x, y, z to p[0..2].
template <class T>
constexpr void write_parameters(const vec3<T>& v, T* p) noexcept {
    p[0] = v.x;
    p[1] = v.y;
    p[2] = v.z;
}

/// Writes the unit dual quaternion x as a pose block: its rotation w, x, y, z, then its translation
/// (translation_of). Precondition: |x.real| = 1. x and -x write different numbers for one motion.
template <class T>
constexpr void write_parameters(const dual_quaternion<T>& x, T* p) noexcept {
    write_parameters(rotation_of(x), p);
    write_parameters(translation_of(x), p + 4);
}

/// Writes the twist v as 6 numbers, linear part first.
template <class T>
constexpr void write_parameters(const se3::twist<T>& v, T* p) noexcept {
    write_parameters(v.linear, p);
    write_parameters(v.angular, p + 3);
}

namespace detail {

/// d(q exp(d)) / dd at d = 0, the 4x3 row-major matrix q (0, e_i) / 2 (columns i = 0, 1, 2):
/// [-v^T; w I + [v]x] / 2 for q = (w, v).
inline void quaternion_plus_jacobian(const double* q, double* j) noexcept {
    const double w = q[0] / 2, x = q[1] / 2, y = q[2] / 2, z = q[3] / 2;
    const double rows[4][3] = {{-x, -y, -z}, {w, -z, y}, {z, w, -x}, {-y, x, w}};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 3; ++c) j[r * 3 + c] = rows[r][c];
}

/// d log(q^-1 y) / dy at y = q, the 3x4 row-major matrix 2 [-v | w I - [v]x] for q = (w, v): twice
/// the vector part of q^-1 dy. Its product with quaternion_plus_jacobian is the identity, and
/// it sends q itself (a change of |y|, which log ignores) to zero.
inline void quaternion_minus_jacobian(const double* q, double* j) noexcept {
    const double w = 2 * q[0], x = 2 * q[1], y = 2 * q[2], z = 2 * q[3];
    const double rows[3][4] = {{-x, w, z, -y}, {-y, -z, w, x}, {-z, y, -x, w}};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) j[r * 4 + c] = rows[r][c];
}

/// j (R x 3, with respect to a rotation's right tangent) times quaternion_minus_jacobian at the
/// block q: the R x 4 row-major Jacobian with respect to the block's numbers w, x, y, z.
template <int R>
void write_rotation_jacobian(const matrix<double, R, 3>& j, const double* q,
                             double* ambient) noexcept {
    double m[3 * 4];
    quaternion_minus_jacobian(q, m);
    for (int row = 0; row < R; ++row)
        for (int col = 0; col < 4; ++col) {
            double sum = 0;
            for (int k = 0; k < 3; ++k) sum += j(row, k) * m[k * 4 + col];
            ambient[row * 4 + col] = sum;
        }
}

/// j (R x 6, with respect to a pose's twist) times pose_manifold's MinusJacobian at the block x,
/// [[0, R^T], [M, 0]]: the R x 7 row-major Jacobian with respect to w, x, y, z, tx, ty, tz.
template <int R>
void write_pose_jacobian(const matrix<double, R, 6>& j, const double* x, double* ambient) noexcept {
    double m[3 * 4];
    quaternion_minus_jacobian(x, m);
    const rotation_matrix<double> r = to_matrix(quaternion_from_parameters(x));
    for (int row = 0; row < R; ++row) {
        for (int col = 0; col < 4; ++col) {
            double sum = 0;
            for (int k = 0; k < 3; ++k) sum += j(row, 3 + k) * m[k * 4 + col];
            ambient[row * 7 + col] = sum;
        }
        for (int col = 0; col < 3; ++col) {
            double sum = 0;
            for (int k = 0; k < 3; ++k) sum += j(row, k) * r(col, k);
            ambient[row * 7 + 4 + col] = sum;
        }
    }
}

/// j (R x C) to row-major numbers: the Jacobian with respect to a block of C plain numbers.
template <int R, int C>
void write_plain_jacobian(const matrix<double, R, C>& j, double* ambient) noexcept {
    for (int row = 0; row < R; ++row)
        for (int col = 0; col < C; ++col) ambient[row * C + col] = j(row, col);
}

/// The rotation vector whose exp is q itself, not -q: log(q) with q's sign kept, angle in
/// [0, 2 pi] (to_rotation_vector's for w >= 0). The manifolds' Minus needs it so that
/// Plus(x, Minus(y, x)) is y and not -y, which Ceres's manifold tests require of a Minus (the
/// shortest path, so3::minus, reaches -y when dot(x, y) < 0). Any non-zero scale of q; q = -1
/// gives 2 pi about the x axis (every axis reaches -1).
inline vec3<double> log_keeping_sign(const quaternion<double>& q) noexcept {
    if (!(q.w < 0)) return to_rotation_vector(q);
    const vec3<double> v{q.x, q.y, q.z};
    const double s = norm(v);
    if (s == 0) return {2 * numbers::pi_v<double>, 0, 0};
    return v * (2 * std::atan2(s, q.w) / s);
}

/// The twist whose exp is x itself, not -x: se3::log with the sign of x's rotation kept (angle in
/// [0, 2 pi]), rho = Jl(omega)^-1 t. Jl(omega) is singular at 2 pi, where only translations along
/// the axis are reached: for a rotation part of exactly -1, omega = 2 pi t / |t| (Jl = the
/// projection on t) and rho = t. Near 2 pi rho grows as 1/(2 pi - |omega|), and Plus loses as many
/// digits. Precondition: unit x.
inline se3::twist<double> log_keeping_sign(const dual_quaternion<double>& x) noexcept {
    if (!(x.real.w < 0)) return se3::log(x);
    const vec3<double> t = translation_of(x), v{x.real.x, x.real.y, x.real.z};
    if (norm(v) == 0) {
        const double length = norm(t);
        const vec3<double> axis = length > 0 ? t / length : vec3<double>{1, 0, 0};
        return {t, axis * (2 * numbers::pi_v<double>)};
    }
    const vec3<double> omega = log_keeping_sign(x.real);
    return {so3::left_jacobian_inverse(omega) * t, omega};
}

}  // namespace detail

/// SO(3) as unit quaternions w, x, y, z (4 numbers) with rotation-vector tangents (3 numbers):
/// Plus(x, d) = x * from_rotation_vector(d), Minus(y, x) = log(x^-1 y) keeping its sign, both on
/// the right (d turns x about an axis of its own frame). ceres::QuaternionManifold stores the same
/// 4 numbers and has the same minima, with tangent d_ceres = R(x) d / 2 (it computes exp(d_ceres) x
/// with exp(d_ceres) rotating by 2 |d_ceres|). Precondition: unit quaternions in x and y; Plus
/// keeps them unit to rounding (it does not renormalize).
class quaternion_manifold final : public ::ceres::Manifold {
public:
    /// 4: w, x, y, z.
    [[nodiscard]] int AmbientSize() const override { return 4; }
    /// 3: a rotation vector (angle * axis, radians) in the frame of x.
    [[nodiscard]] int TangentSize() const override { return 3; }

    /// x * exp(delta), written to x_plus_delta (w, x, y, z). Always succeeds.
    bool Plus(const double* x, const double* delta, double* x_plus_delta) const override {
        write_parameters(
            quaternion_from_parameters(x) * from_rotation_vector(vec3_from_parameters(delta)),
            x_plus_delta);
        return true;
    }

    /// d Plus(x, delta) / d delta at delta = 0: 4x3, row-major.
    bool PlusJacobian(const double* x, double* jacobian) const override {
        detail::quaternion_plus_jacobian(x, jacobian);
        return true;
    }

    /// log(x^-1 y) with the sign of x^-1 y kept (angle in [0, 2 pi]): the rotation vector that
    /// Plus adds to x to reach y itself, not -y. Not so3::minus, the shortest path (angle in
    /// [0, pi]), which reaches -y when dot(x, y) < 0; the two agree where dot(x, y) >= 0.
    bool Minus(const double* y, const double* x, double* y_minus_x) const override {
        write_parameters(detail::log_keeping_sign(conjugate(quaternion_from_parameters(x)) *
                                                  quaternion_from_parameters(y)),
                         y_minus_x);
        return true;
    }

    /// d Minus(y, x) / dy at y = x: 3x4, row-major.
    bool MinusJacobian(const double* x, double* jacobian) const override {
        detail::quaternion_minus_jacobian(x, jacobian);
        return true;
    }
};

/// SE(3) as poses w, x, y, z, tx, ty, tz (7 numbers: unit quaternion, then translation) with twist
/// tangents, linear part first (6 numbers, se3::twist): Plus(X, tau) = X se3::exp(tau) and Minus(Y,
/// X) = log(X^-1 Y) keeping its sign, on the right. This is SE(3), not SO(3) x R^3: a step turns
/// and moves along a screw in the frame of X, as the residuals of a pose graph do. Precondition:
/// unit quaternions; Plus keeps them unit to rounding.
class pose_manifold final : public ::ceres::Manifold {
public:
    /// 7: w, x, y, z, tx, ty, tz.
    [[nodiscard]] int AmbientSize() const override { return 7; }
    /// 6: a twist, linear x, y, z then angular x, y, z.
    [[nodiscard]] int TangentSize() const override { return 6; }

    /// X exp(tau), written to x_plus_delta as a pose block. Always succeeds.
    bool Plus(const double* x, const double* delta, double* x_plus_delta) const override {
        write_parameters(se3::plus(pose_from_parameters(x), twist_from_parameters(delta)),
                         x_plus_delta);
        return true;
    }

    /// d Plus(X, tau) / d tau at tau = 0: 7x6, row-major, [[0, Q], [R, 0]] with Q the
    /// quaternion's 4x3 plus-Jacobian and R the rotation matrix of X (a linear step moves along
    /// the axes of X).
    bool PlusJacobian(const double* x, double* jacobian) const override {
        for (int i = 0; i < 7 * 6; ++i) jacobian[i] = 0;
        double q[4 * 3];
        detail::quaternion_plus_jacobian(x, q);
        const rotation_matrix<double> r = to_matrix(quaternion_from_parameters(x));
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 3; ++col) jacobian[row * 6 + 3 + col] = q[row * 3 + col];
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col) jacobian[(4 + row) * 6 + col] = r(row, col);
        return true;
    }

    /// log(X^-1 Y) with the sign of the rotation of X^-1 Y kept (angle in [0, 2 pi]): the twist
    /// that Plus adds to X to reach the block Y itself, not the same motion with its quaternion
    /// negated. se3::minus (angle in [0, pi]) where the rotations' dot product is >= 0.
    bool Minus(const double* y, const double* x, double* y_minus_x) const override {
        write_parameters(
            detail::log_keeping_sign(quat::detail::rigid_inverse(pose_from_parameters(x)) *
                                     pose_from_parameters(y)),
            y_minus_x);
        return true;
    }

    /// d Minus(Y, X) / dY at Y = X: 6x7, row-major, [[0, R^T], [M, 0]] with M the quaternion's
    /// 3x4 minus-Jacobian. MinusJacobian * PlusJacobian is the 6x6 identity.
    bool MinusJacobian(const double* x, double* jacobian) const override {
        for (int i = 0; i < 6 * 7; ++i) jacobian[i] = 0;
        double m[3 * 4];
        detail::quaternion_minus_jacobian(x, m);
        const rotation_matrix<double> r = to_matrix(quaternion_from_parameters(x));
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col) jacobian[row * 7 + 4 + col] = r(col, row);
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 4; ++col) jacobian[(3 + row) * 7 + col] = m[row * 4 + col];
        return true;
    }
};
/// Which relative-pose error a relative_pose_cost evaluates (lie/relative_pose.hpp).
enum class relative_pose_form {
    so3xr3,  ///< so3xr3::relative_pose_error, Ceres's pose_graph_3d: (delta p, 2 vec(delta q))
    se3,     ///< se3::relative_pose_error: log(Z^-1 A^-1 B)
};

/// The upper-triangular U with U^T U = information, so that |U e|^2 = e^T information e: the
/// square root that weighs a residual e by the information (inverse covariance). Only the upper
/// triangle of information is read. Empty when a pivot is not positive and finite (information not
/// positive definite, or NaN). Ceres's pose_graph_3d example weighs by L = transpose(U), the lower
/// Cholesky factor (information = L L^T): |L e|^2 = e^T L^T L e, which equals e^T information e
/// only where the information is diagonal.
[[nodiscard]] inline std::optional<matrix6<double>> information_square_root(
    const matrix6<double>& information) noexcept {
    matrix6<double> u = matrix6<double>::zero();
    for (int r = 0; r < 6; ++r) {
        double pivot = information(r, r);
        for (int k = 0; k < r; ++k) pivot -= u(k, r) * u(k, r);
        if (!(pivot > 0) || !std::isfinite(pivot)) return std::nullopt;
        u(r, r) = std::sqrt(pivot);
        for (int c = r + 1; c < 6; ++c) {
            double s = information(r, c);
            for (int k = 0; k < r; ++k) s -= u(k, r) * u(k, c);
            u(r, c) = s / u(r, r);
        }
    }
    return u;
}

/// A pose-graph edge as a ceres::CostFunction on two pose blocks (w, x, y, z, tx, ty, tz each, the
/// layout of pose_manifold): the residual S e(A, B) for the relative-pose error e of the chosen
/// form, with the measured pose Z of B seen from A and S the square root of the information
/// (information_square_root, or any 6x6 weight). The Jacobians are analytic: S times the tangent
/// Jacobians of lie/relative_pose.hpp times pose_manifold's MinusJacobian, 6x7 with respect to the
/// ambient numbers. They are exact along every change that keeps the quaternion unit and zero along
/// the quaternion itself, so they serve pose_manifold and any other manifold on these 7 numbers
/// that keeps the quaternion unit (ceres::ProductManifold of ceres::QuaternionManifold and
/// ceres::EuclideanManifold<3>, Ceres's own split parameterization). Precondition: unit
/// quaternions in the blocks and in Z; a NaN or infinite number gives a non-finite residual, which
/// Ceres rejects as a failed evaluation.
class relative_pose_cost final : public ::ceres::SizedCostFunction<6, 7, 7> {
public:
    /// An edge of the given form: Z = measured (unit), S = sqrt_information applied to the error.
    relative_pose_cost(relative_pose_form form, const dual_quaternion<double>& measured,
                       const matrix6<double>& sqrt_information) noexcept
        : form_(form),
          measured_(measured),
          measured_rotation_(rotation_of(measured)),
          measured_translation_(translation_of(measured)),
          sqrt_information_(sqrt_information) {}

    /// S e(A, B) to residuals (6), A and B read from parameters[0] and [1] (w, x, y, z, tx, ty,
    /// tz); each jacobians[k] that is not null receives the 6x7 row-major Jacobian with respect to
    /// block k. Always succeeds: a non-finite input shows as a non-finite residual.
    bool Evaluate(double const* const* parameters, double* residuals,
                  double** jacobians) const override {
        const double* const a = parameters[0];
        const double* const b = parameters[1];
        const bool want_a = jacobians != nullptr && jacobians[0] != nullptr;
        const bool want_b = jacobians != nullptr && jacobians[1] != nullptr;
        matrix6<double> J_e_a{}, J_e_b{};
        matrix<double, 6, 1> e{};
        if (form_ == relative_pose_form::so3xr3) {
            e = quat::detail::so3xr3_relative_pose_error(
                quaternion_from_parameters(a), vec3_from_parameters(a + 4),
                quaternion_from_parameters(b), vec3_from_parameters(b + 4), measured_rotation_,
                measured_translation_, want_a ? &J_e_a : nullptr, want_b ? &J_e_b : nullptr);
        } else {
            e = se3::relative_pose_error(pose_from_parameters(a), pose_from_parameters(b),
                                         measured_, want_a ? &J_e_a : nullptr,
                                         want_b ? &J_e_b : nullptr);
        }
        const matrix<double, 6, 1> r = sqrt_information_ * e;
        for (int k = 0; k < 6; ++k) residuals[k] = r(k, 0);
        if (want_a) detail::write_pose_jacobian<6>(sqrt_information_ * J_e_a, a, jacobians[0]);
        if (want_b) detail::write_pose_jacobian<6>(sqrt_information_ * J_e_b, b, jacobians[1]);
        return true;
    }

private:
    relative_pose_form form_;
    dual_quaternion<double> measured_;
    quaternion<double> measured_rotation_;
    vec3<double> measured_translation_;
    matrix6<double> sqrt_information_;
};

}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_INTEROP_CERES_HPP_INCLUDED
