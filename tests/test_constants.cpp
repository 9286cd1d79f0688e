// Specification of constants.hpp: pi as <numbers> has it, in every language mode; radians and
// degrees as GLM has them.
#include <cmath>
#include <limits>
#include <type_traits>
#if __has_include(<numbers>)
#include <numbers>
#endif

#include <glm/trigonometric.hpp>
#include <quat/constants.hpp>

#include "support/catch.hpp"

namespace test_constants {

static_assert(std::is_same_v<decltype(quat::numbers::pi), const double>);
static_assert(quat::numbers::pi == 3.141592653589793);
static_assert(quat::numbers::pi_v<float> == 3.14159265f);
static_assert(quat::numbers::pi_v<double> == quat::numbers::pi);
#if defined(__cpp_lib_math_constants)
static_assert(quat::numbers::pi_v<float> == std::numbers::pi_v<float>);
static_assert(quat::numbers::pi_v<double> == std::numbers::pi);
static_assert(quat::numbers::pi_v<long double> == std::numbers::pi_v<long double>);
#endif

TEMPLATE_TEST_CASE("pi_v<T> is pi correctly rounded to T", "[constants]", float, double,
                   long double) {
    using T = TestType;
    const long double reference = std::acos(-1.0L);  // pi to long double precision
    const T nearest = static_cast<T>(reference);
    CHECK(quat::numbers::pi_v<T> == nearest);
    // Nothing nearer: the neighbours are further from pi than the constant is.
    CHECK(std::abs(static_cast<long double>(std::nextafter(quat::numbers::pi_v<T>, T(4))) -
                   reference) >
          std::abs(static_cast<long double>(quat::numbers::pi_v<T>) - reference));
    CHECK(std::abs(static_cast<long double>(std::nextafter(quat::numbers::pi_v<T>, T(3))) -
                   reference) >
          std::abs(static_cast<long double>(quat::numbers::pi_v<T>) - reference));
}

// radians and degrees: float in, float out; an integer gives a double; usable in constant
// expressions; in namespace quat, not quat::numbers.
static_assert(std::is_same_v<decltype(quat::radians(90.0f)), float>);
static_assert(std::is_same_v<decltype(quat::radians(90.0)), double>);
static_assert(std::is_same_v<decltype(quat::radians(90)), double>);
static_assert(std::is_same_v<decltype(quat::degrees(1.0L)), long double>);
static_assert(std::is_same_v<decltype(quat::degrees(1)), double>);
static_assert(quat::radians(180.0) == quat::numbers::pi);
static_assert(quat::radians(0) == 0.0 && quat::degrees(0.0f) == 0.0f);
static_assert(quat::radians(-90) == -quat::numbers::pi / 2);

TEMPLATE_TEST_CASE("radians and degrees multiply by the correctly rounded pi / 180 and 180 / pi",
                   "[constants][first-use]", float, double, long double) {
    using T = TestType;
    const long double pi = std::acos(-1.0L);
    const T per_degree = static_cast<T>(pi / 180), per_radian = static_cast<T>(180 / pi);
    for (int d = -720; d <= 720; d += 5) {
        const T x = T(d) + T(0.25);
        CHECK(quat::radians(x) == x * per_degree);
        CHECK(quat::degrees(x) == x * per_radian);
        // Within half an ulp of the factor and one rounding of the product.
        const long double exact = static_cast<long double>(x) * pi / 180;
        CHECK(std::abs(static_cast<long double>(quat::radians(x)) - exact) <=
              2 * std::numeric_limits<T>::epsilon() * std::abs(exact));
    }
    // radians(180) is pi to within an ulp (constants.hpp); exactly pi for float, double and x87's
    // 64-bit long double, one ulp below it for IEEE binary128 long double (AArch64).
    if constexpr (std::numeric_limits<T>::digits <= 64) {
        CHECK(quat::radians(T(180)) == quat::numbers::pi_v<T>);
    } else {
        const T pi_t = quat::numbers::pi_v<T>;
        CHECK(std::abs(quat::radians(T(180)) - pi_t) <= std::nextafter(pi_t, T(4)) - pi_t);
    }
    CHECK(quat::degrees(quat::numbers::pi_v<T>) ==
          Approx(T(180)).epsilon(std::numeric_limits<T>::epsilon()));
}

TEMPLATE_TEST_CASE("radians and degrees agree with glm::radians and glm::degrees",
                   "[constants][glm]", float, double) {
    using T = TestType;
    for (int d = -3600; d <= 3600; ++d) {
        const T x = T(d) / T(10);
        // The same factor rounded to T for double; GLM rounds its float factor from a double
        // literal, at most one ulp apart.
        CHECK(quat::radians(x) ==
              Approx(glm::radians(x)).epsilon(std::numeric_limits<T>::epsilon()).margin(0));
        CHECK(quat::degrees(x) ==
              Approx(glm::degrees(x)).epsilon(std::numeric_limits<T>::epsilon()).margin(0));
    }
    CHECK(quat::radians(123.0) == glm::radians(123.0));
    CHECK(quat::degrees(2.5) == glm::degrees(2.5));
}

}  // namespace test_constants
