// One segment of a cumulative B-spline on a Lie group (SO(3) or SE(3)): the value, the body-frame
// velocity and its first two time derivatives, and their Jacobians with respect to the segment's K
// control points, after C. Sommer, V. Usenko, D. Schubert, N. Demmel, D. Cremers, "Efficient
// Derivative Computation for Cumulative B-Splines on Lie Groups", CVPR 2020 (derived here from its
// equations, in quat's conventions). With d_j = log(P_(j-1)^-1 P_j), A_j = exp(b~_j d_j) and
// x_j = b~_j' d_j (primes are time derivatives), the value is X = P_0 A_1 ... A_(K-1) and
// the body velocity omega = (X^-1 X')^v follows the paper's recurrence, one step per factor:
//     w_(j+1)  = Ad(A_j^-1) w_j + x_j,                                          w_1 = 0,
//     a_(j+1)  = Ad(A_j^-1) a_j + b~_j'' d_j + [w_(j+1), x_j],                   a_1 = 0,
//     y_(j+1)  = Ad(A_j^-1) y_j + 2 [a_(j+1), x_j] + [w_(j+1), b~_j'' d_j]
//                + [x_j, [w_(j+1), x_j]] + b~_j''' d_j,                         y_1 = 0,
// with omega = w_K, its derivative a_K and second derivative y_K. The third line follows from
// differentiating the second with d/dt Ad(A_j^-1) v = -[x_j, Ad(A_j^-1) v] + Ad(A_j^-1) v' and
// substituting it back. Each costs O(K) group operations, against O(K^2) for the product rule.
//
// Jacobians use the right perturbation P_m <- P_m exp(delta_m) and the output's right minus (plain
// difference for the velocities), as lie/so3.hpp and lie/se3.hpp do. Each step depends on d_j
// through Ad(A_j^-1) (d/d d_j of Ad(A_j^-1) v = ad(Ad(A_j^-1) v) b~_j Jr(b~_j d_j)) and through its
// source terms; a backward pass carries the derivative of the output with respect to each level's
// (w, a, y), a K-step reverse sweep of the recurrence (the paper's Jacobians, unrolled level by level), O(K)
// again.
// d_j depends on P_j through Jr(d_j)^-1 and on P_(j-1) through -Jl(d_j)^-1 (so3::minus).
#ifndef QUAT_TRAJECTORY_DETAIL_LIE_BSPLINE_HPP_INCLUDED
#define QUAT_TRAJECTORY_DETAIL_LIE_BSPLINE_HPP_INCLUDED

#include <array>
#include <cstddef>

#include "../../lie/se3.hpp"
#include "../../lie/so3.hpp"
#include "../../matrix.hpp"
#include "../../quaternion.hpp"
#include "../../rigid/dual_quaternion.hpp"
#include "../../vec3.hpp"
#include "uniform_basis.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

/// SO(3) for the spline: unit quaternions, rotation vectors, 3x3 Jacobians; ad(v) = [v]x.
template <class T>
struct so3_spline_group {
    using element = quaternion<T>;
    using tangent = vec3<T>;
    using jacobian = matrix3<T>;
    [[nodiscard]] static constexpr tangent zero() noexcept { return {T(0), T(0), T(0)}; }
    [[nodiscard]] static constexpr tangent minus(const element& y, const element& x, jacobian* J_y,
                                                 jacobian* J_x) noexcept {
        return so3::minus(y, x, J_y, J_x);
    }
    [[nodiscard]] static constexpr element exp(const tangent& v, jacobian* J) noexcept {
        return so3::exp(v, J);
    }
    [[nodiscard]] static constexpr jacobian inverse_adjoint(const element& a) noexcept {
        return transpose(so3::adjoint(a));
    }
    [[nodiscard]] static constexpr jacobian ad(const tangent& v) noexcept { return so3::hat(v); }
    [[nodiscard]] static constexpr tangent bracket(const tangent& a, const tangent& b) noexcept {
        return cross(a, b);
    }
};

