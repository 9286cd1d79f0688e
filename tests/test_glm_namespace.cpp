// docs/integration.md "With GLM in the same file": after `using namespace glm;` the name quat is
// ambiguous (glm::quat, a type, against namespace quat), so code that uses both libraries writes
// ::quat:: or a namespace alias. This file is such code: GLM's headers and the using-directive come
// first, quat's headers after them, at file scope, and both documented spellings are used. So
// quat's own headers must never name their namespace as `quat::` either (clang rejects that here).
// That the unqualified spelling does not compile is checked by CTest
// glm_unqualified_quat_is_ambiguous (clang builds; tests/compile_fail/glm_unqualified_quat.cpp).
//
// The second test case adds `using namespace quat;`: then vec3, euler, radians and degrees are
// ambiguous too (checked by the CTest tests glm_and_quat_unqualified_*_is_ambiguous, both
// compilers; tests/compile_fail/glm_and_quat_*.cpp), and every other name resolves by its
// arguments' types.
//
// GLM's constructor takes the scalar first, glm::quat(w, x, y, z), like quat's {w, x, y, z} (GLM
// stores x, y, z, w in memory); both use Hamilton's product and active rotations, so the same four
// numbers are the same rotation in both libraries.
#include <cmath>

#include "support/catch.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>
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

    // Both rotate a vector alike, and quat's four numbers fed to GLM's (w, x, y, z) constructor
    // give GLM the same rotation.
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

// ---- using namespace glm; using namespace quat; ------------------------------------------------
// The second using-directive sits in a namespace of this file's own: for names looked up inside it,
// quat's members then appear at global scope beside glm's (the nearest namespace enclosing both),
// so
// lookup sees exactly what it sees after both directives at file scope.
namespace with_both_directives {

using namespace quat;  // NOLINT(google-build-using-namespace): the case under test

TEST_CASE("After using namespace glm and using namespace quat, the documented spellings work",
          "[glm][namespace]") {
    // Ambiguous names, qualified: vec3, euler, radians, degrees (and quat itself, see above).
    const ::quat::vec3<double> x{1, 0, 0};
    const qt::vec3<double> y{0, 1, 0};
    const glm::dvec3 glm_x(1, 0, 0);
    const ::quat::euler<double> yaw_quarter{::quat::radians(90.0), 0, 0};
    CHECK(::quat::radians(90.0) == glm::radians(90.0));
    CHECK(::quat::degrees(0.5) == glm::degrees(0.5));
    CHECK(glm::euler<double>() == 0.5772156649015329);  // GLM's: the Euler-Mascheroni constant

    // A name only one library has needs nothing: quatd, to_quaternion, rotation_z, to_glm, dquat.
    const quatd q = to_quaternion(yaw_quarter);
    const quatd r = rotation_z(0.3);
    const dquat g = to_glm(q);
    CHECK(max_difference(g * glm_x, rotate(q, x)) <= tolerance);
    CHECK(max_difference(glm_x, ::quat::vec3<double>{1, 0, 0}) == 0);
    CHECK(rotate(q, x).y == ::quat::rotate(q, x).y);

    // Names both libraries have, called with quat's types: quat's function, the same result as the
    // qualified call.
    CHECK(normalize(::quat::quatd{1, 1, 0, 0}) == ::quat::normalize(::quat::quatd{1, 1, 0, 0}));
    CHECK(normalize(x + y) == ::quat::normalize(x + y));
    CHECK(dot(q, r) == ::quat::dot(q, r));
    CHECK(dot(x, y) == ::quat::dot(x, y));
    CHECK(cross(x, y) == ::quat::cross(x, y));
    CHECK(inverse(q) == ::quat::inverse(q));
    CHECK(conjugate(q) == ::quat::conjugate(q));
    CHECK(transpose(to_matrix(q)) == ::quat::transpose(to_matrix(q)));
    CHECK(determinant(to_matrix(q)) == ::quat::determinant(to_matrix(q)));
    CHECK(slerp(q, r, 0.25) == ::quat::slerp(q, r, 0.25));
    CHECK(squad(q, r, q, r, 0.25) == ::quat::squad(q, r, q, r, 0.25));
    CHECK(pow(q, 0.5) == ::quat::pow(q, 0.5));
    CHECK(rotate(q, y) == ::quat::rotate(q, y));
    CHECK(q * y == ::quat::rotate(q, y));
    CHECK(angle(q) == ::quat::angle(q));
    CHECK(axis(q) == ::quat::axis(q));
    CHECK(exp(log(q)) == ::quat::exp(::quat::log(q)));
    CHECK(lerp(x, y, 0.25) == ::quat::lerp(x, y, 0.25));

    // The same names with GLM's types: GLM's function.
    const dquat h = angleAxis(0.3, glm::dvec3(0, 0, 1));
    CHECK(normalize(glm::dvec3(1, 1, 0)) == glm::normalize(glm::dvec3(1, 1, 0)));
    CHECK(dot(g, h) == glm::dot(g, h));
    CHECK(cross(glm_x, glm::dvec3(0, 1, 0)) == glm::cross(glm_x, glm::dvec3(0, 1, 0)));
    CHECK(inverse(g) == glm::inverse(g));
    CHECK(slerp(g, h, 0.25) == glm::slerp(g, h, 0.25));
    CHECK(angle(g) == glm::angle(g));
    CHECK(axis(g) == glm::axis(g));
    CHECK(transpose(glm::dmat3(1.0)) == glm::transpose(glm::dmat3(1.0)));
    CHECK(rotate(glm::dmat4(1.0), 0.3, glm::dvec3(0, 0, 1)) ==
          glm::rotate(glm::dmat4(1.0), 0.3, glm::dvec3(0, 0, 1)));

    // Block-scope using-declarations hide the nominated names: here vec3, euler and radians are
    // quat's, unqualified. (At global scope a using-declaration would not help: it would meet
    // glm's names in the same scope and be ambiguous again.)
    {
        using ::quat::euler;
        using ::quat::radians;
        using ::quat::vec3;
        const vec3<double> v{1, 0, 0};
        const euler<double> e{radians(90.0), 0, 0};
        CHECK(to_quaternion(e) == q);
        CHECK(rotate(to_quaternion(e), v) == rotate(q, x));
    }
}

}  // namespace with_both_directives
