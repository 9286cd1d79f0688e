// Specification of swing_twist.hpp: q = swing * twist, twist about the axis, swing perpendicular.
#include <cmath>
#include <limits>

#include <quat/swing_twist.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_swing_twist {

using quat::quaternion;
using quat::vec3;
using quat::test::eps;
using quat::test::tolerance;

static_assert(quat::swing_twist(quat::quatd{0, 0, 0, 1}, vec3<double>{0, 0, 3}).twist ==
                  quat::quatd{0, 0, 0, 1},
              "a half turn about the axis is all twist");
static_assert(quat::swing_twist(quat::quatd{0, 0, 0, 1}, vec3<double>{0, 0, 3}).swing ==
              quat::quatd::identity());

namespace {

template <class T>
vec3<T> vector_part(const quaternion<T>& q) {
    return {q.x, q.y, q.z};
}

// Independent reference in long double: the smallest rotation taking unit a to unit b,
// normalize(1 + a . b, a x b) (the half-way quaternion).
template <class T>
quaternion<long double> shortest_arc(const vec3<T>& a_in, const vec3<T>& b_in) {
    const vec3<long double> a{a_in.x, a_in.y, a_in.z}, b{b_in.x, b_in.y, b_in.z};
    const vec3<long double> c = quat::cross(a, b);
    return quat::normalize(quaternion<long double>{1 + quat::dot(a, b), c.x, c.y, c.z});
}

// Unreal Engine's FQuat::ToSwingTwist, written from its documented behaviour: project the vector
// part on the (unit) twist axis, twist = that projection with q's w, normalized, or the identity
// when it is exactly zero; swing = q * twist^-1.
template <class T>
quat::swing_twist_parts<T> unreal_swing_twist(const quaternion<T>& q, const vec3<T>& unit_axis) {
    const vec3<T> projection = unit_axis * quat::dot(unit_axis, vector_part(q));
    quaternion<T> twist{q.w, projection.x, projection.y, projection.z};
    twist = quat::squared_norm(twist) == 0 ? quaternion<T>::identity() : quat::normalize(twist);
    return {q * quat::inverse(twist), twist};
}

}  // namespace

TEMPLATE_TEST_CASE("swing * twist is q, twist turns about the axis, swing about a perpendicular",
                   "[swing_twist]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    // Measured worst |swing . axis| 1.25 eps (double and float), bound 8 (tolerance::product);
    // angle between swing * twist and q 4.6 eps (double) and 5.6 eps (float), bound 16.
    for (int n = 0; n < 5000; ++n) {
        const quaternion<T> q = random.unit_quaternion<T>();
        const vec3<T> unit_axis = random.unit_vector<T>();
        const T length = T(std::pow(10.0, random.uniform<double>(-20, 20)));
        const auto [swing, twist] = quat::swing_twist(q, unit_axis * length);
        CAPTURE(n, length);
        CHECK(quat::angle_between(swing * twist, q) <= tolerance<T>::round_trip);
        CHECK(quat::norm(quat::cross(vector_part(twist), unit_axis)) <= tolerance<T>::product);
        CHECK(std::abs(quat::dot(vector_part(swing), unit_axis)) <= tolerance<T>::product);
        CHECK(std::abs(quat::norm(swing) - 1) <= tolerance<T>::unit_norm);
        CHECK(std::abs(quat::norm(twist) - 1) <= tolerance<T>::unit_norm);
        // The opposite axis gives the same rotations, up to the conditioning of the twist: its
        // angle 2 atan2(v . a, w) moves by ~eps / |(w, v . a)| when the axis rounds differently.
        const auto opposite = quat::swing_twist(q, -unit_axis);
        const T conditioning = 1 / std::hypot(q.w, quat::dot(vector_part(q), unit_axis));
        CHECK(quat::angle_between(opposite.twist, twist) <=
              tolerance<T>::round_trip * conditioning);
        CHECK(quat::angle_between(opposite.swing, swing) <=
              tolerance<T>::round_trip * conditioning);
        const auto checked = quat::try_swing_twist(q, unit_axis * length);
        REQUIRE(checked.has_value());
        CHECK(checked->swing == swing);
        CHECK(checked->twist == twist);
    }
}

TEMPLATE_TEST_CASE("the swing is the smallest rotation taking the axis to q's image of it",
                   "[swing_twist]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 5000; ++n) {
        const quaternion<T> q = random.unit_quaternion<T>();
        const vec3<T> axis = random.unit_vector<T>();
        const vec3<T> image = quat::rotate(q, axis);
        const T cosine = quat::dot(axis, image);
        // Near a half turn of the axis the shortest arc is ill-conditioned (its axis is undefined
        // at cosine = -1); the rounding of `image` is amplified by 1 / (1 + cosine).
        const quaternion<long double> reference = shortest_arc(axis, image);
        const quaternion<T> swing = quat::swing_twist(q, axis).swing;
        const long double error = quat::angle_between(
            quaternion<long double>{swing.w, swing.x, swing.y, swing.z}, reference);
        CAPTURE(n, cosine);
        CHECK(error <= tolerance<T>::round_trip / (1 + cosine));
    }
}