/// SE(3) for the spline: unit dual quaternions, twists as columns (rho, omega), linear first;
/// ad(rho, omega) = [[ [omega]x, [rho]x ], [0, [omega]x ]].
template <class T>
struct se3_spline_group {
    using element = dual_quaternion<T>;
    using tangent = matrix<T, 6, 1>;
    using jacobian = matrix6<T>;
    [[nodiscard]] static constexpr vec3<T> linear(const tangent& v) noexcept {
        return {v(0, 0), v(1, 0), v(2, 0)};
    }
    [[nodiscard]] static constexpr vec3<T> angular(const tangent& v) noexcept {
        return {v(3, 0), v(4, 0), v(5, 0)};
    }
    [[nodiscard]] static constexpr tangent zero() noexcept { return tangent::zero(); }
    [[nodiscard]] static constexpr tangent minus(const element& y, const element& x, jacobian* J_y,
                                                 jacobian* J_x) noexcept {
        return se3::to_vector(se3::minus(y, x, J_y, J_x));
    }
    [[nodiscard]] static constexpr element exp(const tangent& v, jacobian* J) noexcept {
        return se3::exp(se3::to_twist(v), J);
    }
    [[nodiscard]] static constexpr jacobian inverse_adjoint(const element& a) noexcept {
        return se3::adjoint(rigid_inverse(a));
    }
    [[nodiscard]] static constexpr jacobian ad(const tangent& v) noexcept {
        const matrix3<T> w = so3::hat(angular(v));
        return upper_block_triangular(w, so3::hat(linear(v)));
    }
    [[nodiscard]] static constexpr tangent bracket(const tangent& a, const tangent& b) noexcept {
        const vec3<T> l = cross(angular(a), linear(b)) + cross(linear(a), angular(b));
        const vec3<T> w = cross(angular(a), angular(b));
        return {{{l.x}, {l.y}, {l.z}, {w.x}, {w.y}, {w.z}}};
    }
};

/// The value and the body velocity with its first two time derivatives at one time.
template <class Group>
struct lie_spline_sample {
    typename Group::element value;
    typename Group::tangent velocity, acceleration, jerk;
};

/// The per-point blocks of one output's Jacobian from its derivatives with respect to d_1 ..
/// d_(K-1) (J_d[0] unused): block m = J_d[m] dd_m/dP_m + J_d[m+1] dd_(m+1)/dP_m, plus `direct`
/// for P_0.
template <class M, std::size_t K>
constexpr void to_point_blocks(const std::array<M, K>& J_d, const std::array<M, K>& J_self,
                               const std::array<M, K>& J_previous, const M& direct,
                               std::array<M, K>& out) noexcept {
    for (std::size_t m = 0; m < K; ++m) {
        M block = m == 0 ? direct : J_d[m] * J_self[m];
        if (m + 1 < K) block = block + J_d[m + 1] * J_previous[m + 1];
        out[m] = block;
    }
}

