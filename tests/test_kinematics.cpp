// Specification of kinematics.hpp: angular velocity between orientations and its integration.
#include <algorithm>
#include <cmath>
#include <limits>

#include <quat/kinematics.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"
#include "support/wide_float.hpp"

namespace test_kinematics {

using quat::quaternion;
using quat::vec3;
using quat::test::eps;
using quat::test::tolerance;

// A quarter turn about z in 2 time units: pi / 4 rad per unit about z, in body and world frames.
constexpr double quarter_turn_rate =
    quat::body_angular_velocity(quat::quatd::identity(), quat::rotation_z(quat::numbers::pi / 2), 2)
        .z;
static_assert(quarter_turn_rate > quat::numbers::pi / 4 - 1e-15 &&
              quarter_turn_rate < quat::numbers::pi / 4 + 1e-15);
static_assert(quat::world_angular_velocity(quat::rotation_z(quat::numbers::pi / 2),
                                           quat::quatd::identity(), 2)
                  .x == 0);
static_assert(quat::integrate_body(quat::quatd::identity(), vec3<double>{0, 0, 0}, 1) ==
              quat::quatd::identity());

namespace {

using quat::test::wide;  // support/wide_float.hpp: products of two doubles are exact in 113 bits

// Independent reference: the rotation vector of q0* q1 (body) or q1 q0* (world) divided by dt. The
// product is formed in `wide`, where each product of two inputs is exact and the sums round at
// 1e-34, so the vector part is right to ~1e-22 relative even at angles of 1e-12; the arc tangent
// then runs in long double (1e-19 relative).
template <class T>
vec3<long double> reference_velocity(const quaternion<T>& q0, const quaternion<T>& q1,
                                     long double dt, bool body) {
    const quaternion<wide> a{wide(q0.w), wide(q0.x), wide(q0.y), wide(q0.z)};
    const quaternion<wide> b{wide(q1.w), wide(q1.x), wide(q1.y), wide(q1.z)};
    quaternion<wide> r = body ? quat::conjugate(a) * b : b * quat::conjugate(a);
    if (r.w < 0) r = -r;
    const vec3<long double> u{static_cast<long double>(r.x), static_cast<long double>(r.y),
                              static_cast<long double>(r.z)};
    const long double s = std::sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
    if (s == 0) return {0, 0, 0};
    return u * (2 * std::atan2(s, static_cast<long double>(r.w)) / s / dt);
}

template <class T>
long double relative_error(const vec3<T>& omega, const vec3<long double>& reference) {
    const vec3<long double> d{omega.x - reference.x, omega.y - reference.y, omega.z - reference.z};
    const long double n = quat::norm(reference);
    return n == 0 ? quat::norm(d) : quat::norm(d) / n;
}

template <class T>
T angle(const quaternion<T>& a, const quaternion<T>& b) {
    return quat::angle_between(a, b);
}

}  // namespace

TEMPLATE_TEST_CASE("body and world angular velocity undo integrate_body and integrate_world",
                   "[kinematics]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 2000; ++n) {
        const quaternion<T> q0 = random.unit_quaternion<T>();
        const T dt = random.uniform<T>(1e-3, 2);
        const vec3<T> omega = random.unit_vector<T>() * (random.uniform<T>(0, 3.1) / dt);
        const quaternion<T> body_end = quat::integrate_body(q0, omega, dt);
        const quaternion<T> world_end = quat::integrate_world(q0, omega, dt);
        CAPTURE(n, dt);
        // Back to omega: the error is a few eps of |omega dt| (<= pi), so bound it absolutely.
        const T scale = tolerance<T>::conversion * 4 / dt;
        CHECK(quat::test::max_difference(quat::body_angular_velocity(q0, body_end, dt), omega) <=
              scale);
        CHECK(quat::test::max_difference(quat::world_angular_velocity(q0, world_end, dt), omega) <=
              scale);
        // The world rate is the body rate seen in the world frame.
        CHECK(quat::test::max_difference(quat::world_angular_velocity(q0, body_end, dt),
                                         quat::rotate(q0, omega)) <= scale);
        CHECK(std::abs(quat::norm(body_end) - 1) <= tolerance<T>::unit_norm);
    }
}

