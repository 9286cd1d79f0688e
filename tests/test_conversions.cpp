// Specification of conversions.hpp: quaternion <-> matrix <-> axis-angle <-> rotation vector.
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Geometry>
#include <quat/conversions.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/same_bits.hpp"
#include "support/tolerance.hpp"

namespace test_conversions {

using quat::axis_angle;
using quat::quaternion;
using quat::rotation_matrix;
using quat::vec3;
using quat::test::max_difference;
using quat::test::tolerance;

static_assert(quat::to_matrix(quat::quatd::identity()) == rotation_matrix<double>::identity());
static_assert(quat::to_matrix(quat::quatd{0, 0, 0, 1}) ==
                  rotation_matrix<double>::from_rows({-1, 0, 0}, {0, -1, 0}, {0, 0, 1}),
              "180 degrees about z");
static_assert(quat::to_mrp(quat::quatd{0, 0, 1, 0}) == vec3<double>{0, 1, 0}, "half turn: |p| = 1");
static_assert(quat::from_mrp(vec3<double>{1, 0, 0}) == quat::quatd{0, 1, 0, 0});
static_assert(quat::from_mrp(vec3<double>{0, 0, 0}) == quat::quatd::identity());

TEMPLATE_TEST_CASE("to_matrix is a homomorphism that agrees with rotate", "[conversions]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 2000; ++n) {
        const auto a = random.unit_quaternion<T>(), b = random.unit_quaternion<T>();
        const vec3<T> v = random.unit_vector<T>();
        CHECK(max_difference(quat::to_matrix(a * b), quat::to_matrix(a) * quat::to_matrix(b)) <=
              tolerance<T>::conversion);
        CHECK(max_difference(quat::rotate(quat::to_matrix(a), v), quat::rotate(a, v)) <=
              tolerance<T>::rotate);
        CHECK(quat::to_matrix(-a) == quat::to_matrix(a));
        CHECK(quat::orthogonality_error(quat::to_matrix(a)) <= tolerance<T>::conversion);
    }
}

TEMPLATE_TEST_CASE("matrix -> quaternion inverts to_matrix, 180-degree turns included",
                   "[conversions]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    std::vector<quaternion<T>> inputs;
    inputs.reserve(2204);
    for (int n = 0; n < 2000; ++n) inputs.push_back(random.unit_quaternion<T>());
    for (int n = 0; n < 200; ++n) {  // half turns: w = 0, about random and coordinate axes
        const vec3<T> a = random.unit_vector<T>();
        inputs.push_back({0, a.x, a.y, a.z});
    }
    inputs.push_back({0, 1, 0, 0});
    inputs.push_back({0, 0, 1, 0});
    inputs.push_back({0, 0, 0, 1});
    inputs.push_back({1, 0, 0, 0});
    for (const auto& q : inputs) {
        const quaternion<T> back = quat::to_quaternion(quat::to_matrix(q));
        CAPTURE(q.w, q.x, q.y, q.z);
        CHECK(back.w >= 0);
        CHECK(std::abs(quat::norm(back) - 1) <= tolerance<T>::unit_norm);
        CHECK(quat::angle_between(back, q) <= tolerance<T>::round_trip);
    }
}

TEMPLATE_TEST_CASE("try_to_quaternion rejects non-rotations", "[conversions]", float, double) {
    using T = TestType;
    auto m = rotation_matrix<T>::identity();
    CHECK(quat::try_to_quaternion(m).has_value());
    m(0, 1) = T(0.01);
    CHECK_FALSE(quat::try_to_quaternion(m).has_value());
    CHECK(quat::try_to_quaternion(m, T(0.1)).has_value());
    auto mirror = rotation_matrix<T>::identity();
    mirror(1, 1) = -1;
    CHECK_FALSE(quat::try_to_quaternion(mirror).has_value());
    auto broken = rotation_matrix<T>::identity();
    broken(2, 0) = std::numeric_limits<T>::quiet_NaN();
    CHECK_FALSE(quat::try_to_quaternion(broken).has_value());
    broken(2, 0) = std::numeric_limits<T>::infinity();
    CHECK_FALSE(quat::try_to_quaternion(broken).has_value());
}

