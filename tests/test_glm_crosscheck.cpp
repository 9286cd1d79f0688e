// Cross-check against GLM 0.9.9 on thousands of seeded random inputs.
//
// How GLM's conventions map to quat's:
// - glm::quat(w, x, y, z) takes the scalar first like quat::quaternion{w, x, y, z}, but stores
//   x, y, z, w in memory; both use Hamilton's product and q v q* for rotation, so products and
//   rotate agree directly.
// - glm::mat3 is column-major: glm_matrix[col][row] == quat_matrix(row, col).
// - glm::angleAxis(angle, axis) == to_quaternion(axis_angle{axis, angle}).
// - glm::eulerAngles(q) returns (pitch, yaw, roll) = the angles about x, y and z of
//   R = Rz(roll) Ry(yaw) Rx(pitch), i.e. quat::euler<T, sequence::zyx>{roll, yaw, pitch}.
// - glm::log(q) of a unit q with w >= 0 is (0, angle/2 * axis): to_rotation_vector(q) / 2.
//   glm::exp((0, u)) is from_rotation_vector(2 u).
// - glm::slerp(a, b, t) takes the shorter arc like quat::slerp (glm::mix does not flip).
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>
#include <quat/interop/glm.hpp>
#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_glm_crosscheck {

using quat::from_glm;
using quat::quaternion;
using quat::to_glm;
using quat::vec3;
using quat::test::tolerance;

namespace {

template <class T>
T difference(const quaternion<T>& a, const glm::qua<T>& b) {
    return quat::test::max_difference(a, from_glm(b));
}

}  // namespace

TEMPLATE_TEST_CASE("product, rotate and conjugate agree with GLM", "[glm]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 5000; ++n) {
        const auto a = random.unit_quaternion<T>(), b = random.unit_quaternion<T>();
        const vec3<T> v = random.vector<T>();
        CHECK(difference(a * b, to_glm(a) * to_glm(b)) <= tolerance<T>::glm);
        CHECK(difference(quat::conjugate(a), glm::conjugate(to_glm(a))) == 0);
        const glm::vec<3, T> g = to_glm(a) * glm::vec<3, T>(v.x, v.y, v.z);
        CHECK(quat::test::max_difference(quat::rotate(a, v), vec3<T>{g.x, g.y, g.z}) <=
              tolerance<T>::glm * quat::norm(v));
    }
}

TEMPLATE_TEST_CASE("to_matrix and to_quaternion agree with mat3_cast and quat_cast", "[glm]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 5000; ++n) {
        const auto q = random.unit_quaternion<T>();
        const auto m = quat::to_matrix(q);
        const glm::mat<3, 3, T> g = glm::mat3_cast(to_glm(q));
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col)
                CHECK(std::abs(m(row, col) - g[col][row]) <= tolerance<T>::glm);
        // quat_cast may return -q; both are the same rotation.
        CHECK(quat::angle_between(quat::to_quaternion(m), from_glm(glm::quat_cast(g))) <=
              tolerance<T>::glm);
    }
}

TEMPLATE_TEST_CASE("axis-angle agrees with angleAxis, angle and axis", "[glm]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 5000; ++n) {
        const vec3<T> axis = random.unit_vector<T>();
        const T angle = random.uniform<T>(-6, 6);
        const auto q = quat::to_quaternion(quat::axis_angle<T>{axis, angle});
        CHECK(difference(q, glm::angleAxis(angle, glm::vec<3, T>(axis.x, axis.y, axis.z))) <=
              tolerance<T>::glm);
        const auto back = quat::to_axis_angle(q);
        const glm::qua<T> canonical = to_glm(q.w < 0 ? -q : q);
        CHECK(std::abs(back.angle - glm::angle(canonical)) <=
              tolerance<T>::glm * 1000);  // GLM uses acos(w)
    }
}

TEMPLATE_TEST_CASE("to_euler<zyx> agrees with eulerAngles away from gimbal lock", "[glm]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    int compared = 0;
    for (int n = 0; n < 5000; ++n) {
        const auto q = random.unit_quaternion<T>();
        const auto e = quat::to_euler<quat::sequence::zyx>(q);
        if (std::abs(e[1]) > T(1.5)) continue;  // GLM's asin loses accuracy near +-pi/2
        const glm::vec<3, T> g = glm::eulerAngles(to_glm(q));  // (pitch x, yaw y, roll z)
        CHECK(std::abs(e[0] - g.z) <= tolerance<T>::glm * 100);
        CHECK(std::abs(e[1] - g.y) <= tolerance<T>::glm * 100);
        CHECK(std::abs(e[2] - g.x) <= tolerance<T>::glm * 100);
        // And GLM's Euler constructor builds our default convention from (pitch, yaw, roll).
        const glm::qua<T> rebuilt(glm::vec<3, T>(g.x, g.y, g.z));
        CHECK(quat::angle_between(quat::to_quaternion(e), from_glm(rebuilt)) <= tolerance<T>::glm);
        ++compared;
    }
    CHECK(compared > 4000);
}

