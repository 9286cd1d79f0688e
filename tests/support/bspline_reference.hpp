// The textbook evaluation of a cumulative B-spline on SO(3) or SE(3) that
// tests/test_so3_bspline_derivatives.cpp and tests/test_se3_bspline.cpp hold the O(K) recurrences
// to: the value as the direct product
//     X = P_0 exp(b~_1 d_1) ... exp(b~_(K-1) d_(K-1)),
// its time derivatives by the product rule over every factor (O(K^n) products for the n-th
// derivative, against the library's O(K)), and the body velocity and its derivatives from
//     Omega = X^-1 X',  Omega' = X^-1 X'' - Omega^2,  Omega'' = X^-1 X''' - Omega^3 - 2 Omega Omega' - Omega' Omega,
// in the algebra of quaternions (Omega = (0, omega / 2)) or dual quaternions (Omega = (0, omega / 2)
// + eps (0, rho / 2)). Each factor A(t) = exp(b(t) Xi) has A' = b' Xi A, A'' = (b'' Xi + b'^2 Xi^2) A
// and A''' = (b''' Xi + 3 b' b'' Xi^2 + b'^3 Xi^3) A (Xi commutes with A).
#pragma once

#include <array>
#include <cstddef>

#include <quat/lie/se3.hpp>
#include <quat/lie/so3.hpp>
#include <quat/trajectory/detail/uniform_basis.hpp>

namespace quat::test {

template <class T>
quaternion<T> algebra_add(const quaternion<T>& a, const quaternion<T>& b) {
    return a + b;
}
template <class T>
dual_quaternion<T> algebra_add(const dual_quaternion<T>& a, const dual_quaternion<T>& b) {
    return {a.real + b.real, a.dual + b.dual};
}
template <class T>
quaternion<T> algebra_zero(const quaternion<T>&) {
    return {T(0), T(0), T(0), T(0)};
}
template <class T>
dual_quaternion<T> algebra_zero(const dual_quaternion<T>&) {
    return {{T(0), T(0), T(0), T(0)}, {T(0), T(0), T(0), T(0)}};
}

/// Group-specific pieces: the increment and exp, Xi = the algebra element of a tangent, and the
/// tangent of an algebra element 2 Omega.
template <class T>
struct so3_reference {
    using element = quaternion<T>;
    using tangent = vec3<T>;
    static tangent minus(const element& y, const element& x) { return so3::minus(y, x); }
    static element exp(const tangent& v) { return so3::exp(v); }
    static element xi(const tangent& v) { return {T(0), v.x * T(0.5), v.y * T(0.5), v.z * T(0.5)}; }
    static tangent of(const element& a) { return {a.x * T(2), a.y * T(2), a.z * T(2)}; }
    static element inverse(const element& a) { return conjugate(a); }
    static tangent scaled(const tangent& v, T s) { return v * s; }
};
template <class T>
struct se3_reference {
    using element = dual_quaternion<T>;
    using tangent = se3::twist<T>;
    static tangent minus(const element& y, const element& x) { return se3::minus(y, x); }
    static element exp(const tangent& v) { return se3::exp(v); }
    static element xi(const tangent& v) {
        const vec3<T> w = v.angular * T(0.5), r = v.linear * T(0.5);
        return {{T(0), w.x, w.y, w.z}, {T(0), r.x, r.y, r.z}};
    }
    static tangent of(const element& a) {
        return {{a.dual.x * T(2), a.dual.y * T(2), a.dual.z * T(2)},
                {a.real.x * T(2), a.real.y * T(2), a.real.z * T(2)}};
    }
    static element inverse(const element& a) { return {conjugate(a.real), conjugate(a.dual)}; }
    static tangent scaled(const tangent& v, T s) { return v * s; }
};

template <class Tangent, class Element>
struct reference_sample {
    Element value;
    Tangent velocity, acceleration, jerk;
};

/// The product rule: the n-th derivative of left f_from ... f_(count-1) (left constant) is the sum
/// over o = 0 .. n of C(n, o) times the n - o -th derivative of (left f_from^(o)) f_(from+1) ...
template <class T, class E, std::size_t N>
E product_derivative(const std::array<std::array<E, 4>, N>& factors, std::size_t from, int n,
                     const E& left) {
    if (from == N) return n == 0 ? left : algebra_zero(left);
    E sum = algebra_zero(left);
    for (int o = 0; o <= n; ++o) {
        const E term = product_derivative<T>(factors, from + 1, n - o,
                                             left * factors[from][static_cast<std::size_t>(o)]);
        sum = algebra_add(sum, term * T(static_cast<double>(detail::binomial_of(n, o))));
    }
    return sum;
}

/// The sample of the spline over the K points p at the cumulative weights w, the textbook way.
template <class Group, class T, std::size_t K>
reference_sample<typename Group::tangent, typename Group::element> textbook_bspline(
    const typename Group::element* p, const detail::cumulative_weights<T, K>& w) {
    using E = typename Group::element;
    constexpr std::size_t F = K - 1;
    std::array<std::array<E, 4>, F> factors{};
    for (std::size_t j = 1; j < K; ++j) {
        const auto d = Group::minus(p[j], p[j - 1]);
        const E a = Group::exp(Group::scaled(d, w.b[0][j]));
        const E xi = Group::xi(d), xi2 = xi * xi, xi3 = xi2 * xi;
        const T b1 = w.b[1][j], b2 = w.b[2][j], b3 = w.b[3][j];
        auto& f = factors[j - 1];
        f[0] = a;
        f[1] = xi * a * b1;
        f[2] = algebra_add(xi * b2, xi2 * (b1 * b1)) * a;
        f[3] = algebra_add(algebra_add(xi * b3, xi2 * (T(3) * b1 * b2)), xi3 * (b1 * b1 * b1)) * a;
    }
    std::array<E, 4> x{};
    for (int n = 0; n < 4; ++n)
        x[static_cast<std::size_t>(n)] = product_derivative<T>(factors, 0, n, p[0]);
    const E inv = Group::inverse(x[0]);
    const E omega = inv * x[1];
    const E omega_dot = algebra_add(inv * x[2], omega * omega * T(-1));
    E omega_ddot = inv * x[3];
    omega_ddot = algebra_add(omega_ddot, omega * omega * omega * T(-1));
    omega_ddot = algebra_add(omega_ddot, omega * omega_dot * T(-2));
    omega_ddot = algebra_add(omega_ddot, omega_dot * omega * T(-1));
    return {x[0], Group::of(omega), Group::of(omega_dot), Group::of(omega_ddot)};
}

}  // namespace quat::test
