// Specification of vec3.hpp: the vector algebra rotations are built on.
#include <cmath>
#include <limits>
#include <type_traits>

#include <quat/vec3.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_vec3 {

using quat::vec3;

static_assert(std::is_trivially_default_constructible_v<vec3<double>>, "a plain struct");
static_assert(std::is_constructible_v<vec3<double>, vec3<float>> &&
                  !std::is_convertible_v<vec3<float>, vec3<double>>,
              "precisions convert explicitly only");
static_assert(std::is_trivially_copyable_v<vec3<float>>);
static_assert(quat::cross(vec3<double>{1, 0, 0}, vec3<double>{0, 1, 0}) == vec3<double>{0, 0, 1},
              "right-handed: x cross y = z");
static_assert(quat::cross(vec3<double>{0, 1, 0}, vec3<double>{0, 0, 1}) == vec3<double>{1, 0, 0});
static_assert(quat::dot(vec3<int>{1, 2, 3}, vec3<int>{4, 5, 6}) == 32);
static_assert(vec3<double>{1, 2, 3} * 2.0 == 2.0 * vec3<double>{1, 2, 3});
static_assert(-vec3<double>{1, -2, 3} == vec3<double>{-1, 2, -3});
static_assert(quat::norm(vec3<double>{3, 4, 12}) == 13, "norm is usable in constant expressions");

TEMPLATE_TEST_CASE("norm neither overflows nor underflows", "[vec3]", float, double) {
    using T = TestType;
    const T huge = std::numeric_limits<T>::max() / 4,
            tiny = std::numeric_limits<T>::denorm_min() * 4;
    CHECK(quat::norm(vec3<T>{huge, huge, T(0)}) == Approx(huge * std::sqrt(T(2))));
    CHECK(quat::norm(vec3<T>{tiny, T(0), T(0)}) == tiny);
    const vec3<T> n = quat::normalize(vec3<T>{T(0), huge, huge});
    CHECK(n.y == Approx(std::sqrt(T(0.5))));
}

TEMPLATE_TEST_CASE("try_normalize rejects the zero vector and non-finite input", "[vec3]", float,
                   double) {
    using T = TestType;
    CHECK_FALSE(quat::try_normalize(vec3<T>{0, 0, 0}).has_value());
    CHECK_FALSE(
        quat::try_normalize(vec3<T>{std::numeric_limits<T>::quiet_NaN(), 1, 0}).has_value());
    CHECK_FALSE(quat::try_normalize(vec3<T>{std::numeric_limits<T>::infinity(), 1, 0}).has_value());
    const auto unit = quat::try_normalize(vec3<T>{0, 0, 5});
    REQUIRE(unit.has_value());
    CHECK(*unit == vec3<T>{0, 0, 1});
}

TEST_CASE("a scalar beside a vec3 converts to its precision", "[vec3][first-use]") {
    const vec3<float> v{1.5f, -2.25f, 0.1f};
    CHECK(v * 2 == v * 2.0f);
    CHECK(2 * v == 2.0f * v);
    CHECK(v * 0.1 == v * 0.1f);  // a double literal rounds to float first, like float(0.1)
    CHECK(0.1 * v == 0.1f * v);
    CHECK(v / 3 == v / 3.0f);
    static_assert(std::is_same_v<decltype(v * 2.0), vec3<float>>, "no promotion to double");
}

TEST_CASE("compound assignment on vec3", "[vec3][first-use]") {
    vec3<double> v{1, 2, 3};
    const vec3<double> w{0.5, -1, 4};
    v += w;
    CHECK(v == vec3<double>{1.5, 1, 7});
    v -= w;
    CHECK(v == vec3<double>{1, 2, 3});
    v *= 2;
    CHECK(v == vec3<double>{2, 4, 6});
    v /= 4;
    CHECK(v == vec3<double>{0.5, 1, 1.5});
    static_assert(std::is_same_v<decltype(v += w), vec3<double>&>);
}

TEST_CASE("vec3 converts explicitly between precisions, component by component",
          "[vec3][first-use]") {
    const vec3<double> d{0.1, -1e-3, 1e30};
    const vec3<float> f{d};
    CHECK(f == vec3<float>{0.1f, -1e-3f, 1e30f});
    CHECK(vec3<double>{f}.x == static_cast<double>(0.1f));
    constexpr vec3<float> folded{vec3<double>{1, 2, 3}};
    static_assert(folded == vec3<float>{1, 2, 3});
}

TEST_CASE("v[i] reads and writes x, y, z", "[vec3][first-use]") {
    vec3<double> v{1, 2, 3};
    CHECK(v[0] == 1);
    CHECK(v[1] == 2);
    CHECK(v[2] == 3);
    v[1] = -5;
    CHECK(v.y == -5);
    CHECK(&v[2] == &v.z);  // a reference to the member, not a copy
    const vec3<float> c{4, 5, 6};
    CHECK(&c[0] == &c.x);
    static_assert(vec3<int>{7, 8, 9}[2] == 9, "usable in constant expressions");
    static_assert(std::is_same_v<decltype(c[0]), const float&>);
    static_assert(std::is_same_v<decltype(v[0]), double&>);
    // An index of 3 or more is a precondition violation, stopped by QUAT_ASSERT in debug builds
    // (tests/contracts/assert_checks.cpp, case vec3_index).
}

TEMPLATE_TEST_CASE("lerp of points is std::lerp component by component, exact at both ends",
                   "[vec3][first-use]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 5000; ++n) {
        const vec3<T> a = random.vector<T>(10), b = random.vector<T>(10);
        CHECK(quat::lerp(a, b, T(0)) == a);
        CHECK(quat::lerp(a, b, T(1)) == b);
        CHECK(quat::lerp(a, a, random.uniform<T>(-2, 3)) == a);
        // Monotonic: a larger t never moves a component back.
        const T t = random.uniform<T>(-1, 2), later = std::nextafter(t, T(3));
        const vec3<T> p = quat::lerp(a, b, t), q = quat::lerp(a, b, later);
        CHECK((b.x >= a.x ? q.x >= p.x : q.x <= p.x));
        CHECK((b.y >= a.y ? q.y >= p.y : q.y <= p.y));
        CHECK((b.z >= a.z ? q.z >= p.z : q.z <= p.z));
        CHECK(quat::test::max_difference(p, a + (b - a) * t) <=
              4 * quat::test::eps<T> * (quat::norm(a) + quat::norm(b)) * (1 + std::abs(t)));
#if defined(__cpp_lib_interpolate)
        // The same bits as std::lerp (C++20) on each component, extrapolation included.
        CHECK(p.x == std::lerp(a.x, b.x, t));
        CHECK(p.y == std::lerp(a.y, b.y, t));
        CHECK(p.z == std::lerp(a.z, b.z, t));
#endif
    }
    static_assert(quat::lerp(vec3<double>{0, 2, -4}, vec3<double>{1, 4, 4}, 0.5) ==
                  vec3<double>{0.5, 3, 0});
    static_assert(
        std::is_same_v<decltype(quat::lerp(vec3<float>{}, vec3<float>{}, 0.5)), vec3<float>>,
        "t converts to the points' precision");
}

}  // namespace test_vec3
