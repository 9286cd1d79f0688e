// docs/thesis-notes.md: each place where the thesis (Kivi 2019) needs correcting, shown
// numerically: the thesis's form next to the correct one, and the difference between them.
#include <cmath>

#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_thesis_notes {

using quat::axis_angle;
using quat::quatd;
using quat::rotation_matrix;
using quat::test::max_difference;
using v3 = quat::vec3<double>;
using tol = quat::test::tolerance<double>;

namespace {

constexpr double pi = quat::numbers::pi;

/// Angle of the rotation that takes unit a to unit b.
double rotation_angle(const quatd& a, const quatd& b) {
    return quat::to_axis_angle(quat::conjugate(a) * b).angle;
}

/// The thesis's matrices (section 3.4), exactly as printed.
rotation_matrix<double> thesis_rx(double phi) {
    const double c = std::cos(phi), s = std::sin(phi);
    return {{{1, 0, 0}, {0, c, s}, {0, -s, c}}};
}
rotation_matrix<double> thesis_ry(double theta) {
    const double c = std::cos(theta), s = std::sin(theta);
    return {{{c, 0, -s}, {0, 1, 0}, {s, 0, c}}};
}
rotation_matrix<double> thesis_rz(double psi) {
    const double c = std::cos(psi), s = std::sin(psi);
    return {{{c, s, 0}, {-s, c, 0}, {0, 0, 1}}};
}

/// Octonions by the Cayley–Dickson construction on quat's quaternions: (a, b)(c, d) = (ac − d*b, da
/// + bc*).
struct octonion {
    quatd a, b;
};
octonion operator*(const octonion& p, const octonion& q) {
    return {p.a * q.a - quat::conjugate(q.b) * p.b, q.b * p.a + p.b * quat::conjugate(q.a)};
}
double distance(const octonion& p, const octonion& q) {
    return quat::norm(p.a - q.a) + quat::norm(p.b - q.b);
}

/// A double that counts the arithmetic done with it, for operation counts.
struct counted {
    double value;
    static inline long multiplications = 0, additions = 0;
    counted(double v = 0) : value(v) {}  // NOLINT: implicit, like a built-in scalar
};
counted operator+(counted a, counted b) { return ++counted::additions, counted(a.value + b.value); }
counted operator-(counted a, counted b) { return ++counted::additions, counted(a.value - b.value); }
counted operator*(counted a, counted b) {
    return ++counted::multiplications, counted(a.value * b.value);
}
counted operator-(counted a) { return counted(-a.value); }

}  // namespace

TEST_CASE(
    "1. half angle: the thesis's q = (cos a, sin a v) rotates by 2a; (cos(a/2), sin(a/2) v) by a",
    "[thesis]") {
    quat::test::random_rotations random;
    for (int n = 0; n < 200; ++n) {
        const v3 axis = random.unit_vector<double>();
        const double alpha = random.uniform<double>(0.05, pi / 2 - 0.05);
        const quatd thesis{std::cos(alpha), std::sin(alpha) * axis.x, std::sin(alpha) * axis.y,
                           std::sin(alpha) * axis.z};
        const quatd correct = quat::to_quaternion(axis_angle<double>{axis, alpha});
        CHECK(std::abs(rotation_angle(quatd::identity(), thesis) - 2 * alpha) <= tol::round_trip);
        CHECK(std::abs(rotation_angle(quatd::identity(), correct) - alpha) <= tol::round_trip);
    }
    // Concretely: 90 degrees about z should take x to y; the thesis's q takes it to -x.
    const quatd thesis{std::cos(pi / 2), 0, 0, std::sin(pi / 2)};
    CHECK(max_difference(quat::rotate(thesis, v3{1, 0, 0}), v3{-1, 0, 0}) <= tol::rotate);
    const quatd correct = quat::to_quaternion(axis_angle<double>{{0, 0, 1}, pi / 2});
    CHECK(max_difference(quat::rotate(correct, v3{1, 0, 0}), v3{0, 1, 0}) <= tol::rotate);
}

