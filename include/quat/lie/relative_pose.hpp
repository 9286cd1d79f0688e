// The relative-pose error of a pose graph, the residual of an edge that measured the pose of b seen
// from a, in its two common forms, with Jacobians with respect to both poses:
//   so3xr3::relative_pose_error: SO(3) x R^3, the form of Ceres's pose_graph_3d example,
//       e = (R_a^T (p_b - p_a) - p_ab, 2 vec(q_ab (q_a^-1 q_b)^-1));
//   se3::relative_pose_error: SE(3), e = log(Z^-1 A^-1 B), a twist, linear part first.
// Both are templates over the scalar (ceres::Jet included) and take poses as unit dual quaternions.
// The Jacobians are lie/so3.hpp's right convention for both forms: J = d e(A exp(tau)) / d tau at
// tau = 0, tau a twist (rho, omega) of SE(3), the pose manifold's tangent (interop/ceres.hpp).
// Derivations and the chain to Ceres's ambient parameters: docs/lie-groups.md.
#ifndef QUAT_LIE_RELATIVE_POSE_HPP_INCLUDED
#define QUAT_LIE_RELATIVE_POSE_HPP_INCLUDED

#include "../config.hpp"
#include "../detail/math.hpp"
#include "../matrix.hpp"
#include "../quaternion.hpp"
#include "../rigid/dual_quaternion.hpp"
#include "../vec3.hpp"
#include "se3.hpp"
#include "so3.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
namespace detail {

/// so3xr3::relative_pose_error on rotations and translations given apart (interop/ceres.hpp reads
/// them so from a parameter block). With d = q_ab (q_a^-1 q_b)^-1 = (w, v) and u = R_a^T (p_b -
/// p_a): perturbing A by exp(rho, omega) moves p_a by R_a rho and turns R_a^T into exp(-omega)
/// R_a^T, so du = [u]x omega - rho, and d becomes d exp(omega), so d(2 vec d) = (w I + [v]x)
/// omega. Perturbing B moves p_b by R_b rho, du = R_a^T R_b rho, and turns d into q_ab exp(-omega)
/// q_ab^-1 d, so d(2 vec d) = -(w I - [v]x) R_ab omega.
template <class T>
[[nodiscard]] constexpr matrix<T, 6, 1> so3xr3_relative_pose_error(
    const quaternion<T>& q_a, const vec3<T>& p_a, const quaternion<T>& q_b, const vec3<T>& p_b,
    const quaternion<T>& q_ab, const vec3<T>& p_ab, matrix6<T>* J_e_a, matrix6<T>* J_e_b) noexcept {
    const quaternion<T> q_a_inverse = conjugate(q_a);
    const quaternion<T> estimated = q_a_inverse * q_b;
    const vec3<T> u = rotate(q_a_inverse, p_b - p_a);
    const quaternion<T> d = q_ab * conjugate(estimated);
    const vec3<T> v{d.x, d.y, d.z};
    const vec3<T> e_p = u - p_ab;
    matrix<T, 6, 1> e{};
    e(0, 0) = e_p.x;
    e(1, 0) = e_p.y;
    e(2, 0) = e_p.z;
    e(3, 0) = T(2) * v.x;
    e(4, 0) = T(2) * v.y;
    e(5, 0) = T(2) * v.z;
    if (J_e_a == nullptr && J_e_b == nullptr) return e;
    const matrix3<T> w_identity = d.w * matrix3<T>::identity(), v_hat = so3::hat(v);
    if (J_e_a != nullptr) {
        *J_e_a = matrix6<T>::zero();
        set_block(*J_e_a, 0, 0, -matrix3<T>::identity());
        set_block(*J_e_a, 0, 3, so3::hat(u));
        set_block(*J_e_a, 3, 3, w_identity + v_hat);
    }
    if (J_e_b != nullptr) {
        *J_e_b = matrix6<T>::zero();
        set_block(*J_e_b, 0, 0, so3::adjoint(estimated));
        set_block(*J_e_b, 3, 3, -((w_identity - v_hat) * so3::adjoint(q_ab)));
    }
    return e;
}

}  // namespace detail
}  // inline namespace isa_...

// so3xr3 holds the instruction-set key inside it, as so3 and se3 do.
namespace so3xr3 {
#include "../detail/isa_namespace.inc"

/// e = (R_a^T (p_b - p_a) - p_ab, 2 vec(q_ab (q_a^-1 q_b)^-1)), the relative-pose error of Ceres's
/// pose_graph_3d example: translation first, then twice the vector part of the rotation error
/// (about the rotation vector for small errors, its sign that of the quaternion product, not
/// canonicalized). a, b are the poses, measured the pose of b seen from a; *J_e_a, *J_e_b are the
/// Jacobians in the twist tangent of a and b (right perturbation). Precondition: unit inputs; a
/// NaN or infinite input gives NaN or infinite components, never a crash.
template <class T>
[[nodiscard]] constexpr matrix<T, 6, 1> relative_pose_error(
    const dual_quaternion<T>& a, const dual_quaternion<T>& b, const dual_quaternion<T>& measured,
    quat::detail::type_identity_t<matrix6<T>>* J_e_a = nullptr,
    quat::detail::type_identity_t<matrix6<T>>* J_e_b = nullptr) noexcept {
    return quat::detail::so3xr3_relative_pose_error(
        rotation_of(a), translation_of(a), rotation_of(b), translation_of(b), rotation_of(measured),
        translation_of(measured), J_e_a, J_e_b);
}

}  // inline namespace isa_...
}  // namespace so3xr3

namespace se3 {
#include "../detail/isa_namespace.inc"

/// e = log(Z^-1 A^-1 B) = minus(between(a, b), measured) as 6 numbers, linear part first: the
/// SE(3) relative-pose error, |omega| in [0, pi] (Z A^-1 B and its negation alike). *J_e_b =
/// Jr(e)^-1 and *J_e_a = -Jr(e)^-1 Ad(A^-1 B)^-1, in the twist tangent of a and b. Precondition:
/// unit inputs; a NaN or infinite input gives NaN or infinite components, never a crash.
template <class T>
[[nodiscard]] constexpr matrix<T, 6, 1> relative_pose_error(
    const dual_quaternion<T>& a, const dual_quaternion<T>& b, const dual_quaternion<T>& measured,
    quat::detail::type_identity_t<matrix6<T>>* J_e_a = nullptr,
    quat::detail::type_identity_t<matrix6<T>>* J_e_b = nullptr) noexcept {
    matrix6<T> J_d_a{}, J_e_d{};
    const dual_quaternion<T> d = between(a, b, J_e_a != nullptr ? &J_d_a : nullptr);
    const bool derive = J_e_a != nullptr || J_e_b != nullptr;
    const twist<T> e = minus(d, measured, derive ? &J_e_d : nullptr);
    if (J_e_a != nullptr) *J_e_a = J_e_d * J_d_a;
    if (J_e_b != nullptr) *J_e_b = J_e_d;  // between's J_d_b is the identity
    return to_vector(e);
}

}  // inline namespace isa_...
}  // namespace se3

}  // namespace quat

#endif  // QUAT_LIE_RELATIVE_POSE_HPP_INCLUDED