TEMPLATE_TEST_CASE("axis-angle round trips through quaternion and matrix", "[conversions]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 2000; ++n) {
        const axis_angle<T> r{random.unit_vector<T>(), random.uniform<T>(1e-3, 3.14)};
        const quaternion<T> q = quat::to_quaternion(r);
        CHECK(max_difference(quat::to_matrix(r), quat::to_matrix(q)) <= tolerance<T>::conversion);
        const axis_angle<T> back = quat::to_axis_angle(q);
        CHECK(back.angle ==
              Approx(r.angle).epsilon(64 * std::numeric_limits<T>::epsilon() / r.angle).margin(0));
        CHECK(max_difference(back.axis, r.axis) <= tolerance<T>::round_trip / r.angle);
        const axis_angle<T> from_matrix = quat::to_axis_angle(quat::to_matrix(r));
        CHECK(quat::angle_between(quat::to_quaternion(from_matrix), q) <= tolerance<T>::round_trip);
    }
    const axis_angle<T> none = quat::to_axis_angle(quaternion<T>::identity());
    CHECK(none.angle == 0);
    CHECK(none.axis == vec3<T>{1, 0, 0});
    // The half angle: a quarter turn about z is (cos 45°, 0, 0, sin 45°), not (cos 90°, ..., sin
    // 90°).
    const quaternion<T> quarter =
        quat::to_quaternion(axis_angle<T>{{0, 0, 1}, quat::numbers::pi_v<T> / 2});
    CHECK(quarter.w == Approx(std::sqrt(0.5)));
    CHECK(quarter.z == Approx(std::sqrt(0.5)));
}

TEMPLATE_TEST_CASE("try_to_quaternion(axis_angle) normalizes the axis and rejects bad input",
                   "[conversions]", float, double) {
    using T = TestType;
    const auto q = quat::try_to_quaternion(axis_angle<T>{{0, 0, 7}, T(1)});
    REQUIRE(q.has_value());
    CHECK(std::abs(quat::norm(*q) - 1) <= tolerance<T>::unit_norm);
    CHECK_FALSE(quat::try_to_quaternion(axis_angle<T>{{0, 0, 0}, T(1)}).has_value());
    CHECK_FALSE(
        quat::try_to_quaternion(axis_angle<T>{{0, 0, 1}, std::numeric_limits<T>::infinity()})
            .has_value());
    CHECK_FALSE(
        quat::try_to_quaternion(axis_angle<T>{{std::numeric_limits<T>::quiet_NaN(), 0, 1}, T(1)})
            .has_value());
}

TEMPLATE_TEST_CASE("rotation vectors: exp and log are inverse from tiny angles to pi",
                   "[conversions]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int decade = -30; decade <= 0; ++decade) {
        for (int n = 0; n < 20; ++n) {
            const T angle =
                std::min(T(3.14159), T(std::pow(10.0, decade)) * random.uniform<T>(1, 9.99));
            const vec3<T> v = random.unit_vector<T>() * angle;
            const quaternion<T> q = quat::from_rotation_vector(v);
            CAPTURE(angle);
            CHECK(std::abs(quat::norm(q) - 1) <= tolerance<T>::unit_norm);
            const vec3<T> back = quat::to_rotation_vector(q);
            CHECK(max_difference(back, v) <= tolerance<T>::conversion * angle);
            // Independent reference: the axis-angle formula, in long double.
            const long double h = static_cast<long double>(angle) / 2, s = std::sin(h) / angle;
            CHECK(std::abs(static_cast<long double>(q.w) - std::cos(h)) <=
                  tolerance<T>::conversion);
            CHECK(std::abs(static_cast<long double>(q.x) - s * v.x) <=
                  tolerance<T>::conversion * std::abs(s * v.x) +
                      std::numeric_limits<T>::denorm_min());
        }
    }
    CHECK(quat::from_rotation_vector(vec3<T>{0, 0, 0}) == quaternion<T>::identity());
    CHECK(quat::to_rotation_vector(quaternion<T>::identity()) == vec3<T>{0, 0, 0});
    const vec3<T> half_turn = quat::to_rotation_vector(quaternion<T>{0, 0, 1, 0});
    CHECK(half_turn.y == Approx(quat::numbers::pi_v<T>));
}

// ---- Modified Rodrigues parameters
// ---------------------------------------------------------------