TEST_CASE("2. inverse: q*/|q| is not the inverse of a non-unit q; q*/|q|^2 is", "[thesis]") {
    const quatd q{1, 2, 3, 4};  // |q|^2 = 30
    const quatd thesis = quat::conjugate(q) / quat::norm(q);
    const quatd product = q * thesis;  // = |q| = sqrt(30), not 1
    CHECK(std::abs(product.w - std::sqrt(30.0)) <= tol::product * 30);
    CHECK(max_difference(q * quat::inverse(q), quatd::identity()) <= tol::product);
    CHECK(max_difference(quat::inverse(q) * q, quatd::identity()) <= tol::product);
    // For unit quaternions the two agree, which hides the slip.
    const quatd unit = quat::normalize(q);
    CHECK(max_difference(quat::conjugate(unit) / quat::norm(unit), quat::inverse(unit)) <=
          tol::product);
}

TEST_CASE("3a. direction: q p q^-1 turns counter-clockwise seen from the axis tip, not clockwise",
          "[thesis]") {
    // Looking down from +z, counter-clockwise takes x toward y.
    const quatd q = quat::to_quaternion(axis_angle<double>{{0, 0, 1}, 0.3});
    const v3 p = quat::rotate(q, v3{1, 0, 0});
    CHECK(p.y > 0);
    CHECK(std::abs(std::atan2(p.y, p.x) - 0.3) <= tol::round_trip);
}

TEST_CASE("3b. the printed R_x, R_y, R_z are passive: thesis R_x(phi) = our R_x(-phi) = R_x(phi)^T",
          "[thesis]") {
    for (double angle = -3.0; angle <= 3.0; angle += 0.25) {
        for (int axis = 0; axis < 3; ++axis) {
            const v3 e{axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0};
            const rotation_matrix<double> thesis = axis == 0   ? thesis_rx(angle)
                                                   : axis == 1 ? thesis_ry(angle)
                                                               : thesis_rz(angle);
            const rotation_matrix<double> active = quat::to_matrix(axis_angle<double>{e, angle});
            CHECK(max_difference(thesis, quat::to_matrix(axis_angle<double>{e, -angle})) <=
                  tol::conversion);
            CHECK(max_difference(thesis, quat::transpose(active)) <= tol::conversion);
        }
    }
    // Applied as R p, the thesis's R_x(90 deg) takes y to -z: a clockwise turn, opposite to q p
    // q^-1.
    const v3 turned = quat::rotate(thesis_rx(pi / 2), v3{0, 1, 0});
    CHECK(max_difference(turned, v3{0, 0, -1}) <= tol::rotate);
    const quatd q = quat::to_quaternion(axis_angle<double>{{1, 0, 0}, pi / 2});
    CHECK(max_difference(quat::rotate(q, v3{0, 1, 0}), v3{0, 0, 1}) <= tol::rotate);
}

TEST_CASE(
    "3c. the thesis's R = Rz Ry Rx of passive matrices is to_matrix(euler{-psi, -theta, -phi})",
    "[thesis]") {
    quat::test::random_rotations random;
    for (int n = 0; n < 200; ++n) {
        const double phi = random.uniform<double>(-pi, pi),
                     theta = random.uniform<double>(-1.5, 1.5),
                     psi = random.uniform<double>(-pi, pi);
        const rotation_matrix<double> thesis = thesis_rz(psi) * thesis_ry(theta) * thesis_rx(phi);
        CHECK(max_difference(thesis, quat::to_matrix(quat::euler<double>{{-psi, -theta, -phi}})) <=
              tol::conversion);
        CHECK(max_difference(
                  thesis, quat::transpose(quat::to_matrix(quat::euler<double, quat::sequence::xyz>{
                              {phi, theta, psi}}))) <= tol::conversion);
        // and it is not the active yaw-pitch-roll matrix with the same angles.
        CHECK(max_difference(thesis, quat::to_matrix(quat::euler<double>{{psi, theta, phi}})) >
              1e-3);
    }
}

