// Specification of rigid/homogeneous_matrix.hpp: 4x4 rigid motions on column vectors (x, y, z, 1),
// their products, and conversions to and from dual quaternions, against long double matrices and
// GLM.
#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/Geometry>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <quat/interop/glm.hpp>
#include <quat/rigid/homogeneous_matrix.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/rigid_reference.hpp"
#include "support/same_bits.hpp"
#include "support/tolerance.hpp"

namespace test_homogeneous_matrix {

using quat::dual_quaternion;
using quat::homogeneous_matrix;
using quat::quaternion;
using quat::vec3;
using quat::test::eps;
using quat::test::max_difference;

namespace {

using quat::test::same_bits;

}  // namespace

TEST_CASE("homogeneous_matrix is row-major, m(row, col), with the translation in column 3",
          "[homogeneous_matrix]") {
    homogeneous_matrix<double> m = homogeneous_matrix<double>::identity();
    m(0, 3) = 4;
    m(1, 3) = 5;
    m(2, 3) = 6;
    CHECK(m.elements[0][3] == 4);
    CHECK(quat::translation_of(m) == vec3<double>{4, 5, 6});
    CHECK(quat::transform(m, vec3<double>{1, 2, 3}) == vec3<double>{5, 7, 9});
    CHECK(quat::transform_vector(m, vec3<double>{1, 2, 3}) == vec3<double>{1, 2, 3});
    const homogeneous_matrix<float> f(m);
    CHECK(f(2, 3) == 6.0f);
    CHECK(f != homogeneous_matrix<float>::identity());
}

TEMPLATE_TEST_CASE("to_homogeneous and to_dual_quaternion are inverse conversions",
                   "[homogeneous_matrix]", float, double) {
    quat::test::random_rotations random;
    for (int i = 0; i < 300; ++i) {
        const auto dq = random.rigid_motion<TestType>();
        const homogeneous_matrix<TestType> m = quat::to_homogeneous(dq);
        CHECK(quat::test::max_difference(quat::test::reference_matrix(m),
                                         quat::test::reference_matrix(dq)) <= 16 * eps<TestType>);
        const vec3<TestType> p = random.vector<TestType>(1.0);
        CHECK(max_difference(quat::transform(m, p), quat::transform(dq, p)) <= 16 * eps<TestType>);
        const auto back = quat::to_dual_quaternion(m);
        CHECK(back.real.w >= 0);
        const auto same_sign = dq.real.w < 0 ? -dq : dq;
        CHECK(max_difference(back.real, same_sign.real) <= 8 * eps<TestType>);
        CHECK(max_difference(back.dual, same_sign.dual) <= 16 * eps<TestType>);
    }
}

TEMPLATE_TEST_CASE("the matrix product composes like the dual quaternion product",
                   "[homogeneous_matrix]", float, double) {
    quat::test::random_rotations random;
    for (int i = 0; i < 200; ++i) {
        const auto a = quat::to_homogeneous(random.rigid_motion<TestType>());
        const auto b = quat::to_homogeneous(random.rigid_motion<TestType>());
        const quat::test::matrix4 reference =
            quat::test::reference_matrix(a) * quat::test::reference_matrix(b);
        CHECK(quat::test::max_difference(quat::test::reference_matrix(a * b), reference) <=
              16 * eps<TestType>);
        auto c = a;
        c *= b;
        CHECK(c == a * b);
    }
}

TEST_CASE("half turns convert exactly", "[homogeneous_matrix]") {
    for (const quat::quatd q :
         {quat::quatd{0, 1, 0, 0}, quat::quatd{0, 0, 1, 0}, quat::quatd{0, 0, 0, 1}}) {
        const auto dq = quat::to_dual_quaternion(q, vec3<double>{1, 2, 3});
        const auto m = quat::to_homogeneous(dq);
        const auto back = quat::to_dual_quaternion(m);
        CHECK(back.real == q);
        CHECK(quat::translation_of(back) == vec3<double>{1, 2, 3});
    }
}

TEST_CASE("try_to_dual_quaternion rejects matrices that are not rigid", "[homogeneous_matrix]") {
    const auto rigid = quat::to_homogeneous(
        quat::to_dual_quaternion(quat::rotation_z(0.5), vec3<double>{1, 2, 3}));
    REQUIRE(quat::try_to_dual_quaternion(rigid));
    auto projective = rigid;
    projective(3, 0) = 0.1;
    CHECK_FALSE(quat::try_to_dual_quaternion(projective));
    auto scaled_w = rigid;
    scaled_w(3, 3) = 2;
    CHECK_FALSE(quat::try_to_dual_quaternion(scaled_w));
    auto reflection = rigid;
    for (int j = 0; j < 3; ++j) reflection(2, j) = -reflection(2, j);
    CHECK_FALSE(quat::try_to_dual_quaternion(reflection));
    auto sheared = rigid;
    sheared(0, 1) += 1e-3;
    CHECK_FALSE(quat::try_to_dual_quaternion(sheared));
    CHECK(quat::try_to_dual_quaternion(sheared, 1e-2));  // a looser tolerance accepts it
    auto bad = rigid;
    bad(1, 3) = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(quat::try_to_dual_quaternion(bad));
    bad(1, 3) = std::numeric_limits<double>::infinity();
    CHECK_FALSE(quat::try_to_dual_quaternion(bad));
}

TEST_CASE("homogeneous matrices agree with glm::mat4", "[homogeneous_matrix][glm]") {
    quat::test::random_rotations random;
    for (int i = 0; i < 100; ++i) {
        const quaternion<double> q = random.unit_quaternion<double>();
        const vec3<double> t = random.vector<double>(2.0);
        const vec3<double> p = random.vector<double>(1.0);
        const auto m = quat::to_homogeneous(quat::to_dual_quaternion(q, t));
        glm::dmat4 theirs = glm::mat4_cast(quat::to_glm(q));
        theirs[3] = glm::dvec4(t.x, t.y, t.z, 1);
        const glm::dvec4 moved = theirs * glm::dvec4(p.x, p.y, p.z, 1);
        CHECK(max_difference(quat::transform(m, p), vec3<double>{moved.x, moved.y, moved.z}) <=
              16 * eps<double>);
        CHECK(quat::from_glm(quat::to_glm(m)) == m);
        const homogeneous_matrix<double> from_theirs = quat::from_glm(theirs);
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                CHECK(std::abs(from_theirs(r, c) - m(r, c)) <= 8 * eps<double>);
    }
}

TEST_CASE("homogeneous matrix operations are constexpr", "[homogeneous_matrix][constexpr]") {
    constexpr auto m = quat::to_homogeneous(
        quat::to_dual_quaternion(quat::quatd{0, 0, 0, 1}, vec3<double>{1, 0, 0}));
    constexpr auto product = m * m;
    static_assert(product(0, 0) == 1 && product(0, 3) == 0);
    constexpr auto back = quat::to_dual_quaternion(m);
    STATIC_REQUIRE(back.real.z == 1);
}

TEMPLATE_TEST_CASE("h * p is transform(h, p), bit for bit, and glm::mat4 * vec4(p, 1)",
                   "[homogeneous_matrix][first-use]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int i = 0; i < 2000; ++i) {
        const homogeneous_matrix<T> h = quat::to_homogeneous(random.rigid_motion<T>());
        const vec3<T> p = random.vector<T>(3.0);
        // A point transform: rotated, then translated (transform_vector turns a direction only).
        CHECK(same_bits(h * p, quat::transform(h, p)));
        const glm::vec<4, T> moved = quat::to_glm(h) * glm::vec<4, T>(p.x, p.y, p.z, 1);
        CHECK(max_difference(h * p, vec3<T>{moved.x, moved.y, moved.z}) <= 16 * eps<T>);
    }
}

