// The counted cases behind `quat_bench --counts` and tests/test_counts.cpp: each function runs one
// operation of quat on quat::counted<double> and returns the operations it performed.
#pragma once

#include <vector>

#include <quat/batch.hpp>
#include <quat/quat.hpp>

#include "counted.hpp"

namespace bench::count_cases {

using C = quat::counted<double>;

inline C c(double v) { return C(v); }
inline quat::vec3<C> point() { return {c(0.3), c(-1.2), c(2.5)}; }
inline quat::quaternion<C> unit_quaternion() { return {c(0.5), c(0.5), c(-0.5), c(0.5)}; }
inline quat::quaternion<C> other_quaternion() { return {c(0.1), c(0.7), c(0.1), c(-0.7)}; }
inline quat::euler<C> euler_angles() { return quat::euler<C>{{c(0.4), c(-0.3), c(1.1)}}; }
inline quat::axis_angle<C> axis_and_angle() { return {{c(0.6), c(0.0), c(0.8)}, c(1.3)}; }

/// Counts the operations f performs (its inputs are built before counting starts).
template <class F>
quat::operation_counts count(F f) {
    quat::reset_counts();
    f();
    return quat::counts();
}

inline quat::operation_counts matrix_from_euler() {
    const auto e = euler_angles();
    const auto v = point();
    return count([&] { (void)quat::rotate(quat::to_matrix(e), v); });
}
inline quat::operation_counts quaternion_from_euler() {
    const auto e = euler_angles();
    const auto v = point();
    return count([&] { (void)quat::rotate(quat::to_quaternion(e), v); });
}
/// The thesis's q p q*, p = (0, v): two full Hamilton products.
inline quat::operation_counts quaternion_from_euler_naive() {
    const auto e = euler_angles();
    const auto v = point();
    return count([&] {
        const auto q = quat::to_quaternion(e);
        (void)(q * quat::quaternion<C>{C(0), v.x, v.y, v.z} * quat::conjugate(q));
    });
}
inline quat::operation_counts matrix_from_axis_angle() {
    const auto a = axis_and_angle();
    const auto v = point();
    return count([&] { (void)quat::rotate(quat::to_matrix(a), v); });
}
inline quat::operation_counts quaternion_from_axis_angle() {
    const auto a = axis_and_angle();
    const auto v = point();
    return count([&] { (void)quat::rotate(quat::to_quaternion(a), v); });
}
inline quat::operation_counts rotate_naive() {
    const auto q = unit_quaternion();
    const auto v = point();
    return count([&] {
        (void)(q * quat::quaternion<C>{C(0), v.x, v.y, v.z} * quat::conjugate(q));
    });
}
inline quat::operation_counts rotate_quaternion() {
    const auto q = unit_quaternion();
    const auto v = point();
    return count([&] { (void)quat::rotate(q, v); });
}
inline quat::operation_counts rotate_matrix() {
    const auto m = quat::to_matrix(unit_quaternion());
    const auto v = point();
    return count([&] { (void)quat::rotate(m, v); });
}
/// Batch rotation by a quaternion, per point (rounded down): to_matrix once, then M v each.
inline quat::operation_counts rotate_batch_per_point(std::size_t n) {
    const auto q = unit_quaternion();
    const std::vector<quat::vec3<C>> in(n, point());
    std::vector<quat::vec3<C>> out(n);
    quat::operation_counts total = count([&] { quat::rotate(q, in, out); });
    const auto per = [n](std::int64_t x) { return x / static_cast<std::int64_t>(n); };
    return {per(total.add), per(total.mul), per(total.div), per(total.sqrt), per(total.trig)};
}
inline quat::operation_counts compose_quaternions() {
    const auto a = unit_quaternion(), b = other_quaternion();
    return count([&] { (void)(a * b); });
}
inline quat::operation_counts compose_matrices() {
    const auto a = quat::to_matrix(unit_quaternion()), b = quat::to_matrix(other_quaternion());
    return count([&] { (void)(a * b); });
}
inline quat::operation_counts quaternion_to_matrix() {
    const auto q = unit_quaternion();
    return count([&] { (void)quat::to_matrix(q); });
}

}  // namespace bench::count_cases