TEST_CASE("4. division algebras: quaternions are associative, octonions are not", "[thesis]") {
    quat::test::random_rotations random;
    double worst_quaternion = 0, smallest_octonion = 1e9;
    for (int n = 0; n < 200; ++n) {
        const quatd a = random.unit_quaternion<double>(), b = random.unit_quaternion<double>(),
                    c = random.unit_quaternion<double>(), d = random.unit_quaternion<double>(),
                    e = random.unit_quaternion<double>(), f = random.unit_quaternion<double>();
        worst_quaternion = std::max(worst_quaternion, quat::norm((a * b) * c - a * (b * c)));
        const octonion x{a, b}, y{c, d}, z{e, f};
        smallest_octonion = std::min(smallest_octonion, distance((x * y) * z, x * (y * z)));
    }
    CHECK(worst_quaternion <= tol::product * 4);
    CHECK(smallest_octonion > 1e-3);
}

TEST_CASE("5. cost: rotate(q, v) needs fewer operations than q (0, v) q*", "[thesis]") {
    const quat::quaternion<counted> q{0.5, 0.5, 0.5, 0.5};
    const quat::vec3<counted> v{1.0, 2.0, 3.0};

    counted::multiplications = counted::additions = 0;
    const quat::vec3<counted> fast = quat::rotate(q, v);
    const long fast_mul = counted::multiplications, fast_add = counted::additions;

    counted::multiplications = counted::additions = 0;
    const quat::quaternion<counted> naive =
        q * quat::quaternion<counted>{0.0, v.x, v.y, v.z} * quat::conjugate(q);
    const long naive_mul = counted::multiplications, naive_add = counted::additions;

    INFO("rotate(q, v): " << fast_mul << " multiplications, " << fast_add
                          << " additions; q (0, v) q*: " << naive_mul << " multiplications, "
                          << naive_add << " additions");
    CHECK(std::abs(fast.x.value - naive.x.value) + std::abs(fast.y.value - naive.y.value) +
              std::abs(fast.z.value - naive.z.value) <=
          tol::rotate * 10);
    // Two general Hamilton products: 2 x (16 multiplications, 12 additions).
    CHECK(naive_mul == 32);
    CHECK(naive_add == 24);
    // Measured with this counting scalar: 25 multiplications and 23 additions (M v, M from q with
    // s = 2 (2 - |q|^2); v + w t + u x t would take 18 and 12 but keeps |v| only to 5.4 eps).
    CHECK(fast_mul <= 25);
    CHECK(fast_add <= 23);
}

TEST_CASE("6. homogeneous first: the thesis's 4x4 matrices are quat's with coordinates rotated",
          "[thesis]") {
    quat::test::random_rotations random;
    for (int i = 0; i < 100; ++i) {
        const auto motion =
            quat::to_dual_quaternion(random.unit_quaternion<double>(), random.vector<double>(2.0));
        const quat::homogeneous_matrix<double> m = quat::to_homogeneous(motion);
        // The thesis's layout (definitions 2.12-2.14): coordinate 0 is the homogeneous one, so
        // thesis(i, j) = m(i - 1, j - 1) with indices taken mod 4: first row (1, 0, 0, 0), first
        // column (1, t).
        double thesis[4][4];
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) thesis[r][c] = m((r + 3) % 4, (c + 3) % 4);
        CHECK(thesis[0][0] == 1);
        CHECK(thesis[0][1] == 0);
        CHECK(thesis[1][0] == m(0, 3));
        // R(M R^(u)): u^ = <1, u>, then divide by the first component (definitions 2.12, 2.14,
        // 3.1).
        const v3 u = random.vector<double>(1.0);
        const double hat[4] = {1, u.x, u.y, u.z};
        double image[4] = {0, 0, 0, 0};
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) image[r] += thesis[r][c] * hat[c];
        const v3 projected{image[1] / image[0], image[2] / image[0], image[3] / image[0]};
        CHECK(max_difference(projected, quat::transform(m, u)) <= 4 * tol::rotate);
        CHECK(max_difference(projected, quat::transform(motion, u)) <= 8 * tol::rotate);
    }
}

}  // namespace test_thesis_notes