namespace {

// Independent reference in long double: axis * tan(angle / 4) with the angle in [0, pi] from the
// axis-angle form of q.
template <class T>
vec3<long double> reference_mrp(const quaternion<T>& q) {
    quaternion<long double> p{q.w, q.x, q.y, q.z};
    if (p.w < 0) p = -p;
    const long double s = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    if (s == 0) return {0, 0, 0};
    const long double angle = 2 * std::atan2(s, p.w);
    return vec3<long double>{p.x, p.y, p.z} * (std::tan(angle / 4) / s);
}

template <class T>
long double relative_difference(const vec3<T>& p, const vec3<long double>& reference) {
    const vec3<long double> d{p.x - reference.x, p.y - reference.y, p.z - reference.z};
    return quat::norm(d) / quat::norm(reference);
}

}  // namespace

TEMPLATE_TEST_CASE("to_mrp is axis * tan(angle / 4) for angles from 1e-30 to pi",
                   "[conversions][mrp]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    // Measured worst relative error 1.19 eps (double) and 1.02 eps (float); bound 4 eps.
    for (int n = 0; n < 2000; ++n) {
        const quaternion<T> q = random.unit_quaternion<T>();
        const vec3<T> p = quat::to_mrp(q);
        CAPTURE(n);
        CHECK(relative_difference(p, reference_mrp(q)) <= 4 * quat::test::eps<T>);
        CHECK(quat::norm(p) <= 1);
        CHECK(quat::to_mrp(-q) == p);
        CHECK(relative_difference(quat::to_mrp(q * T(1e-3)), reference_mrp(q)) <=
              4 * quat::test::eps<T>);
    }
    for (int decade = 1; decade <= 30; ++decade) {
        const T angle = T(std::pow(10.0, -decade));
        const vec3<T> axis = random.unit_vector<T>();
        const quaternion<T> q = quat::from_rotation_vector(axis * angle);
        CAPTURE(angle);
        CHECK(relative_difference(quat::to_mrp(q), reference_mrp(q)) <= 4 * quat::test::eps<T>);
    }
    // scipy: Rotation.from_rotvec([0, 0, pi/2]).as_mrp() == [0, 0, tan(pi/8)] = 0.41421356...
    const vec3<T> quarter = quat::to_mrp(quat::rotation_z(quat::numbers::pi_v<T> / 2));
    CHECK(quarter.z == Approx(0.41421356237309515).epsilon(4 * quat::test::eps<T>));
    CHECK(quarter.x == 0);
    CHECK(quat::to_mrp(quaternion<T>::identity()) == vec3<T>{0, 0, 0});
    // A half turn: |p| = 1, the sign of the vector part as given.
    CHECK(quat::to_mrp(quaternion<T>{0, 0, 1, 0}) == vec3<T>{0, 1, 0});
    CHECK(quat::to_mrp(quaternion<T>{0, 0, -1, 0}) == vec3<T>{0, -1, 0});
    CHECK(quat::to_mrp(quaternion<T>{T(-0.0), 0, 0, 1}) == vec3<T>{0, 0, 1});
    const T nan = std::numeric_limits<T>::quiet_NaN();
    CHECK(std::isnan(quat::to_mrp(quaternion<T>{nan, 0, 0, 0}).x));
    CHECK(std::isnan(quat::to_mrp(quaternion<T>{0, 0, 0, 0}).x));
    CHECK(std::isnan(quat::to_mrp(quaternion<T>{1, std::numeric_limits<T>::infinity(), 0, 0}).x));
}

