// README "With GLM in the same file": after `using namespace glm;` the name quat is ambiguous
// (glm::quat, a type, against namespace quat), so code that uses both libraries writes ::quat::
// or a namespace alias. This file is such code: GLM's headers and the using-directive come first,
// quat's headers after them, at file scope, and both documented spellings are used. So quat's own
// headers must never name their namespace as `quat::` either (clang rejects that here). That the
// unqualified spelling does not compile is checked by CTest glm_unqualified_quat_is_ambiguous
// (clang builds; tests/compile_fail/glm_unqualified_quat.cpp).
//
// GLM's constructor takes the scalar first, glm::quat(w, x, y, z), like quat's {w, x, y, z} (GLM
// stores x, y, z, w in memory); both use Hamilton's product and active rotations, so the same four
// numbers are the same rotation in both libraries.
#include <cmath>

#include "support/catch.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

using namespace glm;  // NOLINT(google-build-using-namespace): the case under test

#include <quat/interop/glm.hpp>
#include <quat/quat.hpp>

namespace qt = ::quat;

namespace {

double max_difference(const dvec3& a, const ::quat::vec3<double>& b) {
    return std::fmax(std::fabs(a.x - b.x), std::fmax(std::fabs(a.y - b.y), std::fabs(a.z - b.z)));
}

constexpr double tolerance = 64 * 2.220446049250313e-16;  // GLM rounds differently

}  // namespace

TEST_CASE("After using namespace glm, ::quat:: and a namespace alias name quat",
          "[glm][namespace]") {
    const double angle = 0.7;
    const dvec3 glm_axis = normalize(dvec3(1, -2, 3));  // glm::normalize, found unqualified
    const ::quat::vec3<double> axis{glm_axis.x, glm_axis.y, glm_axis.z};

    // The same rotation built by each library from axis and angle.
    const ::quat::quatd q = ::quat::to_quaternion(::quat::axis_angle<double>{axis, angle});
    const qt::quatd same = qt::to_quaternion(qt::axis_angle<double>{axis, angle});
    const dquat g = angleAxis(angle, glm_axis);  // glm::dquat, glm::angleAxis
    CHECK(q == same);
    CHECK(std::fabs(g.w - q.w) <= tolerance);
    CHECK(std::fabs(g.x - q.x) <= tolerance);
    CHECK(std::fabs(g.y - q.y) <= tolerance);
    CHECK(std::fabs(g.z - q.z) <= tolerance);

    // Both rotate a vector alike, and quat's four numbers fed to GLM's (w, x, y, z) constructor give
    // GLM the same rotation.
    const dvec3 v(0.25, 1.5, -2.0);
    const ::quat::vec3<double> quat_v{v.x, v.y, v.z};
    const qt::vec3<double> rotated = qt::rotate(same, quat_v);
    CHECK(max_difference(g * v, rotated) <= tolerance * 4);
    CHECK(max_difference(dquat(q.w, q.x, q.y, q.z) * v, ::quat::rotate(q, quat_v)) <=
          tolerance * 4);

    // The interop header converts by name, so it builds the same glm::dquat.
    const dquat converted = ::quat::to_glm(q);
    CHECK(converted == dquat(q.w, q.x, q.y, q.z));
    CHECK(qt::from_glm(converted) == q);

    // A quarter turn about z takes x to y in both (active, counter-clockwise).
    const qt::quatd quarter =
        qt::to_quaternion(qt::axis_angle<double>{{0, 0, 1}, 1.5707963267948966});
    const dvec3 turned = dquat(quarter.w, quarter.x, quarter.y, quarter.z) * dvec3(1, 0, 0);
    CHECK(max_difference(turned, qt::rotate(quarter, qt::vec3<double>{1, 0, 0})) <= tolerance);
    CHECK(std::fabs(turned.y - 1) <= tolerance);
}
