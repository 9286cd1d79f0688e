// Specification of rotation_matrix.hpp: 3x3 matrices acting on column vectors.
#include <cmath>
#include <limits>
#include <random>
#include <type_traits>

#include <Eigen/Core>
#include <quat/rotation_matrix.hpp>

#include "support/catch.hpp"
#include "support/same_bits.hpp"

namespace test_rotation_matrix {

using matrix = quat::rotation_matrix<double>;
using quat::vec3;

namespace {
constexpr matrix quarter_turn_z = matrix::from_columns({0, 1, 0}, {-1, 0, 0}, {0, 0, 1});  // x -> y
constexpr matrix quarter_turn_x = matrix::from_rows({1, 0, 0}, {0, 0, -1}, {0, 1, 0});     // y -> z
}  // namespace

static_assert(std::is_trivially_default_constructible_v<matrix>, "a plain struct");
static_assert(std::is_constructible_v<matrix, quat::rotation_matrix<float>> &&
                  !std::is_convertible_v<quat::rotation_matrix<float>, matrix>,
              "precisions convert explicitly only");
static_assert(std::is_trivially_copyable_v<matrix>);
static_assert(quarter_turn_z(1, 0) == 1 && quarter_turn_z(0, 1) == -1, "m(row, col)");
static_assert(quat::rotate(quarter_turn_z, vec3<double>{1, 0, 0}) == vec3<double>{0, 1, 0},
              "v' = M v");
static_assert(quat::rotate(quarter_turn_x, vec3<double>{0, 1, 0}) == vec3<double>{0, 0, 1});
static_assert(quat::transpose(quarter_turn_z) * quarter_turn_z == matrix::identity());
static_assert(quat::determinant(quarter_turn_x) == 1);
static_assert(quat::column(quarter_turn_z, 0) == vec3<double>{0, 1, 0});
static_assert(quat::row(quarter_turn_x, 1) == vec3<double>{0, 0, -1});

TEST_CASE("a * b applies b first", "[rotation_matrix]") {
    const vec3<double> v{1, 2, 3};
    CHECK(quat::rotate(quarter_turn_z * quarter_turn_x, v) ==
          quat::rotate(quarter_turn_z, quat::rotate(quarter_turn_x, v)));
    CHECK(quarter_turn_z * quarter_turn_x != quarter_turn_x * quarter_turn_z);
}

TEST_CASE("orthogonality_error measures distance from orthogonal and passes NaN through",
          "[rotation_matrix]") {
    CHECK(quat::orthogonality_error(quarter_turn_z) == 0);
    matrix skewed = quarter_turn_z;
    skewed(0, 0) = 0.1;
    CHECK(quat::orthogonality_error(skewed) == Approx(0.1));
    skewed(2, 2) = std::numeric_limits<double>::quiet_NaN();
    CHECK(std::isnan(quat::orthogonality_error(skewed)));
    matrix mirror = matrix::identity();
    mirror(2, 2) = -1;
    CHECK(quat::orthogonality_error(mirror) == 0);
    CHECK(quat::determinant(mirror) == -1);
}

TEST_CASE("m * v is rotate(m, v), bit for bit, and Eigen's Matrix3 * Vector3",
          "[rotation_matrix][first-use]") {
    static_assert(quarter_turn_z * vec3<double>{1, 0, 0} == vec3<double>{0, 1, 0}, "v' = M v");
    std::mt19937_64 engine(20190501);
    std::normal_distribution<double> gauss;
    for (int n = 0; n < 2000; ++n) {
        // Any 3x3 matrix: * is the matrix-vector product, rotation or not.
        matrix m{};
        Eigen::Matrix3d e;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) e(i, j) = m(i, j) = gauss(engine);
        const vec3<double> v{gauss(engine), gauss(engine), gauss(engine)};
        const vec3<double> product = m * v, long_form = quat::rotate(m, v);
        CHECK(quat::test::same_bits(product, long_form));
        const Eigen::Vector3d reference = e * Eigen::Vector3d(v.x, v.y, v.z);
        const double bound = 4 * std::numeric_limits<double>::epsilon() * 10;
        CHECK(std::abs(product.x - reference.x()) <= bound);
        CHECK(std::abs(product.y - reference.y()) <= bound);
        CHECK(std::abs(product.z - reference.z()) <= bound);
    }
}

}  // namespace test_rotation_matrix
