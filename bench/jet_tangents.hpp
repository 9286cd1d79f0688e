// Jacobians by automatic differentiation for quat_bench (bench_lie.cpp, bench_trajectory.cpp):
// ceres::Jet variables placed as right-tangent perturbations of quaternions and dual quaternions,
// and the Jets' derivatives read back into tangent Jacobians, the convention of lie/so3.hpp and
// lie/se3.hpp.
#pragma once

#include <ceres/jet.h>

#include <quat/lie/se3.hpp>
#include <quat/lie/so3.hpp>

namespace bench {

template <int N>
using jet = ceres::Jet<double, N>;

/// Jet variables first .. first + 2 at v.
template <int N>
quat::vec3<jet<N>> variables(const quat::vec3<double>& v, int first) {
    return {jet<N>(v.x, first), jet<N>(v.y, first + 1), jet<N>(v.z, first + 2)};
}
/// x (1, d/2): the first-order right plus of SO(3), d Jets at 0 from variable `first`.
template <int N>
quat::quaternion<jet<N>> first_order_plus(const quat::quaternion<double>& x, int first) {
    const quat::vec3<jet<N>> d = variables<N>({0, 0, 0}, first);
    return quat::quaternion<jet<N>>(x) *
           quat::quaternion<jet<N>>{jet<N>(1), d.x * 0.5, d.y * 0.5, d.z * 0.5};
}
/// x ((1, omega/2) + eps (0, rho/2)): SE(3)'s, rho from variable `first`, omega after it.
template <int N>
quat::dual_quaternion<jet<N>> first_order_plus(const quat::dual_quaternion<double>& x, int first) {
    const quat::vec3<jet<N>> rho = variables<N>({0, 0, 0}, first);
    const quat::vec3<jet<N>> omega = variables<N>({0, 0, 0}, first + 3);
    const quat::dual_quaternion<jet<N>> step{
        {jet<N>(1), omega.x * 0.5, omega.y * 0.5, omega.z * 0.5},
        {jet<N>(0), rho.x * 0.5, rho.y * 0.5, rho.z * 0.5}};
    return quat::dual_quaternion<jet<N>>(x) * step;
}
/// The derivatives of a unit quaternion of Jets read into the tangent: column i is
/// 2 vec(q^-1 dq / dd_i), the inverse of the plus-Jacobian.
template <int N>
quat::matrix<double, 3, N> tangent(const quat::quaternion<jet<N>>& q) {
    using quatd = quat::quaternion<double>;
    const quatd inverse{q.w.a, -q.x.a, -q.y.a, -q.z.a};
    quat::matrix<double, 3, N> m{};
    for (int i = 0; i < N; ++i) {
        const quatd d = inverse * quatd{q.w.v[i], q.x.v[i], q.y.v[i], q.z.v[i]};
        m(0, i) = 2 * d.x;
        m(1, i) = 2 * d.y;
        m(2, i) = 2 * d.z;
    }
    return m;
}
/// The same for a unit dual quaternion of Jets: X^-1 dX = (0, omega/2) + eps (0, rho/2).
template <int N>
quat::matrix<double, 6, N> tangent(const quat::dual_quaternion<jet<N>>& x) {
    using dq = quat::dual_quaternion<double>;
    const dq inverse{{x.real.w.a, -x.real.x.a, -x.real.y.a, -x.real.z.a},
                     {x.dual.w.a, -x.dual.x.a, -x.dual.y.a, -x.dual.z.a}};
    quat::matrix<double, 6, N> m{};
    for (int i = 0; i < N; ++i) {
        const dq d = inverse * dq{{x.real.w.v[i], x.real.x.v[i], x.real.y.v[i], x.real.z.v[i]},
                                  {x.dual.w.v[i], x.dual.x.v[i], x.dual.y.v[i], x.dual.z.v[i]}};
        const double column[6] = {d.dual.x, d.dual.y, d.dual.z, d.real.x, d.real.y, d.real.z};
        for (int r = 0; r < 6; ++r) m(r, i) = 2 * column[r];
    }
    return m;
}
/// The derivatives of Jets as a matrix, one row per output.
template <int N, int R>
quat::matrix<double, R, N> partials(const jet<N> (&outputs)[R]) {
    quat::matrix<double, R, N> m{};
    for (int r = 0; r < R; ++r)
        for (int i = 0; i < N; ++i) m(r, i) = outputs[r].v[i];
    return m;
}
/// The derivatives of a vector of Jets, one row per component.
template <int N>
quat::matrix<double, 3, N> partials(const quat::vec3<jet<N>>& v) {
    const jet<N> outputs[3] = {v.x, v.y, v.z};
    return partials(outputs);
}
/// The derivatives of a twist of Jets, linear rows first.
template <int N>
quat::matrix<double, 6, N> partials(const quat::se3::twist<jet<N>>& t) {
    const jet<N> outputs[6] = {t.linear.x,  t.linear.y,  t.linear.z,
                               t.angular.x, t.angular.y, t.angular.z};
    return partials(outputs);
}

}  // namespace bench
