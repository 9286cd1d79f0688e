// Specification of fitting/nearest_rotation.hpp, against Eigen's SVD as the independent reference.
#include <cmath>
#include <limits>

#include <Eigen/Dense>
#include <quat/fitting/nearest_rotation.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_nearest_rotation {

using matrix = quat::rotation_matrix<double>;
using quat::test::max_difference;

namespace {

// The nearest proper rotation U diag(1, 1, det(U V^T)) V^T from the SVD m = U S V^T.
matrix reference(const matrix& m) {
    Eigen::Matrix3d e;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) e(i, j) = m(i, j);
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(e, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Vector3d d(1, 1, (svd.matrixU() * svd.matrixV().transpose()).determinant());
    const Eigen::Matrix3d r = svd.matrixU() * d.asDiagonal() * svd.matrixV().transpose();
    matrix out{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out(i, j) = r(i, j);
    return out;
}

}  // namespace

TEST_CASE("a rotation is its own nearest rotation", "[nearest_rotation]") {
    quat::test::random_rotations random;
    for (int n = 0; n < 500; ++n) {
        const matrix r = quat::to_matrix(random.unit_quaternion<double>());
        CHECK(max_difference(quat::nearest_rotation(r), r) <= 16 * quat::test::eps<double>);
    }
}

TEST_CASE("perturbed and scaled matrices map to the SVD's nearest rotation", "[nearest_rotation]") {
    quat::test::random_rotations random;
    for (int n = 0; n < 2000; ++n) {
        matrix m = quat::to_matrix(random.unit_quaternion<double>());
        const double size = n < 1000 ? 0.1 : 1.0;  // small noise, then arbitrary matrices
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                m(i, j) =
                    random.uniform<double>(0.5, 2) * m(i, j) + size * random.uniform<double>(-1, 1);
        const matrix r = quat::nearest_rotation(m);
        CAPTURE(n);
        CHECK(quat::orthogonality_error(r) <= 16 * quat::test::eps<double>);
        CHECK(quat::determinant(r) == Approx(1));
        CHECK(max_difference(r, reference(m)) <= 1e-9);
    }
}

TEST_CASE("det <= 0: still the nearest proper rotation; ties and bad input are reported",
          "[nearest_rotation]") {
    matrix mirror = matrix::from_rows({1, 0, 0}, {0, 2, 0}, {0, 0, -3});
    const matrix r = quat::nearest_rotation(mirror);
    CHECK(quat::determinant(r) == Approx(1));
    CHECK(max_difference(r, reference(mirror)) <= 1e-12);
    const matrix minus_identity = matrix::from_rows({-1, 0, 0}, {0, -1, 0}, {0, 0, -1});
    CHECK_FALSE(
        quat::try_nearest_rotation(minus_identity).has_value());  // every half turn is nearest
    CHECK(quat::orthogonality_error(quat::nearest_rotation(minus_identity)) <=
          8 * quat::test::eps<double>);
    matrix broken = matrix::identity();
    broken(1, 2) = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(quat::try_nearest_rotation(broken).has_value());
    CHECK(quat::try_nearest_rotation(mirror).has_value());
    const matrix zero{};
    CHECK_FALSE(quat::try_nearest_rotation(zero).has_value());
}

TEMPLATE_TEST_CASE("FOAM is used only where the answer is well separated, and is then exact",
                   "[nearest_rotation]", float, double) {
    // m = U diag(s0, s1, s2) V^T with rotations U, V, in long double: the nearest rotation is
    // U V^T and Horn's eigen-gap is 2 (s1 + s2) / max |m(i, j)|. FOAM's bound must never exceed
    // that gap, and where it reaches separated_gap() (FOAM's answer is used) the rotation must be
    // as good as the eigenvector's: measured at most 3.6 eps over noisy point sets.
    using T = TestType;
    using quat::quaternion;
    quat::test::random_rotations random;
    const long double values[][3] = {
        {1, 1, 1},    {1, 1, -1},    {1, 1, 0}, {1, 0, 0},     {1, 0.5L, -0.5L}, {1, 1e-3L, 1e-3L},
        {1, 0.2L, 0}, {1, 1, -0.9L}, {3, 2, 1}, {1, 1e-9L, 0}, {0, 0, 0},        {2, 2, 2}};
    int used = 0;
    for (int n = 0; n < 4000; ++n) {
        long double s[3] = {};
        if (n < 12 * 20) {
            for (int k = 0; k < 3; ++k) s[k] = values[n % 12][k];
        } else {
            s[0] = 1;
            s[1] = random.uniform<long double>(0, 1);
            s[2] = random.uniform<long double>(-1, 1) * s[1];
        }
        const quaternion<long double> u = random.unit_quaternion<long double>(),
                                      v = random.unit_quaternion<long double>();
        const quat::rotation_matrix<long double> mu = quat::to_matrix(u), mv = quat::to_matrix(v);
        quat::rotation_matrix<T> m{};
        long double largest = 0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                long double e = 0;
                for (int k = 0; k < 3; ++k) e += mu(i, k) * s[k] * mv(j, k);
                m(i, j) = T(e);
                largest = std::max(largest, std::fabs(e));
            }
        if (largest == 0) largest = 1;
        const quat::detail::horn_solution<T> fast =
            quat::detail::foam(quat::detail::unit_scaled(m));
        CAPTURE(n, double(s[0]), double(s[1]), double(s[2]));
        CHECK(double(fast.eigenvalue_gap) <= double(2 * (s[1] + s[2]) / largest) * 1.001 + 1e-6);
        if (fast.eigenvalue_gap >= quat::detail::separated_gap<T>()) {
            ++used;
            const quaternion<long double> truth = u * quat::conjugate(v);
            const quaternion<long double> q{fast.rotation.w, fast.rotation.x, fast.rotation.y,
                                            fast.rotation.z};
            CHECK(double(quat::angle_between(q, truth)) <= 8 * double(quat::test::eps<T>));
        }
    }
    CHECK(used > 2000);
}

}  // namespace test_nearest_rotation