TEMPLATE_TEST_CASE("angular velocity takes the shorter arc: q1 and -q1 give the same omega",
                   "[kinematics]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        const quaternion<T> q0 = random.unit_quaternion<T>(), q1 = random.unit_quaternion<T>();
        const vec3<T> omega = quat::body_angular_velocity(q0, q1, T(0.5));
        // Bit for bit the same under strict IEEE arithmetic (negation is exact); a compiler that
        // contracts a * b + c into fused multiply-adds may contract each call site differently.
        const T same = tolerance<T>::product * quat::norm(omega);
        CHECK(quat::test::max_difference(quat::body_angular_velocity(q0, -q1, T(0.5)), omega) <=
              same);
        CHECK(quat::test::max_difference(quat::body_angular_velocity(-q0, q1, T(0.5)), omega) <=
              same);
        CHECK(quat::test::max_difference(quat::world_angular_velocity(q0, -q1, T(0.5)),
                                         quat::world_angular_velocity(q0, q1, T(0.5))) <= same);
        CHECK(quat::norm(omega) * T(0.5) <= quat::numbers::pi_v<T> * (1 + 4 * eps<T>));
        CHECK(angle(quat::integrate_body(q0, omega, T(0.5)), q1) <= tolerance<T>::round_trip);
    }
}

TEMPLATE_TEST_CASE("angular velocity in coordinates: a turn about z seen from a tilted body",
                   "[kinematics]", float, double) {
    using T = TestType;
    const quaternion<T> tilted =
        quat::rotation_x(quat::numbers::pi_v<T> / 2);               // body z is world -y
    const quaternion<T> later = tilted * quat::rotation_z(T(0.1));  // turned about body z
    const vec3<T> body = quat::body_angular_velocity(tilted, later, T(0.5));
    const vec3<T> world = quat::world_angular_velocity(tilted, later, T(0.5));
    CHECK(quat::test::max_difference(body, vec3<T>{0, 0, T(0.2)}) <= tolerance<T>::conversion);
    CHECK(quat::test::max_difference(world, vec3<T>{0, T(-0.2), 0}) <= tolerance<T>::conversion);
    CHECK(quat::body_angular_velocity(tilted, tilted, T(1)) == vec3<T>{0, 0, 0});
}

TEMPLATE_TEST_CASE("angular velocity is accurate relative to tiny turns, 1e-3 to 1e-12 rad",
                   "[kinematics]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    // Measured worst relative error over 200 samples per decade (g++ 12, x86-64): body and world
    // 1.85 eps (double) and 2.02 eps (float); bound 4 eps. For float, q1 rounds to a
    // neighbour of q0 below about 1e-7 rad, and the reference follows the rounded q1.
    long double worst = 0;
    for (int decade = 3; decade <= 12; ++decade) {
        for (int n = 0; n < 200; ++n) {
            const quaternion<T> q0 = random.unit_quaternion<T>();
            const T dt = T(0.01);
            const T turn = T(std::pow(10.0, -decade)) * random.uniform<T>(1, 9.99);
            const vec3<T> omega = random.unit_vector<T>() * (turn / dt);
            for (const bool body : {true, false}) {
                const quaternion<T> q1 = body ? quat::integrate_body(q0, omega, dt)
                                              : quat::integrate_world(q0, omega, dt);
                const vec3<T> measured = body ? quat::body_angular_velocity(q0, q1, dt)
                                              : quat::world_angular_velocity(q0, q1, dt);
                const long double error =
                    relative_error(measured, reference_velocity(q0, q1, dt, body)) / eps<T>;
                worst = std::max(worst, error);
                CAPTURE(decade, body, error);
                CHECK(error <= 4);
            }
        }
    }
    INFO("worst relative error " << static_cast<double>(worst) << " eps");
    CHECK(worst > 0);
}

TEST_CASE("the naive q0* q1 loses the digits of a tiny turn that angular velocity keeps",
          "[kinematics]") {
    // Why the implementation forms the vector part from q1 - q0: conjugate(q0) * q1 leaves a
    // difference of nearly equal products, wrong by ~eps absolutely. Measured at 1e-10 rad:
    // naive worst 8.4e9 eps relative, quat 1.5 eps.
    quat::test::random_rotations random;
    long double naive_worst = 0, quat_worst = 0;
    for (int n = 0; n < 200; ++n) {
        const quat::quatd q0 = random.unit_quaternion<double>();
        const vec3<double> omega = random.unit_vector<double>() * 1e-10;
        const quat::quatd q1 = quat::integrate_body(q0, omega, 1.0);
        const vec3<long double> reference = reference_velocity(q0, q1, 1.0L, true);
        const vec3<double> naive = quat::to_rotation_vector(quat::conjugate(q0) * q1);
        naive_worst = std::max(naive_worst, relative_error(naive, reference) / eps<double>);
        quat_worst = std::max(
            quat_worst,
            relative_error(quat::body_angular_velocity(q0, q1, 1.0), reference) / eps<double>);
    }
    INFO("naive " << static_cast<double>(naive_worst) << " eps, quat "
                  << static_cast<double>(quat_worst) << " eps");
    CHECK(naive_worst > 1000);
    CHECK(quat_worst <= 4);
}

