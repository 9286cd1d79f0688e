// Specification of vec3.hpp: the vector algebra rotations are built on.
#include <limits>
#include <type_traits>

#include <quat/vec3.hpp>

#include "support/catch.hpp"

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
