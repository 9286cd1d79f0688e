// Specification of matrix.hpp: small fixed-size matrices for Jacobians and covariances.
#include <random>
#include <type_traits>

#include <Eigen/Core>
#include <quat/matrix.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"

namespace test_matrix {

using quat::matrix;
using quat::matrix3;
using quat::vec3;

namespace {
constexpr matrix<double, 2, 3> two_by_three{{{1, 2, 3}, {4, 5, 6}}};
constexpr matrix<double, 3, 2> three_by_two{{{1, -1}, {0, 2}, {3, 0.5}}};

template <int R, int C>
matrix<double, R, C> random_matrix(std::mt19937_64& engine) {
    std::uniform_real_distribution<double> uniform(-2, 2);
    matrix<double, R, C> m{};
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j) m(i, j) = uniform(engine);
    return m;
}

template <int R, int C>
Eigen::Matrix<double, R, C> as_eigen(const matrix<double, R, C>& m) {
    Eigen::Matrix<double, R, C> out;
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j) out(i, j) = m(i, j);
    return out;
}
}  // namespace

static_assert(std::is_aggregate_v<matrix<double, 6, 6>> &&
                  std::is_trivially_default_constructible_v<matrix<double, 6, 6>>,
              "a plain aggregate: matrix<T, R, C> m; leaves it uninitialized, m{} is zero");
static_assert(two_by_three(0, 2) == 3 && two_by_three(1, 0) == 4, "m(row, col), rows first");
static_assert(quat::transpose(two_by_three)(2, 1) == 6);
static_assert(matrix3<double>::identity()(1, 1) == 1 && matrix3<double>::identity()(0, 1) == 0);
static_assert(matrix<double, 2, 3>::identity()(1, 1) == 1 &&
                  matrix<double, 2, 3>::identity()(1, 2) == 0,
              "identity() of a rectangular matrix: ones on the leading diagonal");
static_assert(matrix<double, 4, 4>::zero() == matrix<double, 4, 4>{});
static_assert((two_by_three * three_by_two)(0, 0) == 1 * 1 + 2 * 0 + 3 * 3, "row times column");
static_assert(two_by_three * matrix3<double>::identity() == two_by_three);
static_assert(quat::block<2, 2>(two_by_three, 0, 1) == matrix<double, 2, 2>{{{2, 3}, {5, 6}}});

TEST_CASE("products agree with Eigen's; sums, scalings and transposes work element by element",
          "[matrix]") {
    // Eigen may sum the products in another order or contract them into FMAs: equal to rounding.
    std::mt19937_64 engine(quat::test::seed);
    for (int trial = 0; trial < 100; ++trial) {
        const auto a = random_matrix<6, 3>(engine);
        const auto b = random_matrix<3, 6>(engine);
        const auto c = random_matrix<6, 6>(engine);
        const matrix<double, 6, 6> product = a * b;
        const Eigen::Matrix<double, 6, 6> expected = as_eigen(a) * as_eigen(b);
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) {
                CHECK(product(i, j) == Approx(expected(i, j)).epsilon(1e-15).margin(1e-15));
                CHECK((c + product)(i, j) == c(i, j) + product(i, j));
                CHECK((c - product)(i, j) == c(i, j) - product(i, j));
                CHECK((-c)(i, j) == -c(i, j));
                CHECK((c * 0.5)(i, j) == c(i, j) * 0.5);
                CHECK((2.0 * c)(i, j) == 2.0 * c(i, j));
                CHECK(quat::transpose(c)(i, j) == c(j, i));
            }
    }
}

TEST_CASE("a 3x3 matrix times a vec3 is the matrix product with a column", "[matrix]") {
    std::mt19937_64 engine(quat::test::seed);
    const auto m = random_matrix<3, 3>(engine);
    const vec3<double> v{0.5, -1.25, 2};
    const matrix<double, 3, 1> column{{{v.x}, {v.y}, {v.z}}};
    const vec3<double> mv = m * v;
    const matrix<double, 3, 1> expected = m * column;
    CHECK(mv.x == expected(0, 0));
    CHECK(mv.y == expected(1, 0));
    CHECK(mv.z == expected(2, 0));
}

TEST_CASE("blocks read and write the given rows and columns only", "[matrix]") {
    matrix<double, 6, 6> m = matrix<double, 6, 6>::zero();
    const matrix3<double> r{{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}}};
    quat::set_block(m, 0, 3, r);
    CHECK(quat::block<3, 3>(m, 0, 3) == r);
    CHECK(quat::block<3, 3>(m, 3, 0) == matrix3<double>::zero());
    CHECK(quat::block<3, 3>(m, 0, 0) == matrix3<double>::zero());
    CHECK(m(1, 5) == 6);
    CHECK(quat::block<1, 6>(m, 2, 0) == matrix<double, 1, 6>{{{0, 0, 0, 7, 8, 9}}});
}

TEST_CASE("+=, -=, to_matrix3 and to_rotation_matrix keep every value", "[matrix]") {
    matrix3<double> m = matrix3<double>::identity();
    m += matrix3<double>::identity();
    CHECK(m == matrix3<double>::identity() * 2.0);
    m -= matrix3<double>::identity();
    CHECK(m == matrix3<double>::identity());
    const quat::rotation_matrix<double> r{{{1, 2, 3}, {4, 5, 6}, {7, 8, 9}}};
    const matrix3<double> same = quat::to_matrix3(r);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) CHECK(same(i, j) == r(i, j));
    CHECK(same != matrix3<double>::identity());
    CHECK(quat::to_rotation_matrix(same) == r);
    static_assert(!std::is_convertible_v<matrix3<double>, quat::rotation_matrix<double>>);
    static_assert(!std::is_convertible_v<quat::rotation_matrix<double>, matrix3<double>>);
}

TEST_CASE("float and long double matrices instantiate", "[matrix]") {
    constexpr auto f = matrix<float, 2, 2>::identity() * 2.0f + matrix<float, 2, 2>::identity();
    static_assert(f(1, 1) == 3.0f);
    constexpr auto l = quat::transpose(matrix<long double, 1, 3>{{{1.0L, 2.0L, 3.0L}}});
    static_assert(l(2, 0) == 3.0L);
    CHECK(f(0, 1) == 0.0f);
}

}  // namespace test_matrix
