// Specification of homogeneous_matrix.hpp: 4x4 rigid motions on column vectors (x, y, z, 1), their
// products, and conversions to and from dual quaternions, against long double matrices and GLM.
#include <cmath>
#include <limits>
#include <optional>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <quat/homogeneous_matrix.hpp>
#include <quat/interop/glm.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/rigid_reference.hpp"
#include "support/tolerance.hpp"

using quat::dual_quaternion;
using quat::homogeneous_matrix;
using quat::quaternion;
using quat::vec3;
using quat::test::eps;
using quat::test::max_difference;

namespace {}  // namespace

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
