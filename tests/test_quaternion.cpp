// Specification of quaternion.hpp: Hamilton's algebra and rotating vectors with it.
#include <cmath>
#include <limits>
#include <type_traits>

#include <quat/quaternion.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

using quat::quatd;
using quat::quaternion;
using quat::vec3;

namespace {
constexpr quatd one{1, 0, 0, 0}, i{0, 1, 0, 0}, j{0, 0, 1, 0}, k{0, 0, 0, 1};
}  // namespace

static_assert(std::is_trivially_default_constructible_v<quatd>, "a plain struct");
static_assert(std::is_constructible_v<quatd, quat::quatf> && !std::is_convertible_v<quat::quatf, quatd>,
              "precisions convert explicitly only");
static_assert(std::is_trivially_copyable_v<quat::quatf>);
static_assert(std::is_nothrow_default_constructible_v<quatd>);
static_assert(quatd::identity() == one);
// Hamilton's rules (thesis 2.16): i^2 = j^2 = k^2 = ijk = -1, ij = k, jk = i, ki = j and anti-commuting.
static_assert(i * i == -one && j * j == -one && k * k == -one && i * j * k == -one);
static_assert(i * j == k && j * k == i && k * i == j);
static_assert(j * i == -k && k * j == -i && i * k == -j);
static_assert(quat::conjugate(quatd{1, 2, 3, 4}) == quatd{1, -2, -3, -4});
static_assert(quat::squared_norm(quatd{1, 2, 3, 4}) == 30);
static_assert(quat::inverse(quatd{0, 0, 2, 0}) == quatd{0, 0, -0.5, 0}, "q* / |q|^2, not q* / |q|");

TEMPLATE_TEST_CASE("the product is associative and distributive but not commutative",
                   "[quaternion]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        const auto a = random.unit_quaternion<T>(), b = random.unit_quaternion<T>(),
                   c = random.unit_quaternion<T>();
        CHECK(quat::test::max_difference((a * b) * c, a * (b * c)) <=
              quat::test::tolerance<T>::product);
        CHECK(quat::test::max_difference(a * (b + c), a * b + a * c) <=
              quat::test::tolerance<T>::product);
    }
    CHECK(i * j != j * i);
}

TEMPLATE_TEST_CASE("inverse and conjugate", "[quaternion]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        const quaternion<T> q = random.unit_quaternion<T>() * random.uniform<T>(0.1, 10);
        CHECK(quat::test::max_difference(q * quat::inverse(q), quaternion<T>::identity()) <=
              quat::test::tolerance<T>::product);
        CHECK(quat::test::max_difference(quat::inverse(q) * q, quaternion<T>::identity()) <=
              quat::test::tolerance<T>::product);
        const quaternion<T> u = quat::normalize(q);
        CHECK(quat::test::max_difference(quat::inverse(u), quat::conjugate(u)) <=
              quat::test::tolerance<T>::product);
    }
}

TEMPLATE_TEST_CASE("normalize works from subnormal to huge components", "[quaternion]", float,
                   double) {
    using T = TestType;
    for (const T scale : {std::numeric_limits<T>::denorm_min() * 8, std::numeric_limits<T>::min(),
                          T(1e-20), T(1), T(1e20), std::numeric_limits<T>::max() / 2}) {
        const quaternion<T> q = quat::normalize(quaternion<T>{scale, scale, scale, scale});
        CAPTURE(scale);
        CHECK(std::abs(quat::norm(q) - 1) <= quat::test::tolerance<T>::unit_norm);
        CHECK(q.w == Approx(0.5));
    }
}

TEMPLATE_TEST_CASE("checked normalize and inverse reject what they cannot handle", "[quaternion]",
                   float, double) {
    using T = TestType;
    const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    CHECK_FALSE(quat::try_normalize(quaternion<T>{0, 0, 0, 0}).has_value());
    CHECK_FALSE(quat::try_normalize(quaternion<T>{nan, 1, 0, 0}).has_value());
    CHECK_FALSE(quat::try_normalize(quaternion<T>{1, inf, 0, 0}).has_value());
    CHECK_FALSE(quat::try_inverse(quaternion<T>{0, 0, 0, 0}).has_value());
    CHECK_FALSE(quat::try_inverse(quaternion<T>{nan, 0, 0, 0}).has_value());
    CHECK(quat::try_normalize(quaternion<T>{0, 0, 3, 4}) == quaternion<T>{0, 0, T(0.6), T(0.8)});
    CHECK(quat::try_inverse(quaternion<T>{2, 0, 0, 0}) == quaternion<T>{T(0.5), 0, 0, 0});
}

TEMPLATE_TEST_CASE("rotate(q, v) is q (0, v) q* and a * b applies b first", "[quaternion]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        const auto a = random.unit_quaternion<T>(), b = random.unit_quaternion<T>();
        const vec3<T> v = random.vector<T>();
        const quaternion<T> p = a * quaternion<T>{0, v.x, v.y, v.z} * quat::conjugate(a);
        const vec3<T> r = quat::rotate(a, v);
        CHECK(quat::test::max_difference(r, vec3<T>{p.x, p.y, p.z}) <=
              quat::test::tolerance<T>::rotate * 4);
        CHECK(std::abs(quat::norm(r) - quat::norm(v)) <=
              quat::test::tolerance<T>::rotate * quat::norm(v));
        CHECK(quat::test::max_difference(quat::rotate(a * b, v),
                                         quat::rotate(a, quat::rotate(b, v))) <=
              quat::test::tolerance<T>::rotate * 4);
        CHECK(quat::test::max_difference(quat::rotate(-a, v), r) <=
              quat::test::tolerance<T>::rotate * 4);
    }
}

TEST_CASE("a positive angle turns counter-clockwise seen from the axis tip", "[quaternion]") {
    const double h = std::sqrt(0.5);
    const quatd quarter_turn_about_z{h, 0, 0, h};
    const vec3<double> r = quat::rotate(quarter_turn_about_z, vec3<double>{1, 0, 0});
    CHECK(r.x == Approx(0).margin(1e-15));
    CHECK(r.y == Approx(1));
}

TEMPLATE_TEST_CASE("angle_between ignores sign and is accurate for nearby rotations",
                   "[quaternion]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    const auto q = random.unit_quaternion<T>();
    CHECK(quat::angle_between(q, -q) == 0);
    const T tiny = T(100) * std::sqrt(std::numeric_limits<T>::epsilon());
    const quaternion<T> turn{std::cos(tiny / 2), std::sin(tiny / 2), 0, 0};
    CHECK(quat::angle_between(q, q * turn) == Approx(tiny).epsilon(1e-3));
    const quaternion<T> half{0, 1, 0, 0};
    CHECK(quat::angle_between(quaternion<T>::identity(), half) == Approx(quat::pi_v<T>));
}
