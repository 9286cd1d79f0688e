// Specification of rigid/screw.hpp: every rigid motion as a turn about an axis line and a slide
// along it.
#include <cmath>
#include <limits>

#include <quat/constants.hpp>
#include <quat/rigid/screw.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_screw {

using quat::dual_quaternion;
using quat::quaternion;
using quat::vec3;
using quat::test::eps;
using quat::test::max_difference;

TEST_CASE("to_screw reads a known screw motion", "[screw]") {
    // A quarter turn about the vertical line through (1, 0, 0), then a slide of 2 up it:
    // the origin goes to (1, -1, 2).
    const auto dq =
        quat::to_dual_quaternion(quat::rotation_z(quat::numbers::pi / 2), vec3<double>{1, -1, 2});
    const quat::screw<double> s = quat::to_screw(dq);
    CHECK(max_difference(s.direction, vec3<double>{0, 0, 1}) <= 2 * eps<double>);
    CHECK(max_difference(s.moment, vec3<double>{0, -1, 0}) <= 4 * eps<double>);  // (1,0,0) x z
    CHECK(s.angle == Approx(quat::numbers::pi / 2).epsilon(2 * eps<double>));
    CHECK(s.displacement == Approx(2).epsilon(2 * eps<double>));
}

TEMPLATE_TEST_CASE("from_screw(to_screw(dq)) is dq, and the axis moves along itself", "[screw]",
                   float, double) {
    quat::test::random_rotations random;
    for (int i = 0; i < 300; ++i) {
        const quaternion<TestType> q = random.unit_quaternion<TestType>();
        const auto dq = quat::to_dual_quaternion(q, random.vector<TestType>(2.0));
        const quat::screw<TestType> s = quat::to_screw(dq);
        CHECK(std::abs(quat::norm(s.direction) - 1) <= 4 * eps<TestType>);
        // A small angle puts the axis far away (a large moment), and rounding grows with it.
        const TestType reach = 1 + quat::norm(s.moment);
        CHECK(std::abs(quat::dot(s.direction, s.moment)) <= 8 * eps<TestType> * reach);
        CHECK(s.angle >= 0);
        CHECK(s.angle <= TestType(quat::numbers::pi));
        const auto back = quat::from_screw(s);
        const auto expected = dq.real.w < 0 ? -dq : dq;
        CHECK(max_difference(back.real, expected.real) <= 8 * eps<TestType>);
        CHECK(max_difference(back.dual, expected.dual) <= 16 * eps<TestType>);
        // The axis point nearest the origin slides along the axis by the displacement.
        const vec3<TestType> on_axis = quat::cross(s.direction, s.moment);
        CHECK(max_difference(quat::transform(dq, on_axis),
                             on_axis + s.direction * s.displacement) <= 16 * eps<TestType> * reach);
    }
}

TEST_CASE("to_screw of pure translations and the identity", "[screw]") {
    const auto shift = quat::to_dual_quaternion(quat::quatd::identity(), vec3<double>{0, 3, 4});
    const quat::screw<double> s = quat::to_screw(shift);
    CHECK(s.angle == 0);
    CHECK(s.displacement == 5);
    CHECK(s.direction == vec3<double>{0, 0.6, 0.8});
    CHECK(s.moment == vec3<double>{0, 0, 0});
    CHECK(quat::from_screw(s) == shift);
    const quat::screw<double> none = quat::to_screw(quat::dual_quaterniond::identity());
    CHECK(none.direction == vec3<double>{1, 0, 0});
    CHECK(none.angle == 0);
    CHECK(none.displacement == 0);
    CHECK(quat::from_screw(none) == quat::dual_quaterniond::identity());
    // A half turn: the angle is pi exactly.
    const auto half =
        quat::to_screw(quat::to_dual_quaternion(quat::quatd{0, 1, 0, 0}, vec3<double>{1, 0, 0}));
    CHECK(half.angle == quat::numbers::pi);
    CHECK(half.displacement == 1);
}

TEST_CASE("to_screw propagates NaN", "[screw][nan]") {
    auto dq = quat::to_dual_quaternion(quat::rotation_x(0.3), vec3<double>{1, 2, 3});
    dq.dual.x = std::numeric_limits<double>::quiet_NaN();
    CHECK(std::isnan(quat::to_screw(dq).displacement));
    dq = quat::to_dual_quaternion(quat::quatd::identity(), vec3<double>{1, 2, 3});
    dq.real.y = std::numeric_limits<double>::quiet_NaN();
    CHECK(std::isnan(quat::to_screw(dq).angle));
}

TEST_CASE("screw conversions are constexpr", "[screw][constexpr]") {
    constexpr auto s =
        quat::to_screw(quat::to_dual_quaternion(quat::quatd{0, 0, 0, 1}, vec3<double>{0, 0, 2}));
    static_assert(s.displacement == 2 && s.direction.z == 1);
    constexpr auto back = quat::from_screw(s);
    STATIC_REQUIRE(back.dual.w < -0.99);  // (0, t) real / 2 = (-1, 0, 0, 0)
}