TEMPLATE_TEST_CASE("to_homogeneous from a rotation, a translation or both copies them exactly",
                   "[homogeneous_matrix][first-use]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    const vec3<T> zero{T(0), T(0), T(0)};
    for (int i = 0; i < 1000; ++i) {
        const quaternion<T> q = random.unit_quaternion<T>();
        const quat::rotation_matrix<T> r = quat::to_matrix(q);
        const vec3<T> t = random.vector<T>(2.0);
        const homogeneous_matrix<T> h = quat::to_homogeneous(r, t);
        CHECK(same_bits(quat::rotation_block(h), r));
        CHECK(same_bits(quat::translation_of(h), t));
        CHECK((h(3, 0) == 0 && h(3, 1) == 0 && h(3, 2) == 0 && h(3, 3) == 1));
        CHECK(same_bits(quat::to_homogeneous(q, t), h));
        CHECK(same_bits(quat::to_homogeneous(q), quat::to_homogeneous(r, zero)));
        CHECK(same_bits(quat::to_homogeneous(r), quat::to_homogeneous(r, zero)));
        CHECK(same_bits(homogeneous_matrix<T>::from_translation(t),
                        quat::to_homogeneous(quat::rotation_matrix<T>::identity(), t)));
        // The dual quaternion route rounds the translation; the direct one does not.
        const homogeneous_matrix<T> via_dq = quat::to_homogeneous(quat::to_dual_quaternion(q, t));
        CHECK(quat::test::max_difference(quat::test::reference_matrix(h),
                                         quat::test::reference_matrix(via_dq)) <= 32 * eps<T>);
        // Translation after rotation, as the product of the two pure motions.
        CHECK(quat::test::max_difference(
                  quat::test::reference_matrix(homogeneous_matrix<T>::from_translation(t) *
                                               quat::to_homogeneous(q)),
                  quat::test::reference_matrix(h)) == 0);
    }
    static_assert(homogeneous_matrix<double>::from_translation({1, 2, 3}) * vec3<double>{1, 1, 1} ==
                  vec3<double>{2, 3, 4});
}