TEMPLATE_TEST_CASE("from_mrp is ((1 - |p|^2), 2 p) / (1 + |p|^2) for any p, huge ones included",
                   "[conversions][mrp]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 2000; ++n) {
        const vec3<T> p = random.unit_vector<T>() * random.uniform<T>(0, 10);
        const quaternion<T> q = quat::from_mrp(p);
        // Reference in long double.
        const long double n2 = static_cast<long double>(p.x) * p.x +
                               static_cast<long double>(p.y) * p.y +
                               static_cast<long double>(p.z) * p.z;
        const quaternion<long double> reference{(1 - n2) / (1 + n2), 2 * p.x / (1 + n2),
                                                2 * p.y / (1 + n2), 2 * p.z / (1 + n2)};
        CAPTURE(n, p.x, p.y, p.z);
        CHECK(quat::test::max_difference(quaternion<long double>{q.w, q.x, q.y, q.z}, reference) <=
              tolerance<T>::conversion);
        CHECK(std::abs(quat::norm(q) - 1) <= tolerance<T>::unit_norm);
        // |p| > 1 is the long way round to the rotation of its shadow -p / |p|^2, which to_mrp
        // gives.
        const vec3<T> back = quat::to_mrp(q);
        const T length2 = quat::squared_norm(p);
        const vec3<T> expected = length2 <= 1 ? p : -p / length2;
        CHECK(quat::test::max_difference(back, expected) <= tolerance<T>::round_trip);
        CHECK(quat::angle_between(quat::from_mrp(expected), q) <= tolerance<T>::round_trip);
    }
    CHECK(quat::from_mrp(vec3<T>{0, 0, 0}) == quaternion<T>::identity());
    CHECK(quat::from_mrp(vec3<T>{1, 0, 0}) == quaternion<T>{0, 1, 0, 0});  // half turn
    // Huge p: near -identity, also where |p|^2 overflows.
    const T max = std::numeric_limits<T>::max();
    for (const vec3<T>& p : {vec3<T>{T(1e19), 0, 0}, vec3<T>{T(1e30), T(-1e30), T(1e25)},
                             vec3<T>{max, max, max}, vec3<T>{-max, 0, 0}}) {
        const quaternion<T> q = quat::from_mrp(p);
        CAPTURE(p.x, p.y, p.z);
        CHECK(q.w == -1);
        CHECK(std::abs(q.x) <= 4 / std::abs(p.x));
        CHECK(std::isfinite(q.y));
    }
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    CHECK(std::isnan(quat::from_mrp(vec3<T>{nan, 0, 0}).w));
    CHECK(std::isnan(quat::from_mrp(vec3<T>{0, inf, 0}).w));
}

TEMPLATE_TEST_CASE("to_mrp and from_mrp are inverse on rotations", "[conversions][mrp]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 2000; ++n) {
        const quaternion<T> q = random.unit_quaternion<T>();
        const quaternion<T> back = quat::from_mrp(quat::to_mrp(q));
        CHECK(back.w >= 0);
        CHECK(quat::test::max_difference(back, q.w < 0 ? -q : q) <= tolerance<T>::round_trip);
    }
}

TEMPLATE_TEST_CASE("angle(q) and axis(q) are to_axis_angle(q).angle and .axis, bit for bit",
                   "[conversions][first-use]", float, double) {
    using T = TestType;
    using quat::test::same_bits;
    quat::test::random_rotations random;
    for (int n = 0; n < 5000; ++n) {
        // Any scale and either sign: the range is [0, pi], q and -q alike.
        const quaternion<T> q = random.unit_quaternion<T>() * random.uniform<T>(-4, 4);
        const axis_angle<T> long_form = quat::to_axis_angle(q);
        CHECK(same_bits(quat::angle(q), long_form.angle));
        CHECK(same_bits(quat::axis(q), long_form.axis));
        CHECK(quat::angle(q) >= 0);
        CHECK(quat::angle(q) <= quat::numbers::pi_v<T>);
        CHECK(same_bits(quat::angle(-q), quat::angle(q)));
        // Eigen's AngleAxis(q) has the same conventions: angle in [0, pi], axis flipped with q.
        const quaternion<T> u = quat::normalize(q);
        const Eigen::AngleAxis<T> e(Eigen::Quaternion<T>(u.w, u.x, u.y, u.z));
        CHECK(std::abs(e.angle() - quat::angle(u)) <= 64 * std::numeric_limits<T>::epsilon());
        const vec3<T> eigen_axis{e.axis().x(), e.axis().y(), e.axis().z()};
        CHECK(max_difference(eigen_axis, quat::axis(u)) <=
              64 * std::numeric_limits<T>::epsilon() / quat::angle(u));
    }
    CHECK(quat::angle(quaternion<T>::identity()) == 0);
    CHECK(quat::axis(quaternion<T>::identity()) == vec3<T>{1, 0, 0});
    CHECK(quat::axis(-quaternion<T>::identity()) == vec3<T>{1, 0, 0});
    CHECK(quat::angle(quaternion<T>{0, 0, 0, 2}) == quat::numbers::pi_v<T>);
    CHECK(quat::axis(quaternion<T>{0, 0, -3, 0}) == vec3<T>{0, -1, 0});
    CHECK(quat::angle(quaternion<T>{0, 0, 0, 0}) == 0);  // as to_axis_angle: angle 0, axis NaN
    CHECK(std::isnan(quat::axis(quaternion<T>{0, 0, 0, 0}).x));
    CHECK(std::isnan(quat::angle(quaternion<T>{1, std::numeric_limits<T>::infinity(), 0, 0})));
    CHECK(std::isnan(quat::axis(quaternion<T>{std::numeric_limits<T>::quiet_NaN(), 0, 0, 1}).x));
    static_assert(quat::angle(quat::quatd{0, 1, 0, 0}) == quat::numbers::pi);
    static_assert(quat::axis(quat::quatd{0, 0, 1, 0}) == vec3<double>{0, 1, 0});
}

