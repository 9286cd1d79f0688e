// Specification of nearest_rotation.hpp, against Eigen's SVD as the independent reference.
#include <cmath>
#include <limits>

#include <Eigen/Dense>
#include <quat/nearest_rotation.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

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