TEMPLATE_TEST_CASE("inverse of a rigid matrix is [R^T, -R^T t], as Eigen's Isometry3 inverse",
                   "[homogeneous_matrix][first-use]", float, double) {
    using T = TestType;
    using eigen_isometry = Eigen::Transform<T, 3, Eigen::Isometry>;
    quat::test::random_rotations random;
    for (int i = 0; i < 2000; ++i) {
        const homogeneous_matrix<T> h = quat::to_homogeneous(random.rigid_motion<T>());
        const homogeneous_matrix<T> inv = quat::inverse(h);
        const quat::rotation_matrix<T> r_transposed = quat::transpose(quat::rotation_block(h));
        CHECK(same_bits(
            inv, quat::to_homogeneous(r_transposed,
                                      -quat::rotate(r_transposed, quat::translation_of(h)))));
        // inverse(h) * h is the identity to rounding, and moves points back.
        CHECK(quat::test::max_difference(
                  quat::test::reference_matrix(inv * h),
                  quat::test::reference_matrix(homogeneous_matrix<T>::identity())) <= 16 * eps<T>);
        const vec3<T> p = random.vector<T>(1.0);
        CHECK(max_difference(inv * (h * p), p) <= 32 * eps<T>);
        // Eigen computes the same formula: Isometry3::inverse() is [R^T, -R^T t].
        eigen_isometry e = eigen_isometry::Identity();
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 4; ++col) e.matrix()(row, col) = h(row, col);
        const auto e_inv = e.inverse();
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 4; ++col)
                CHECK(std::abs(e_inv.matrix()(row, col) - inv(row, col)) <= 8 * eps<T>);
    }
    // A half turn about z and a shift: exact.
    constexpr auto h = quat::to_homogeneous(quat::quatd{0, 0, 0, 1}, vec3<double>{1, 2, 3});
    static_assert(quat::inverse(h) * (h * vec3<double>{5, -6, 7}) == vec3<double>{5, -6, 7});
}

TEST_CASE("inverse of a non-rigid matrix is not its inverse: the precondition is rigid",
          "[homogeneous_matrix][first-use]") {
    // Release builds apply [R^T, -R^T t] to whatever the blocks hold (debug builds stop at
    // QUAT_ASSERT, tests/contracts case homogeneous_inverse): a scale is not undone.
#ifdef NDEBUG
    homogeneous_matrix<double> scaled = homogeneous_matrix<double>::identity();
    scaled(0, 0) = 2;
    CHECK(quat::inverse(scaled)(0, 0) == 2);
#endif
    // NaN propagates.
    homogeneous_matrix<double> bad = homogeneous_matrix<double>::from_translation({1, 2, 3});
    bad(0, 3) = std::numeric_limits<double>::quiet_NaN();
    const homogeneous_matrix<double> inv = quat::inverse(bad);
    CHECK(std::isnan(inv(0, 3)));
    CHECK(inv(0, 0) == 1);
}

TEMPLATE_TEST_CASE("a translation with components up to max() reads back through a dual quaternion",
                   "[homogeneous_matrix][edge]", float, double) {
    using T = TestType;
    const T largest = std::numeric_limits<T>::max();
    // The dual part (t / 2) q never overflows, but 2 dual real* rounds within a few units of max()
    // and overflows if doubled before the product. Reference: the translation as given, exact.
    quat::test::random_rotations random;
    int rounded_past = 0;
    for (int n = 0; n < 200; ++n) {
        const quaternion<T> q = random.unit_quaternion<T>();
        const T sign = n % 2 == 0 ? T(1) : T(-1);
        const vec3<T> translations[] = {{sign * largest, T(0), T(0)},
                                        {T(1), sign * largest, T(-2)},
                                        {largest, -largest, sign * largest}};
        for (const vec3<T>& t : translations) {
            const homogeneous_matrix<T> h = quat::to_homogeneous(q, t);
            const vec3<T> back = quat::translation_of(quat::to_dual_quaternion(h));
            CAPTURE(n, t.x, t.y, t.z, back.x, back.y, back.z);
            // Within 8 units of roundoff of the largest component, and never past max().
            CHECK(max_difference(back, t) <= 8 * eps<T> * largest);
            CHECK(std::abs(back.x) <= largest);
            CHECK(std::abs(back.y) <= largest);
            CHECK(std::abs(back.z) <= largest);
            rounded_past += quat::detail::largest_magnitude(back) == largest ? 1 : 0;
            const homogeneous_matrix<T> again = quat::to_homogeneous(quat::to_dual_quaternion(h));
            for (int row = 0; row < 3; ++row) CHECK(std::isfinite(again(row, 3)));
        }
    }
    CHECK(rounded_past > 0);  // the case that overflowed is exercised
    // Beyond rounding a translation past max() is infinite, as any overflow.
    const dual_quaternion<T> beyond{quaternion<T>::identity(), quaternion<T>{0, largest, 0, 0}};
    CHECK(std::isinf(quat::translation_of(beyond).x));
}

}  // namespace test_homogeneous_matrix