TEMPLATE_TEST_CASE("a constant rate integrated step by step is recovered from each step",
                   "[kinematics]", float, double) {
    using T = TestType;
    const vec3<T> omega{T(0.3), T(-1.2), T(2.0)};
    const T dt = T(1) / 256;
    quaternion<T> q = quat::normalize(quaternion<T>{1, 2, 3, 4});
    const quaternion<T> start = q;
    for (int step = 0; step < 512; ++step) {
        const quaternion<T> next = quat::integrate_body(q, omega, dt);
        // Rounding next to T moves it by ~eps, which moves the rate by ~eps / dt: the bound.
        CHECK(quat::test::max_difference(quat::body_angular_velocity(q, next, dt), omega) <=
              tolerance<T>::conversion / dt);
        q = quat::normalize(next);
    }
    // 512 steps of 1/256: the same as one step of 2 (angle 2 |omega| = 4.76 rad, past pi: compare
    // the rotations, not the rates).
    CHECK(angle(q, quat::integrate_body(start, omega, T(2))) <= 512 * tolerance<T>::round_trip);
}

TEMPLATE_TEST_CASE("angular velocity near a half turn and with a negative, zero or NaN dt",
                   "[kinematics]", float, double) {
    using T = TestType;
    const quaternion<T> q0 = quat::normalize(quaternion<T>{1, -2, 3, 0.5});
    // A turn just short of pi stays on its side; past pi the shorter arc goes the other way.
    const vec3<T> axis = quat::normalize(vec3<T>{1, 1, 0});
    for (const T turn : {quat::numbers::pi_v<T> - T(1e-3), quat::numbers::pi_v<T> - 16 * eps<T>}) {
        const vec3<T> omega =
            quat::body_angular_velocity(q0, quat::integrate_body(q0, axis * turn, 1), T(1));
        CHECK(quat::test::max_difference(omega, axis * turn) <= tolerance<T>::conversion * 4);
    }
    const vec3<T> backwards = quat::body_angular_velocity(
        q0, quat::integrate_body(q0, axis * (quat::numbers::pi_v<T> + T(0.5)), 1), T(1));
    CHECK(quat::test::max_difference(backwards, axis * (T(0.5) - quat::numbers::pi_v<T>)) <=
          tolerance<T>::conversion * 4);
    // A negative dt gives the rate that satisfies the same relation.
    const quaternion<T> q1 = quat::integrate_body(q0, vec3<T>{1, 0, 0}, T(0.25));
    const vec3<T> negative = quat::body_angular_velocity(q0, q1, T(-0.25));
    CHECK(quat::test::max_difference(negative, vec3<T>{-1, 0, 0}) <= tolerance<T>::conversion * 8);
    CHECK(angle(quat::integrate_body(q0, negative, T(-0.25)), q1) <= tolerance<T>::round_trip);
    // dt == 0: infinite (or NaN) components, never a finite-looking rate.
    const vec3<T> zero_dt = quat::body_angular_velocity(q0, q1, T(0));
    CHECK(std::isinf(zero_dt.x));
    CHECK(std::isnan(quat::body_angular_velocity(q0, q0, T(0)).x));
    const T nan = std::numeric_limits<T>::quiet_NaN();
    CHECK(std::isnan(quat::body_angular_velocity(q0, q1, nan).x));
    CHECK(std::isnan(quat::world_angular_velocity(quaternion<T>{nan, 0, 0, 0}, q1, T(1)).y));
    CHECK(std::isnan(quat::integrate_body(q0, vec3<T>{nan, 0, 0}, T(1)).w));
    CHECK(std::isnan(quat::integrate_world(q0, vec3<T>{0, 0, 1}, nan).w));
}

}  // namespace test_kinematics