TEMPLATE_TEST_CASE("to_axis_angle gives a unit axis for subnormal vector parts",
                   "[conversions][edge]", float, double) {
    using T = TestType;
    using L = std::numeric_limits<T>;
    // q = (1, d, d, 0) and (1, d, 2d, 0) with d subnormal: |(d, d, 0)| keeps only the few bits
    // of a subnormal, so dividing by it leaves the axis off unit length (the smallest subnormal
    // times sqrt(2) rounds to itself). Reference: the exact directions (1, 1, 0) / sqrt(2) and
    // (1, 2, 0) / sqrt(5), and the angle 2 atan(|v|) ~ 2 |v|, in long double.
    for (const T d : {L::denorm_min(), L::denorm_min() * T(3), L::min() / T(1024)}) {
        CAPTURE(d);
        for (const long double k : {1.0L, 2.0L}) {
            const quaternion<T> q{T(1), d, d * T(k), T(0)};
            const axis_angle<T> r = quat::to_axis_angle(q);
            const long double length = std::sqrt(1 + k * k);
            CHECK(std::abs(quat::norm(r.axis) - T(1)) <= 4 * L::epsilon());
            CHECK(std::abs(r.axis.x - 1 / length) <= 4 * L::epsilon());
            CHECK(std::abs(r.axis.y - k / length) <= 4 * L::epsilon());
            CHECK(r.axis.z == 0);
            // The angle is subnormal too: right to within the spacing of subnormals.
            const long double angle = 2 * static_cast<long double>(d) * length;
            CHECK(std::abs(static_cast<long double>(r.angle) - angle) <= 2 * L::denorm_min());
            CHECK(quat::axis(q) == r.axis);
        }
    }
}

TEMPLATE_TEST_CASE("from_rotation_vector is a unit quaternion for every finite vector",
                   "[conversions][edge]", float, double) {
    using T = TestType;
    using L = std::numeric_limits<T>;
    // Vectors whose |v|^2 overflows, with exact lengths: (3, 4, 0) 2^(e - 3) has length
    // 1.25 2^(e - 1), below max(); (8, 15, 0) 2^(e - 4) has length 17 2^(e - 4) = 1.0625 2^e,
    // above max() (the angle overflows, its half does not), components below max(). The
    // reference: cos and sin of the exact half angle in long double, whose range holds these.
    struct pythagorean {
        T a, b;
        long double length;
        int shift;
    };
    const int e = L::max_exponent;
    for (const pythagorean p : {pythagorean{3, 4, 5, e - 3}, pythagorean{8, 15, 17, e - 4}}) {
        const vec3<T> v{std::ldexp(p.a, p.shift), std::ldexp(p.b, p.shift), T(0)};
        const long double half = std::ldexp(p.length, p.shift) / 2;
        CAPTURE(v.x, v.y, half);
        REQUIRE(std::isfinite(v.y));
        const quaternion<T> q = quat::from_rotation_vector(v);
        const long double c = std::cos(half), s = std::sin(half);
        CHECK(std::abs(q.w - c) <= 4 * L::epsilon());
        CHECK(std::abs(q.x - s * p.a / p.length) <= 4 * L::epsilon());
        CHECK(std::abs(q.y - s * p.b / p.length) <= 4 * L::epsilon());
        CHECK(q.z == 0);
        CHECK(std::abs(quat::norm(q) - 1) <= 4 * L::epsilon());
    }
    // Every component at max(): the axis (1, 1, 1) / sqrt(3), a unit quaternion.
    const T largest = L::max();
    const quaternion<T> q = quat::from_rotation_vector(vec3<T>{largest, largest, -largest});
    CHECK(std::abs(quat::norm(q) - 1) <= 4 * L::epsilon());
    CHECK(q.x == q.y);
    CHECK(q.z == -q.y);
    // NaN and infinities stay NaN.
    CHECK(std::isnan(quat::from_rotation_vector(vec3<T>{L::infinity(), 0, 0}).w));
    CHECK(std::isnan(quat::from_rotation_vector(vec3<T>{L::quiet_NaN(), 1, 0}).x));
}

}  // namespace test_conversions