TEMPLATE_TEST_CASE("to_screw of a turn by a subnormal angle is finite", "[screw][edge]", float,
                   double) {
    using T = TestType;
    const T tiny = std::numeric_limits<T>::denorm_min();
    const T half = std::sqrt(T(0.5));
    // Real part (1, tiny direction), a slide by 2 along the axis through the origin: the moment
    // is exactly zero, and w / |v| overflows on the way.
    const dual_quaternion<T> along_x{quaternion<T>{1, tiny, 0, 0}, quaternion<T>{0, 1, 0, 0}};
    const dual_quaternion<T> along_xy{quaternion<T>{1, tiny, tiny, 0},
                                      quaternion<T>{0, half, half, 0}};
    for (const dual_quaternion<T>& dq : {along_x, along_xy}) {
        const quat::screw<T> back = quat::to_screw(dq);
        CHECK(std::abs(back.displacement - T(2)) <= 4 * eps<T>);
        CHECK(std::abs(quat::norm(back.direction) - T(1)) <= 4 * eps<T>);
        // The moment is cot(angle / 2) times what rounding leaves across the axis: finite, and
        // exactly zero where nothing is left.
        CHECK(std::isfinite(back.moment.x));
        CHECK(std::isfinite(back.moment.y));
        CHECK(back.moment.z == 0);
    }
    const quat::screw<T> exact = quat::to_screw(along_x);
    CHECK(exact.moment.x == 0);
    CHECK(exact.moment.y == 0);
}

TEMPLATE_TEST_CASE("to_screw of a subnormal turn with a slide along its axis has a zero moment",
                   "[screw][edge]", float, double) {
    using T = TestType;
    using L = std::numeric_limits<T>;
    // The turn (1, d a) about a / |a| by about 2 |a| d, then a slide by k a, along that axis: the
    // axis passes the origin, so the moment is zero. Across the axis is only the rounding of the
    // unit direction, |t| eps, which a factor cot(angle / 2) ~ 1 / d would make huge or infinite.
    // Reference: the exact screw, in long double.
    const vec3<T> directions[] = {{1, 0, 1}, {1, 2, 3}, {3, 1, 2}, {1, 2, 0}};
    for (const T d : {L::denorm_min(), L::denorm_min() * T(7), L::min() / T(64)}) {
        for (const vec3<T>& a : directions) {
            for (const T k : {T(1), T(100), T(1e5)}) {
                CAPTURE(d, a.x, a.y, a.z, k);
                const quaternion<T> q{T(1), d * a.x, d * a.y, d * a.z};
                const quat::screw<T> s = quat::to_screw(quat::to_dual_quaternion(q, a * k));
                const long double length =
                    std::sqrt(static_cast<long double>(a.x * a.x + a.y * a.y + a.z * a.z));
                CHECK(s.moment == vec3<T>{0, 0, 0});
                CHECK(std::abs(s.direction.x - a.x / length) <= 4 * eps<T>);
                CHECK(std::abs(s.direction.y - a.y / length) <= 4 * eps<T>);
                CHECK(std::abs(s.direction.z - a.z / length) <= 4 * eps<T>);
                CHECK(std::abs(s.displacement - k * length) <= 8 * eps<T> * k * length);
                CHECK(std::abs(s.angle - 2 * length * static_cast<long double>(d)) <=
                      4 * L::denorm_min() + 4 * eps<T> * s.angle);
            }
        }
    }
}

TEST_CASE("to_screw of a subnormal turn with a slide across its axis", "[screw][edge]") {
    // A turn by 1e-310 about x and a slide by 1e-300 along y: the axis is the line through
    // p = (across + cot(h) l x t) / 2 = (0, 5e-301, 5e9), and the moment p x l = (0, 5e9, -5e-301)
    // (long double, exact to rounding). A slide of 1 across would put the axis 5e309 away, past
    // max(): that moment is infinite.
    const double d = 1e-310;
    const quat::screw<double> s = quat::to_screw(
        quat::to_dual_quaternion(quaternion<double>{1, d / 2, 0, 0}, vec3<double>{0, 1e-300, 0}));
    const long double cot = 1 / (static_cast<long double>(d / 2));
    CHECK(s.moment.x == 0);
    CHECK(std::abs(s.moment.y - 1e-300L * cot / 2) <= 8 * eps<double> * (1e-300L * cot / 2));
    CHECK(std::abs(s.moment.z + 5e-301L) <= 8 * eps<double> * 5e-301L);
    const quat::screw<double> far = quat::to_screw(
        quat::to_dual_quaternion(quaternion<double>{1, d / 2, 0, 0}, vec3<double>{0, 1, 0}));
    CHECK(std::isinf(far.moment.y));
}

}  // namespace test_screw
