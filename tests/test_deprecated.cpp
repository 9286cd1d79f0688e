// The spellings deprecated in 1.1.0 (docs/conventions.md, "Deprecated names") still compile and
// give exactly the results of their replacements until they are removed in 2.0.0. Warnings are
// errors in the build, so this file alone silences the deprecation warning, around its uses.
#include <quat/lie/se3.hpp>
#include <quat/lie/so3.hpp>
#include <quat/quat.hpp>

#include "support/catch.hpp"

namespace test_deprecated {

namespace {

using namespace quat;

}  // namespace

#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif

TEST_CASE("so3::plus_left(w, x) is plus_left(x, w), Jacobians included", "[deprecated][so3]") {
    const quaternion<double> x = normalize(quaternion<double>{0.9, -0.2, 0.3, 0.25});
    const vec3<double> w{0.4, -1.1, 2.3};
    matrix3<double> new_x{}, new_w{}, old_x{}, old_w{};
    const quaternion<double> expected = so3::plus_left(x, w, &new_x, &new_w);
    CHECK(so3::plus_left(w, x) == expected);
    CHECK(so3::plus_left(w, x, &old_w, &old_x) == expected);
    CHECK(old_x == new_x);
    CHECK(old_w == new_w);
}

TEST_CASE("se3::plus_left(t, x) is plus_left(x, t), Jacobians included", "[deprecated][se3]") {
    const dual_quaternion<double> x = to_dual_quaternion(
        normalize(quaternion<double>{0.9, -0.2, 0.3, 0.25}), vec3<double>{1.5, -0.5, 2.0});
    const se3::twist<double> t{{0.3, 0.7, -1.2}, {0.4, -1.1, 2.3}};
    matrix6<double> new_x{}, new_t{}, old_x{}, old_t{};
    const dual_quaternion<double> expected = se3::plus_left(x, t, &new_x, &new_t);
    CHECK(se3::plus_left(t, x) == expected);
    CHECK(se3::plus_left(t, x, &old_t, &old_x) == expected);
    CHECK(old_x == new_x);
    CHECK(old_t == new_t);
}

TEST_CASE("se3::rotation_matrix_of is so3::adjoint of the rotation, to_matrix's numbers",
          "[deprecated][se3]") {
    const dual_quaternion<double> x = to_dual_quaternion(
        normalize(quaternion<double>{0.9, -0.2, 0.3, 0.25}), vec3<double>{1.5, -0.5, 2.0});
    CHECK(se3::rotation_matrix_of(x) == so3::adjoint(x.real));
    CHECK(se3::rotation_matrix_of(x) == to_matrix3(to_matrix(rotation_of(x))));
}

#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic pop
#endif

}  // namespace test_deprecated