/// Evaluates one segment over the K control points p[0 .. K-1] with the cumulative weights w;
/// derivatives of the velocity up to `order` (0: the value only, 1 velocity, 2 acceleration, 3
/// jerk; those not computed are left zero). Each Jacobian pointer that is not null receives K
/// blocks; a velocity Jacobian asks for at least that order. No allocation: fixed-size arrays.
template <class Group, class T, std::size_t K>
constexpr lie_spline_sample<Group> evaluate_lie_bspline(
    const typename Group::element* p, const cumulative_weights<T, K>& w, int order,
    std::array<typename Group::jacobian, K>* J_value,
    std::array<typename Group::jacobian, K>* J_velocity,
    std::array<typename Group::jacobian, K>* J_acceleration,
    std::array<typename Group::jacobian, K>* J_jerk) noexcept {
    using V = typename Group::tangent;
    using M = typename Group::jacobian;
    if (J_jerk != nullptr && order < 3) order = 3;
    if (J_acceleration != nullptr && order < 2) order = 2;
    if (J_velocity != nullptr && order < 1) order = 1;
    const bool jacobians = J_value != nullptr || J_velocity != nullptr ||
                           J_acceleration != nullptr || J_jerk != nullptr;
    const auto& b0 = w.b[0];
    const auto& b1 = w.b[1];
    const auto& b2 = w.b[2];
    const auto& b3 = w.b[3];
    std::array<V, K> d{}, wB{}, aB{}, yB{};     // d_j; Ad(A_j^-1) times w_j, a_j, y_j
    std::array<V, K + 1> vel{}, acc{}, jerk{};  // w, a, y by level (1 .. K)
    std::array<M, K> J_self{}, J_previous{}, J_exp{}, B{};
    vel[1] = acc[1] = jerk[1] = Group::zero();
    lie_spline_sample<Group> out{p[0], Group::zero(), Group::zero(), Group::zero()};
    for (std::size_t j = 1; j < K; ++j) {
        d[j] = Group::minus(p[j], p[j - 1], jacobians ? &J_self[j] : nullptr,
                            jacobians ? &J_previous[j] : nullptr);
        const typename Group::element a = Group::exp(d[j] * b0[j], jacobians ? &J_exp[j] : nullptr);
        out.value = out.value * a;
        if (order < 1 && J_value == nullptr) continue;
        B[j] = Group::inverse_adjoint(a);
        if (order < 1) continue;
        wB[j] = B[j] * vel[j];
        vel[j + 1] = wB[j] + d[j] * b1[j];
        if (order < 2) continue;
        const V x1 = d[j] * b1[j], x2 = d[j] * b2[j];
        aB[j] = B[j] * acc[j];
        acc[j + 1] = aB[j] + x2 + Group::bracket(vel[j + 1], x1);
        if (order < 3) continue;
        yB[j] = B[j] * jerk[j];
        jerk[j + 1] = yB[j] + Group::bracket(acc[j + 1], x1) * T(2) +
                      Group::bracket(vel[j + 1], x2) +
                      Group::bracket(x1, Group::bracket(vel[j + 1], x1)) + d[j] * b3[j];
    }
    if (order >= 1) out.velocity = vel[K];
    if (order >= 2) out.acceleration = acc[K];
    if (order >= 3) out.jerk = jerk[K];
    if (!jacobians) return out;

    const M I = M::identity(), O = M::zero();
    std::array<M, K> J_d{};
    if (J_value != nullptr) {  // X depends on d_j through Ad(S_j^-1) b~_j Jr(b~_j d_j)
        M L = I;
        for (std::size_t j = K - 1; j >= 1; --j) {
            J_d[j] = L * (J_exp[j] * b0[j]);
            L = L * B[j];
        }
        to_point_blocks<M, K>(J_d, J_self, J_previous, L, *J_value);
    }
    if (J_velocity != nullptr) {
        M La = I;
        for (std::size_t j = K - 1; j >= 1; --j) {
            const M through_b = J_exp[j] * b0[j];
            J_d[j] = La * (Group::ad(wB[j]) * through_b + I * b1[j]);
            La = La * B[j];
        }
        to_point_blocks<M, K>(J_d, J_self, J_previous, O, *J_velocity);
    }
    if (J_acceleration != nullptr) {
        M La = O, Lb = I;
        for (std::size_t j = K - 1; j >= 1; --j) {
            const M through_b = J_exp[j] * b0[j];
            const M ad1 = Group::ad(d[j] * b1[j]);
            const M La_total = La - Lb * ad1;  // a_(j+1) reads w_(j+1) through [w, x_j]
            J_d[j] =
                La_total * (Group::ad(wB[j]) * through_b + I * b1[j]) +
                Lb * (Group::ad(aB[j]) * through_b + I * b2[j] + Group::ad(vel[j + 1]) * b1[j]);
            La = La_total * B[j];
            Lb = Lb * B[j];
        }
        to_point_blocks<M, K>(J_d, J_self, J_previous, O, *J_acceleration);
    }
    if (J_jerk != nullptr) {
        M La = O, Lb = O, Lc = I;
        for (std::size_t j = K - 1; j >= 1; --j) {
            const M through_b = J_exp[j] * b0[j];
            const M ad1 = Group::ad(d[j] * b1[j]), ad2 = Group::ad(d[j] * b2[j]);
            const M ad_w = Group::ad(vel[j + 1]);
            const M Lb_total = Lb - Lc * ad1 * T(2);
            const M La_total = La - Lb_total * ad1 - Lc * (ad2 + ad1 * ad1);
            // d/d d_j of 2 [a, b' d] + [w, b'' d] + b'^2 [d, [w, d]] + b''' d, w and a held
            const M source =
                Group::ad(acc[j + 1]) * (b1[j] * T(2)) + ad_w * b2[j] +
                (Group::ad(d[j]) * ad_w - Group::ad(Group::bracket(vel[j + 1], d[j]))) *
                    (b1[j] * b1[j]) +
                I * b3[j];
            J_d[j] = La_total * (Group::ad(wB[j]) * through_b + I * b1[j]) +
                     Lb_total * (Group::ad(aB[j]) * through_b + I * b2[j] + ad_w * b1[j]) +
                     Lc * (Group::ad(yB[j]) * through_b + source);
            La = La_total * B[j];
            Lb = Lb_total * B[j];
            Lc = Lc * B[j];
        }
        to_point_blocks<M, K>(J_d, J_self, J_previous, O, *J_jerk);
    }
    return out;
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_DETAIL_LIE_BSPLINE_HPP_INCLUDED