TEMPLATE_TEST_CASE("swing_twist is Unreal's ToSwingTwist", "[swing_twist]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 2000; ++n) {
        const quaternion<T> q = random.unit_quaternion<T>();
        const vec3<T> axis = random.unit_vector<T>();
        const auto ours = quat::swing_twist(q, axis);
        const auto unreal = unreal_swing_twist(q, axis);
        // Both normalize the same (w, (v . a) a); quat normalizes the axis again, which the twist
        // feels as ~eps / |(w, v . a)| (its conditioning).
        const T conditioning = 1 / std::hypot(q.w, quat::dot(vector_part(q), axis));
        CHECK(quat::test::max_difference(ours.swing, unreal.swing) <=
              tolerance<T>::product * conditioning);
        CHECK(quat::test::max_difference(ours.twist, unreal.twist) <=
              tolerance<T>::product * conditioning);
    }
}

TEMPLATE_TEST_CASE("pure twists, pure swings and the undefined twist", "[swing_twist]", float,
                   double) {
    using T = TestType;
    const vec3<T> z{0, 0, 1};
    const quaternion<T> twist_only = quat::rotation_z(T(2.5));
    CHECK(quat::angle_between(quat::swing_twist(twist_only, z * 7).twist, twist_only) <=
          tolerance<T>::round_trip);
    CHECK(quat::angle_between(quat::swing_twist(twist_only, z).swing, quaternion<T>::identity()) <=
          tolerance<T>::round_trip);
    const quaternion<T> swing_only = quat::rotation_x(T(-1.2));
    CHECK(quat::swing_twist(swing_only, z).twist == quaternion<T>::identity());
    CHECK(quat::swing_twist(swing_only, z).swing == swing_only);

    // A half turn about an axis perpendicular to z: w = v . z = 0, the twist is undefined.
    const quaternion<T> flip{0, T(0.6), T(0.8), 0};
    CHECK(quat::swing_twist(flip, z).twist == quaternion<T>::identity());
    CHECK(quat::swing_twist(flip, z).swing == flip);
    CHECK_FALSE(quat::try_swing_twist(flip, z).has_value());
    // Within the threshold (w^2 + (v . z)^2 <= eps^2): still undefined.
    const T small = eps<T> / 2;
    const quaternion<T> near_flip = quat::normalize(quaternion<T>{small, T(0.6), T(0.8), small});
    CHECK_FALSE(quat::try_swing_twist(near_flip, z).has_value());
    CHECK(quat::swing_twist(near_flip, z).swing == near_flip);
    // Just beyond it the twist is defined (a half turn about z here) and the parts are exact.
    const T beyond = 2 * eps<T>;
    const quaternion<T> defined = quat::normalize(quaternion<T>{0, T(0.6), T(0.8), beyond});
    const auto parts = quat::try_swing_twist(defined, z);
    REQUIRE(parts.has_value());
    CHECK(quat::angle_between(parts->swing * parts->twist, defined) <= tolerance<T>::round_trip);
    CHECK(std::abs(parts->twist.z) == Approx(1));
    CHECK(std::abs(parts->swing.z) <= tolerance<T>::product);
}

TEMPLATE_TEST_CASE("try_swing_twist rejects a zero or non-finite axis or q", "[swing_twist]", float,
                   double) {
    using T = TestType;
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    const quaternion<T> q = quat::normalize(quaternion<T>{1, 2, 3, 4});
    CHECK_FALSE(quat::try_swing_twist(q, vec3<T>{0, 0, 0}).has_value());
    CHECK_FALSE(quat::try_swing_twist(q, vec3<T>{nan, 0, 1}).has_value());
    CHECK_FALSE(quat::try_swing_twist(q, vec3<T>{inf, 0, 1}).has_value());
    CHECK_FALSE(quat::try_swing_twist(quaternion<T>{nan, 0, 0, 1}, vec3<T>{0, 0, 1}).has_value());
    CHECK_FALSE(quat::try_swing_twist(quaternion<T>{0, inf, 0, 0}, vec3<T>{0, 0, 1}).has_value());
    CHECK(
        quat::try_swing_twist(q, vec3<T>{0, 0, std::numeric_limits<T>::denorm_min()}).has_value());
    // The unchecked function gives NaN parts for such input instead.
    CHECK(std::isnan(quat::swing_twist(q, vec3<T>{0, 0, 0}).twist.w));
    CHECK(std::isnan(quat::swing_twist(quaternion<T>{nan, 0, 0, 1}, vec3<T>{0, 0, 1}).swing.w));
}

}  // namespace test_swing_twist
