// The counted cases behind `quat_bench --counts` and tests/test_counts.cpp: each function runs one
// operation of quat on quat::counted<double> and returns the operations it performed.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <quat/batch/rotations.hpp>
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

// ---- Rigid motions: x -> R x + t as a 4x4 matrix, a dual quaternion, or a (quaternion,
// translation) pair. ----

using H = quat::homogeneous_matrix<C>;
using DQ = quat::dual_quaternion<C>;

inline quat::vec3<C> translation() { return {c(1.5), c(-0.4), c(2.0)}; }
inline quat::vec3<C> other_translation() { return {c(-0.7), c(0.9), c(0.2)}; }

/// The natural 4x4 build: to_matrix(q) into the 3x3 block, t into the last column, last row
/// (0, 0, 0, 1).
inline H homogeneous_from(const quat::quaternion<C>& q, const quat::vec3<C>& t) {
    const quat::rotation_matrix<C> r = quat::to_matrix(q);
    return H{{{r(0, 0), r(0, 1), r(0, 2), t.x},
              {r(1, 0), r(1, 1), r(1, 2), t.y},
              {r(2, 0), r(2, 1), r(2, 2), t.z},
              {C(0), C(0), C(0), C(1)}}};
}
/// The full product M (x, y, z, 1), all four rows, as the thesis's homogeneous coordinates
/// (section 2.2, definition 3.1) write it, there with the 1 first (same count): 16
/// multiplications, 12 additions.
inline std::array<C, 4> full_product(const H& m, const quat::vec3<C>& p) {
    const C v[4] = {p.x, p.y, p.z, C(1)};
    std::array<C, 4> out{};
    for (int i = 0; i < 4; ++i)
        out[static_cast<std::size_t>(i)] =
            m(i, 0) * v[0] + m(i, 1) * v[1] + m(i, 2) * v[2] + m(i, 3) * v[3];
    return out;
}
/// A motion as the pair (q, t): x -> rotate(q, x) + t.
struct rigid_pair {
    quat::quaternion<C> q;
    quat::vec3<C> t;
};

// Build: from the unit quaternion and the translation.
inline quat::operation_counts rigid_build_matrix() {
    const auto q = unit_quaternion();
    const auto t = translation();
    return count([&] { (void)homogeneous_from(q, t); });
}
inline quat::operation_counts rigid_build_dual() {
    const auto q = unit_quaternion();
    const auto t = translation();
    return count([&] { (void)quat::to_dual_quaternion(q, t); });
}
inline quat::operation_counts rigid_build_pair() {
    const auto q = unit_quaternion();
    const auto t = translation();
    return count([&] { (void)rigid_pair{q, t}; });
}

// Move one point, the motion already built: the cost of each additional point.
inline quat::operation_counts rigid_point_matrix_full() {
    const H m = homogeneous_from(unit_quaternion(), translation());
    const auto p = point();
    return count([&] { (void)full_product(m, p); });
}
inline quat::operation_counts rigid_point_matrix() {
    const H m = homogeneous_from(unit_quaternion(), translation());
    const auto p = point();
    return count([&] { (void)quat::transform(m, p); });
}
inline quat::operation_counts rigid_point_dual() {
    const DQ dq = quat::to_dual_quaternion(unit_quaternion(), translation());
    const auto p = point();
    return count([&] { (void)quat::transform(dq, p); });
}
inline quat::operation_counts rigid_point_pair() {
    const rigid_pair m{unit_quaternion(), translation()};
    const auto p = point();
    return count([&] { (void)(quat::rotate(m.q, p) + m.t); });
}
/// Batch transform by a dual quaternion (batch/rigid_motions.hpp), per point (rounded down):
/// to_homogeneous once, then R p + t each.
inline quat::operation_counts rigid_batch_dual_per_point(std::size_t n) {
    const DQ dq = quat::to_dual_quaternion(unit_quaternion(), translation());
    const std::vector<quat::vec3<C>> in(n, point());
    std::vector<quat::vec3<C>> out(n);
    quat::operation_counts total = count([&] { quat::transform(dq, in, out); });
    const auto per = [n](std::int64_t x) { return x / static_cast<std::int64_t>(n); };
    return {per(total.add), per(total.mul), per(total.div), per(total.sqrt), per(total.trig)};
}

// Build, then move one point once (counted together).
inline quat::operation_counts rigid_once_matrix_full() {
    const auto q = unit_quaternion();
    const auto t = translation();
    const auto p = point();
    return count([&] { (void)full_product(homogeneous_from(q, t), p); });
}
inline quat::operation_counts rigid_once_matrix() {
    const auto q = unit_quaternion();
    const auto t = translation();
    const auto p = point();
    return count([&] { (void)quat::transform(homogeneous_from(q, t), p); });
}
inline quat::operation_counts rigid_once_dual() {
    const auto q = unit_quaternion();
    const auto t = translation();
    const auto p = point();
    return count([&] { (void)quat::transform(quat::to_dual_quaternion(q, t), p); });
}
inline quat::operation_counts rigid_once_pair() {
    const auto q = unit_quaternion();
    const auto t = translation();
    const auto p = point();
    return count([&] {
        const rigid_pair m{q, t};
        (void)(quat::rotate(m.q, p) + m.t);
    });
}

// Compose two motions (b first, then a).
inline quat::operation_counts rigid_compose_matrix_full() {
    const H a = homogeneous_from(unit_quaternion(), translation());
    const H b = homogeneous_from(other_quaternion(), other_translation());
    return count([&] { (void)(a * b); });
}
/// The product of two 4x4 rigid motions knowing their last rows are (0, 0, 0, 1): a 3x4 affine
/// product, R_a R_b and R_a t_b + t_a.
inline quat::operation_counts rigid_compose_affine() {
    const H a = homogeneous_from(unit_quaternion(), translation());
    const H b = homogeneous_from(other_quaternion(), other_translation());
    return count([&] {
        const quat::rotation_matrix<C> ra = quat::rotation_block(a);
        const quat::rotation_matrix<C> r = ra * quat::rotation_block(b);
        const quat::vec3<C> t = quat::rotate(ra, quat::translation_of(b)) + quat::translation_of(a);
        (void)H{{{r(0, 0), r(0, 1), r(0, 2), t.x},
                 {r(1, 0), r(1, 1), r(1, 2), t.y},
                 {r(2, 0), r(2, 1), r(2, 2), t.z},
                 {C(0), C(0), C(0), C(1)}}};
    });
}
inline quat::operation_counts rigid_compose_dual() {
    const DQ a = quat::to_dual_quaternion(unit_quaternion(), translation());
    const DQ b = quat::to_dual_quaternion(other_quaternion(), other_translation());
    return count([&] { (void)(a * b); });
}
inline quat::operation_counts rigid_compose_pair() {
    const rigid_pair a{unit_quaternion(), translation()};
    const rigid_pair b{other_quaternion(), other_translation()};
    return count([&] { (void)rigid_pair{a.q * b.q, quat::rotate(a.q, b.t) + a.t}; });
}
/// to_homogeneous(dq): what a composed dual quaternion costs to turn into R p + t form.
inline quat::operation_counts dual_to_homogeneous() {
    const DQ dq = quat::to_dual_quaternion(unit_quaternion(), translation());
    return count([&] { (void)quat::to_homogeneous(dq); });
}

}  // namespace bench::count_cases