TEMPLATE_TEST_CASE("slerp agrees with glm::slerp; exp and log with glm::exp and glm::log", "[glm]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 5000; ++n) {
        const auto a = random.unit_quaternion<T>(), b = random.unit_quaternion<T>();
        const T t = random.uniform<T>(0, 1);
        CHECK(quat::angle_between(quat::slerp(a, b, t),
                                  from_glm(glm::slerp(to_glm(a), to_glm(b), t))) <=
              tolerance<T>::glm * 10);
        const auto canonical = a.w < 0 ? -a : a;
        const glm::qua<T> log = glm::log(to_glm(canonical));
        const vec3<T> v = quat::to_rotation_vector(a);
        CHECK(quat::test::max_difference(v, vec3<T>{2 * log.x, 2 * log.y, 2 * log.z}) <=
              tolerance<T>::glm);
        const glm::qua<T> exp = glm::exp(glm::qua<T>(T(0), v.x / 2, v.y / 2, v.z / 2));
        CHECK(quat::angle_between(quat::from_rotation_vector(v), from_glm(exp)) <=
              tolerance<T>::glm);
    }
}

TEMPLATE_TEST_CASE("q * v and m * v agree with GLM's quat * vec3 and mat3 * vec3",
                   "[glm][first-use]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 5000; ++n) {
        const auto q = random.unit_quaternion<T>();
        const vec3<T> v = random.vector<T>();
        const glm::vec<3, T> g = to_glm(q) * to_glm(v), gm = glm::mat3_cast(to_glm(q)) * to_glm(v);
        CHECK(quat::test::max_difference(q * v, from_glm(g)) <= tolerance<T>::glm * quat::norm(v));
        CHECK(quat::test::max_difference(quat::to_matrix(q) * v, from_glm(gm)) <=
              tolerance<T>::glm * quat::norm(v));
    }
}

TEMPLATE_TEST_CASE("angle and axis agree with glm::angle and glm::axis up to GLM's range",
                   "[glm][first-use]", float, double) {
    // glm::angle is 2 acos(w), in [0, 2 pi]: for w < 0 it is 2 pi - quat::angle, and glm::axis is
    // then -quat::axis (the same rotation). quat's angle is in [0, pi], as Eigen's AngleAxis. (GLM
    // switches to 2 asin(|v|) for |w| > cos(1/2), which gives quat::angle again for w < -0.877.)
    using T = TestType;
    const T pi = quat::numbers::pi_v<T>;
    quat::test::random_rotations random;
    for (int n = 0; n < 5000; ++n) {
        const auto q = random.unit_quaternion<T>();
        const T theirs = glm::angle(to_glm(q));
        const vec3<T> their_axis = from_glm(glm::axis(to_glm(q)));
        const T ours = quat::angle(q);
        // GLM's acos(w) branch is taken for |w| <= cos(1/2); away from its ends it is well
        // conditioned.
        if (std::abs(q.w) > T(0.87)) continue;
        if (q.w >= 0) {
            CHECK(std::abs(ours - theirs) <= tolerance<T>::glm);
            CHECK(quat::test::max_difference(quat::axis(q), their_axis) <= tolerance<T>::glm);
        } else {
            CHECK(std::abs(ours - (2 * pi - theirs)) <= tolerance<T>::glm);
            CHECK(quat::test::max_difference(quat::axis(q), -their_axis) <= tolerance<T>::glm);
        }
    }
    // The identity: GLM's axis is z, quat's (as Eigen's) is x.
    CHECK(from_glm(glm::axis(to_glm(quaternion<T>::identity()))) == vec3<T>{0, 0, 1});
    CHECK(quat::axis(quaternion<T>::identity()) == vec3<T>{1, 0, 0});
}

TEMPLATE_TEST_CASE("exp and log agree with glm::exp and glm::log where GLM's are defined",
                   "[glm][first-use]", float, double) {
    // glm::exp ignores w (it assumes a pure quaternion) and returns the identity for
    // |v| < epsilon; glm::log is the principal logarithm, as quat::log.
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 5000; ++n) {
        const vec3<T> v = random.vector<T>(2.0);
        const quaternion<T> pure{0, v.x, v.y, v.z};
        CHECK(quat::test::max_difference(quat::exp(pure), from_glm(glm::exp(to_glm(pure)))) <=
              tolerance<T>::glm * (1 + quat::norm(v)));
        const quaternion<T> q = random.unit_quaternion<T>() * random.uniform<T>(0.1, 10);
        CHECK(quat::test::max_difference(quat::log(q), from_glm(glm::log(to_glm(q)))) <=
              tolerance<T>::glm);
    }
    // Where GLM's shortcut shows: a tiny v.
    const quaternion<T> tiny{0, T(1e-20), 0, 0};
    CHECK(quat::exp(tiny).x == T(1e-20));
    CHECK(glm::exp(to_glm(tiny)).x == 0);
}

}  // namespace test_glm_crosscheck
