// Specification of interpolation.hpp: slerp and nlerp.
#include <cmath>

#include <quat/interpolation.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

using quat::quaternion;
using quat::test::tolerance;

namespace {

// Independent reference in long double: rotate a by t times the relative rotation along the
// shorter arc, q(t) = a exp(t log(a* b)), from the axis-angle form of a* b.
template <class T>
quaternion<long double> reference_slerp(const quaternion<T>& a, const quaternion<T>& b,
                                        long double t) {
    const quaternion<long double> al{a.w, a.x, a.y, a.z}, bl{b.w, b.x, b.y, b.z};
    quaternion<long double> relative = quat::conjugate(al) * bl;
    if (relative.w < 0) relative = -relative;
    const long double s =
        std::sqrt(relative.x * relative.x + relative.y * relative.y + relative.z * relative.z);
    const long double half = std::atan2(s, relative.w);
    if (s == 0) return al;
    const long double k = std::sin(t * half) / s;
    return al * quaternion<long double>{std::cos(t * half), relative.x * k, relative.y * k,
                                        relative.z * k};
}

// Twice the rotation angle between q and r: angle_between already returns the rotation angle (itself
// twice the 4D angle between the quaternions), so the factor 2 makes each bound below
// (tolerance<T>::slerp_angle) a bound of half that size on the rotation angle: stricter, not looser.
template <class T>
long double distance(const quaternion<T>& q, const quaternion<long double>& r) {
    const quaternion<long double> ql{q.w, q.x, q.y, q.z};
    return 2 * quat::angle_between(ql, r);
}

}  // namespace

TEMPLATE_TEST_CASE("slerp is exact at the ends and takes the shorter arc", "[interpolation]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        const auto a = random.unit_quaternion<T>(), b = random.unit_quaternion<T>();
        CHECK(quat::slerp(a, b, T(0)) == a);
        const quaternion<T> end = quat::slerp(a, b, T(1));
        CHECK((end == b || end == -b));
        CHECK(quat::dot(a, end) >= 0);
    }
}

TEMPLATE_TEST_CASE("slerp moves at constant angular velocity and stays unit", "[interpolation]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        const auto a = random.unit_quaternion<T>(), b = random.unit_quaternion<T>();
        const T total = quat::angle_between(a, b);
        for (const T t : {T(-0.5), T(0.1), T(0.25), T(0.5), T(0.9), T(1.5)}) {
            const quaternion<T> q = quat::slerp(a, b, t);
            CHECK(std::abs(quat::norm(q) - 1) <= tolerance<T>::unit_norm);
            if (t >= 0 && t <= 1) {
                CHECK(std::abs(quat::angle_between(a, q) - t * total) <= tolerance<T>::slerp_angle);
            }
            CHECK(distance(q, reference_slerp(a, b, t)) <= tolerance<T>::slerp_angle);
        }
    }
}

TEMPLATE_TEST_CASE("slerp is stable for nearly equal and nearly opposite rotations",
                   "[interpolation]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int k = 1; k <= 30; ++k) {
        const auto a = random.unit_quaternion<T>();
        const auto axis = random.unit_vector<T>();
        const T small = T(std::pow(10.0, -k / 2.0));
        const quaternion<T> turn{std::cos(small / 2), axis.x * std::sin(small / 2),
                                 axis.y * std::sin(small / 2), axis.z * std::sin(small / 2)};
        const quaternion<T> near = a * turn;
        for (const quaternion<T>& b : {near, -near, a, -a}) {
            const quaternion<T> q = quat::slerp(a, b, T(0.3));
            CAPTURE(k);
            CHECK(std::isfinite(q.w));
            CHECK(std::abs(quat::norm(q) - 1) <= tolerance<T>::unit_norm);
            CHECK(distance(q, reference_slerp(a, b, 0.3L)) <= tolerance<T>::slerp_angle);
        }
    }
}

TEMPLATE_TEST_CASE("nlerp follows the slerp path, normalized", "[interpolation]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        const auto a = random.unit_quaternion<T>(), b = random.unit_quaternion<T>();
        const quaternion<T> q = quat::nlerp(a, b, T(0.5));
        CHECK(std::abs(quat::norm(q) - 1) <= tolerance<T>::unit_norm);
        // At t = 1/2 both interpolations give the arc's midpoint.
        CHECK(quat::angle_between(q, quat::slerp(a, b, T(0.5))) <= tolerance<T>::slerp_angle);
        CHECK(quat::angle_between(quat::nlerp(a, b, T(0)), a) <= tolerance<T>::slerp_angle);
    }
}
