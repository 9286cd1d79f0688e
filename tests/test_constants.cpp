// Specification of constants.hpp: pi as <numbers> has it, in every language mode.
#include <cmath>
#include <type_traits>
#if __has_include(<numbers>)
#include <numbers>
#endif

#include <quat/constants.hpp>

#include "support/catch.hpp"

static_assert(std::is_same_v<decltype(quat::pi), const double>);
static_assert(quat::pi == 3.141592653589793);
static_assert(quat::pi_v<float> == 3.14159265f);
static_assert(quat::pi_v<double> == quat::pi);
#if defined(__cpp_lib_math_constants)
static_assert(quat::pi_v<float> == std::numbers::pi_v<float>);
static_assert(quat::pi_v<double> == std::numbers::pi);
static_assert(quat::pi_v<long double> == std::numbers::pi_v<long double>);
#endif

TEMPLATE_TEST_CASE("pi_v<T> is pi correctly rounded to T", "[constants]", float, double,
                   long double) {
    using T = TestType;
    const long double reference = std::acos(-1.0L);  // pi to long double precision
    const T nearest = static_cast<T>(reference);
    CHECK(quat::pi_v<T> == nearest);
    // Nothing nearer: the neighbours are further from pi than the constant is.
    CHECK(std::abs(static_cast<long double>(std::nextafter(quat::pi_v<T>, T(4))) - reference) >
          std::abs(static_cast<long double>(quat::pi_v<T>) - reference));
    CHECK(std::abs(static_cast<long double>(std::nextafter(quat::pi_v<T>, T(3))) - reference) >
          std::abs(static_cast<long double>(quat::pi_v<T>) - reference));
}
