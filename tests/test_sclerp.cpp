// Specification of rigid/sclerp.hpp: screw linear interpolation equals the matrix form a exp(t
// log(a^-1 b)) of the 4x4 transforms (long double series, tests/support/rigid_reference.hpp), moves
// at constant screw velocity, and stays accurate for pure and nearly pure translations and near
// half turns.
#include <algorithm>
#include <cmath>
#include <limits>

#include <quat/conversions.hpp>
#include <quat/rigid/dual_quaternion.hpp>
#include <quat/rigid/sclerp.hpp>
#include <quat/rigid/screw.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/rigid_reference.hpp"
#include "support/tolerance.hpp"

namespace test_sclerp {

using quat::dual_quaternion;
using quat::quaternion;
using quat::vec3;
using quat::test::eps;

namespace {

// a followed (in a's frame) by a turn of `angle` about a random axis and a random translation.
template <class T>
dual_quaternion<T> nearby(quat::test::random_rotations& random, const dual_quaternion<T>& a,
                          double angle, double reach = 1.0) {
    const vec3<T> axis = random.unit_vector<T>();
    const vec3<T> t = random.vector<T>(reach);
    const quaternion<T> turn = quat::from_rotation_vector(axis * static_cast<T>(angle));
    return a * quat::to_dual_quaternion(turn, t);
}

template <class T>
T screw_angle(const dual_quaternion<T>& dq) {
    return quat::to_screw(dq).angle;
}

}  // namespace

TEMPLATE_TEST_CASE("sclerp agrees with the 4x4 form a exp(t log(a^-1 b)) for random motions",
                   "[sclerp][sweep]", float, double) {
    quat::test::random_rotations random;
    long double worst = 0;
    for (int i = 0; i < 300; ++i) {
        const auto a = random.rigid_motion<TestType>();
        const auto b = random.rigid_motion<TestType>();
        const TestType t = random.uniform<TestType>(0.0, 1.0);
        worst = std::max(worst, quat::test::sclerp_difference(a, b, t).relative());
    }
    CHECK(worst <= quat::test::tolerance<TestType>::sclerp);
}

TEMPLATE_TEST_CASE("sclerp is exact at its ends and takes the shorter path", "[sclerp]", float,
                   double) {
    quat::test::random_rotations random;
    for (int i = 0; i < 100; ++i) {
        const auto a = random.rigid_motion<TestType>();
        const auto b = random.rigid_motion<TestType>();
        CHECK(quat::sclerp(a, b, TestType(0)) == a);
        const auto end = quat::sclerp(a, b, TestType(1));
        CHECK((end == b || end == -b));
        // -b is the same motion: the path is the same.
        const auto middle = quat::sclerp(a, b, TestType(0.5));
        const auto middle_flipped = quat::sclerp(a, -b, TestType(0.5));
        CHECK(quat::test::max_difference(middle.real, middle_flipped.real) <= 4 * eps<TestType>);
        CHECK(quat::test::max_difference(middle.dual, middle_flipped.dual) <= 8 * eps<TestType>);
        // The relative turn of the path is at most a half turn.
        CHECK(screw_angle(quat::inverse(a) * middle) <=
              TestType(quat::numbers::pi / 2) * (1 + 4 * eps<TestType>));
    }
}

TEMPLATE_TEST_CASE("sclerp turns and slides along the screw axis linearly in t", "[sclerp]", float,
                   double) {
    quat::test::random_rotations random;
    for (int i = 0; i < 100; ++i) {
        const auto a = random.rigid_motion<TestType>();
        const auto b = random.rigid_motion<TestType>();
        const auto whole = quat::to_screw(quat::inverse(a) * b);
        for (TestType t : {TestType(0.125), TestType(0.3), TestType(0.5), TestType(0.9)}) {
            const auto part = quat::to_screw(quat::inverse(a) * quat::sclerp(a, b, t));
            CHECK(std::abs(part.angle - t * whole.angle) <= 16 * eps<TestType>);
            CHECK(std::abs(part.displacement - t * whole.displacement) <= 32 * eps<TestType>);
            CHECK(quat::test::max_difference(part.direction, whole.direction) <=
                  64 * eps<TestType> / std::sin(whole.angle / 2));
        }
    }
}

TEMPLATE_TEST_CASE("sclerp of a pure translation moves along the straight line", "[sclerp]", float,
                   double) {
    quat::test::random_rotations random;
    for (int i = 0; i < 50; ++i) {
        const quaternion<TestType> q = random.unit_quaternion<TestType>();
        const vec3<TestType> ta = random.vector<TestType>(3.0);
        const vec3<TestType> tb = random.vector<TestType>(3.0);
        const auto a = quat::to_dual_quaternion(q, ta), b = quat::to_dual_quaternion(q, tb);
        const TestType t = random.uniform<TestType>(0.0, 1.0);
        const auto m = quat::sclerp(a, b, t);
        CHECK(m.real == q);
        const vec3<TestType> expected = ta + (tb - ta) * t;
        CHECK(quat::test::max_difference(quat::translation_of(m), expected) <=
              8 * eps<TestType> * (1 + quat::norm(tb - ta) + quat::norm(ta)));
        CHECK(quat::test::sclerp_difference(a, b, t).relative() <=
              quat::test::tolerance<TestType>::sclerp);
    }
}

TEMPLATE_TEST_CASE("sclerp stays accurate for nearly equal rotations", "[sclerp]", float, double) {
    quat::test::random_rotations random;
    long double worst = 0;
    for (double angle : {1e-1, 1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-13, 1e-20, 0.0}) {
        for (int i = 0; i < 30; ++i) {
            const auto a = random.rigid_motion<TestType>();
            const auto b = nearby(random, a, angle);
            const TestType t = random.uniform<TestType>(0.0, 1.0);
            worst = std::max(worst, quat::test::sclerp_difference(a, b, t).relative());
        }
    }
    CHECK(worst <= quat::test::tolerance<TestType>::sclerp);
}

TEMPLATE_TEST_CASE("sclerp stays accurate near half turns", "[sclerp]", float, double) {
    quat::test::random_rotations random;
    long double worst = 0;
    for (double gap : {1e-1, 1e-2, 1e-3, 1e-4}) {
        for (int i = 0; i < 30; ++i) {
            const auto a = random.rigid_motion<TestType>();
            const auto b = nearby(random, a, quat::numbers::pi - gap);
            const TestType t = random.uniform<TestType>(0.0, 1.0);
            worst = std::max(worst, quat::test::sclerp_difference(a, b, t).relative());
        }
    }
    CHECK(worst <= quat::test::tolerance<TestType>::sclerp);
}

TEST_CASE("sclerp through an exact half turn keeps the turn's axis", "[sclerp]") {
    const auto a = quat::to_dual_quaternion(quat::quatd::identity(), vec3<double>{1, 0, 0});
    // A half turn about the z axis through the point p = (0, 1, 0), sliding 2 along z.
    const vec3<double> p{0, 1, 0}, z{0, 0, 1};
    const quat::screw<double> motion{z, quat::cross(p, z), quat::numbers::pi, 2};
    const auto b = a * quat::from_screw(motion);
    const auto middle = quat::to_screw(quat::inverse(a) * quat::sclerp(a, b, 0.5));
    CHECK(middle.angle == Approx(quat::numbers::pi / 2).epsilon(1e-15));
    CHECK(middle.displacement == Approx(1).epsilon(1e-15));
    CHECK(quat::test::max_difference(middle.direction, vec3<double>{0, 0, 1}) <= 4 * eps<double>);
    CHECK(quat::test::max_difference(middle.moment, motion.moment) <= 8 * eps<double>);
}

TEST_CASE("sclerp extrapolates along the same screw outside [0, 1]", "[sclerp]") {
    quat::test::random_rotations random;
    for (int i = 0; i < 50; ++i) {
        const auto a = random.rigid_motion<double>();
        const auto b = random.rigid_motion<double>();
        for (double t : {-0.5, 1.5, 2.0})
            CHECK(quat::test::sclerp_difference(a, b, t).relative() <= 64 * eps<double>);
    }
}

TEST_CASE("sclerp propagates NaN", "[sclerp][nan]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto a = quat::to_dual_quaternion(quat::quatd::identity(), vec3<double>{1, 2, 3});
    const auto b = quat::to_dual_quaternion(quat::rotation_x(1.0), vec3<double>{0, 1, 0});
    CHECK(std::isnan(quat::sclerp(a, b, nan).dual.x));
    auto bad = b;
    bad.dual.y = nan;
    for (double t : {0.0, 0.5, 1.0})
        CHECK(std::isnan(quat::translation_of(quat::sclerp(a, bad, t)).y));
}

TEST_CASE("sclerp is constexpr", "[sclerp][constexpr]") {
    constexpr auto a = quat::dual_quaterniond::identity();
    constexpr auto b = quat::to_dual_quaternion(quat::quatd{0, 0, 0, 1}, vec3<double>{0, 0, 2});
    constexpr auto middle = quat::sclerp(a, b, 0.5);
    static_assert(middle.real.z > 0.7 && middle.real.z < 0.71);
    STATIC_REQUIRE(middle.dual.w < 0);
}

}  // namespace test_sclerp
