// docs/integration.md "Names after using namespace quat": quat's constants live in quat::numbers,
// nested as the standard's are in std::numbers, so `using namespace quat;` brings no `pi` into
// scope. A program (a port of GLM's own tests, say) that has a global `pi` of its own keeps it:
// unqualified `pi` is the user's, `numbers::pi` is quat's. Before the constants were nested, the
// using-directive made every unqualified `pi` here ambiguous and this file did not compile.
//
// The user's pi is a float that differs from quat's in its value and type, so the checks below
// tell the two apart: a mix-up fails a static_assert, not only a tolerance.
#include <type_traits>

#include <quat/quat.hpp>

#include "support/catch.hpp"

// The user's own constant, at global scope, before and after the using-directive.
constexpr float pi = 3.14159f;

namespace test_namespaces {

using namespace quat;  // NOLINT(google-build-using-namespace): the case under test

namespace {

constexpr float half_turn_of_user = pi;                // the user's pi
constexpr double half_turn_of_quat = numbers::pi;      // quat::numbers::pi
constexpr float quat_pi_float = numbers::pi_v<float>;  // quat::numbers::pi_v<float>

}  // namespace

// Unqualified pi is the global float; numbers::pi is quat's double.
static_assert(std::is_same_v<decltype(pi), const float>);
static_assert(half_turn_of_user == 3.14159f);
static_assert(std::is_same_v<decltype(numbers::pi), const double>);
static_assert(numbers::pi == ::quat::numbers::pi_v<double>);
static_assert(half_turn_of_quat == 3.141592653589793);
static_assert(quat_pi_float == 3.14159265f);
static_assert(static_cast<double>(half_turn_of_user) != half_turn_of_quat);

TEST_CASE("A global pi of the user's stays unambiguous after using namespace quat",
          "[namespaces]") {
    // Inside a function as at file scope: pi is the user's float, so rotation_z takes the scalar
    // type from it and gives a quatf; numbers::pi gives a quatd (rotation_z follows its argument).
    const auto by_user_pi = rotation_z(pi);
    const auto by_quat_pi = rotation_z(numbers::pi);
    STATIC_REQUIRE(std::is_same_v<decltype(by_user_pi), const quatf>);
    STATIC_REQUIRE(std::is_same_v<decltype(by_quat_pi), const quatd>);
    CHECK(by_user_pi == ::quat::rotation_z(::pi));
    CHECK(by_quat_pi == ::quat::rotation_z(::quat::numbers::pi));

    // A local using-directive changes nothing: quat still declares no pi of its own.
    using namespace quat::numbers;  // NOLINT(google-build-using-namespace)
    const double local_numbers_pi = pi_v<double>;
    CHECK(local_numbers_pi == ::quat::numbers::pi);
}

}  // namespace test_namespaces
