// Specification of paths/squad.hpp: Shoemake's spherical cubic through keyframes, checked against
// its definition, finite differences of the path, and GLM's glm::squad / glm::intermediate.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>
#include <quat/interop/glm.hpp>
#include <quat/kinematics.hpp>
#include <quat/paths/squad.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_squad {

using quat::quaternion;
using quat::vec3;
using quat::test::eps;

namespace {

// The squad segment from keyframe i to i + 1, ends handled by repeating the end keyframe.
template <class T>
quaternion<T> segment(const std::vector<quaternion<T>>& q, std::size_t i, T t) {
    const std::size_t last = q.size() - 1;
    const quaternion<T> a1 = quat::squad_control(q[i == 0 ? 0 : i - 1], q[i], q[i + 1]);
    const quaternion<T> a2 = quat::squad_control(q[i], q[i + 1], q[i + 1 == last ? last : i + 2]);
    return quat::squad(q[i], a1, a2, q[i + 1], t);
}

}  // namespace

TEMPLATE_TEST_CASE("squad passes through its keyframes exactly", "[squad]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 200; ++n) {
        const std::vector<quaternion<T>> q = quat::test::random_walk<T>(random, 5, 2.5);
        for (std::size_t i = 0; i + 1 < q.size(); ++i) {
            CHECK(segment(q, i, T(0)) == q[i]);
            CHECK(quat::angle_between(segment(q, i, T(1)), q[i + 1]) == T(0));
        }
    }
}

TEMPLATE_TEST_CASE("squad_control and squad depend on the rotations, not on quaternion signs",
                   "[squad]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 500; ++n) {
        std::vector<quaternion<T>> q = quat::test::random_walk<T>(random, 4, 2.5);
        const T t = random.uniform<T>(0.0, 1.0);
        const quaternion<T> control = quat::squad_control(q[0], q[1], q[2]);
        const quaternion<T> path = segment(q, 1, t);
        q[0] = -q[0];
        q[2] = -q[2];
        q[3] = -q[3];
        CHECK(quat::angle_between(quat::squad_control(q[0], q[1], q[2]), control) <= 16 * eps<T>);
        CHECK(quat::angle_between(segment(q, 1, t), path) <= 64 * eps<T>);
    }
}

TEST_CASE("squad_control is Shoemake's q exp(-(log(q* next) + log(q* previous)) / 4)", "[squad]") {
    // Evaluated independently with long double logarithms and exponentials on keyframes already on
    // one hemisphere (so no alignment is needed).
    quat::test::random_rotations random;
    const auto log = [](const quaternion<long double>& q) {
        const long double s = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
        const long double f = s == 0 ? 0 : std::atan2(s, q.w) / s;
        return quaternion<long double>{0, q.x * f, q.y * f, q.z * f};
    };
    const auto exp = [](const quaternion<long double>& v) {
        const long double a = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        const long double f = a == 0 ? 1 : std::sin(a) / a;
        return quaternion<long double>{std::cos(a), v.x * f, v.y * f, v.z * f};
    };
    for (int n = 0; n < 1000; ++n) {
        std::vector<quaternion<double>> q = quat::test::random_walk<double>(random, 3, 2.0);
        for (std::size_t i = 1; i < 3; ++i)
            if (quat::dot(q[i], q[1]) < 0) q[i] = -q[i];
        if (quat::dot(q[0], q[1]) < 0) q[0] = -q[0];
        const quaternion<long double> p(q[0]), c(q[1]), x(q[2]);
        const quaternion<long double> expected =
            c * exp((log(quat::conjugate(c) * x) + log(quat::conjugate(c) * p)) * -0.25L);
        CHECK(quat::angle_between(quat::squad_control(q[0], q[1], q[2]),
                                  quaternion<double>(expected)) <= 16 * eps<double>);
    }
}

TEMPLATE_TEST_CASE(
    "with evenly spaced keyframes squad's angular velocity is continuous across them", "[squad]",
    float, double) {
    using T = TestType;
    // One-sided finite differences of the path at both ends of each keyframe: their difference is
    // O(h) where the velocity is continuous, and jumps where it is not (piecewise slerp).
    const T h = std::is_same_v<T, float> ? T(1e-2) : T(1e-5);
    quat::test::random_rotations random;
    T worst_squad = 0, worst_slerp = 0, typical_speed = 0;
    for (int n = 0; n < 100; ++n) {
        const std::vector<quaternion<T>> q = quat::test::random_walk<T>(random, 6, 1.5);
        for (std::size_t i = 1; i + 1 < q.size(); ++i) {
            const vec3<T> before = quat::body_angular_velocity(segment(q, i - 1, 1 - h), q[i], h);
            const vec3<T> after = quat::body_angular_velocity(q[i], segment(q, i, h), h);
            worst_squad = std::max(worst_squad, quat::norm(after - before));
            const vec3<T> slerp_before =
                quat::body_angular_velocity(quat::slerp(q[i - 1], q[i], 1 - h), q[i], h);
            const vec3<T> slerp_after =
                quat::body_angular_velocity(q[i], quat::slerp(q[i], q[i + 1], h), h);
            worst_slerp = std::max(worst_slerp, quat::norm(slerp_after - slerp_before));
            typical_speed = std::max(typical_speed, quat::norm(after));
        }
    }
    CHECK(worst_squad <= 40 * h * typical_speed);
    CHECK(worst_slerp >= 0.5 * typical_speed);
}

TEST_CASE("with uneven spacing squad's angular velocity jumps by the ratio of the durations",
          "[squad]") {
    // The documented reason to prefer rotation_spline for uneven keyframes: squad's parameter runs
    // over [0, 1] per segment, so the same tangent at keyframe 1 means velocities in the ratio of
    // the two segments' durations when they take 1 s and 3 s.
    quat::test::random_rotations random;
    const std::vector<quaternion<double>> q = quat::test::random_walk<double>(random, 4, 1.0);
    const double h = 1e-6, first = 1.0, second = 3.0;
    const vec3<double> before = quat::body_angular_velocity(segment(q, 0, 1 - h), q[1], h * first);
    const vec3<double> after = quat::body_angular_velocity(q[1], segment(q, 1, h), h * second);
    CHECK(quat::norm(before - after * (second / first)) <= 1e-4 * quat::norm(before));
}

TEMPLATE_TEST_CASE("squad agrees with GLM's squad and intermediate on keyframes on one hemisphere",
                   "[squad][glm]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 1000; ++n) {
        std::vector<quaternion<T>> q = quat::test::random_walk<T>(random, 4, 1.5);
        for (std::size_t i = 1; i < q.size(); ++i)
            if (quat::dot(q[i - 1], q[i]) < 0) q[i] = -q[i];
        const T t = random.uniform<T>(0.0, 1.0);
        const auto s1 =
            glm::intermediate(quat::to_glm(q[0]), quat::to_glm(q[1]), quat::to_glm(q[2]));
        const auto s2 =
            glm::intermediate(quat::to_glm(q[1]), quat::to_glm(q[2]), quat::to_glm(q[3]));
        const quaternion<T> expected =
            quat::from_glm(glm::squad(quat::to_glm(q[1]), quat::to_glm(q[2]), s1, s2, t));
        CHECK(quat::angle_between(segment(q, 1, t), quat::normalize(expected)) <=
              (std::is_same_v<T, float> ? T(2e-5) : T(1e-12)));
    }
}

TEST_CASE("GLM's squad takes the long way when a keyframe's sign flips; quat's does not",
          "[squad][glm]") {
    // The trap of gz-math #568 and cglm #344: q and -q are one rotation, but GLM's intermediate
    // takes log(next q^-1) as given, so a negated neighbour sends the path round the long way.
    const quaternion<double> q0 = quat::from_rotation_vector(vec3<double>{0.0, 0.0, 0.0});
    const quaternion<double> q1 = quat::from_rotation_vector(vec3<double>{0.0, 0.0, 0.5});
    const quaternion<double> q2 = quat::from_rotation_vector(vec3<double>{0.0, 0.0, 1.0});
    const quaternion<double> q3 = quat::from_rotation_vector(vec3<double>{0.0, 0.0, 1.5});
    const std::vector<quaternion<double>> aligned{q0, q1, q2, q3}, flipped{q0, q1, -q2, q3};
    const auto glm_midpoint = [](const std::vector<quaternion<double>>& q) {
        const auto s1 =
            glm::intermediate(quat::to_glm(q[0]), quat::to_glm(q[1]), quat::to_glm(q[2]));
        const auto s2 =
            glm::intermediate(quat::to_glm(q[1]), quat::to_glm(q[2]), quat::to_glm(q[3]));
        return quat::normalize(
            quat::from_glm(glm::squad(quat::to_glm(q[1]), quat::to_glm(q[2]), s1, s2, 0.5)));
    };
    const quaternion<double> midway = quat::from_rotation_vector(vec3<double>{0.0, 0.0, 0.75});
    CHECK(quat::angle_between(segment(aligned, 1, 0.5), midway) <= 1e-15);
    CHECK(quat::angle_between(segment(flipped, 1, 0.5), midway) <= 1e-15);
    CHECK(quat::angle_between(glm_midpoint(aligned), midway) <= 1e-12);
    CHECK(quat::angle_between(glm_midpoint(flipped), midway) > 1.0);
}

TEST_CASE("squad and squad_control are constexpr", "[squad][constexpr]") {
    constexpr quaternion<double> q0{1.0, 0.0, 0.0, 0.0};
    constexpr quaternion<double> q1{0.8, 0.6, 0.0, 0.0};
    constexpr quaternion<double> q2{0.6, 0.8, 0.0, 0.0};
    constexpr quaternion<double> a1 = quat::squad_control(q0, q1, q2);
    constexpr quaternion<double> a2 = quat::squad_control(q1, q2, q2);
    constexpr quaternion<double> start = quat::squad(q1, a1, a2, q2, 0.0);
    static_assert(start == q1);
    constexpr quaternion<double> middle = quat::squad(q1, a1, a2, q2, 0.5);
    CHECK(quat::angle_between(middle, quat::squad(q1, quat::squad_control(q0, q1, q2),
                                                  quat::squad_control(q1, q2, q2), q2, 0.5)) <=
          8 * eps<double>);
}

TEST_CASE("squad of NaN gives NaN", "[squad][nan]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const quaternion<double> q = quaternion<double>::identity(), bad{nan, 0.0, 0.0, 0.0};
    CHECK(std::isnan(quat::squad_control(q, bad, q).w));
    CHECK(std::isnan(quat::squad_control(bad, q, q).w));
    CHECK(std::isnan(quat::squad(q, q, q, q, nan).w));
    CHECK(std::isnan(quat::squad(q, bad, q, q, 0.5).w));
}

TEST_CASE("GLM's squad(q1, q2, s1, s2, h) is quat's squad(q1, s1, s2, q2, h)", "[squad][glm]") {
    // The keyframes come first and last in quat's order, in the middle in GLM's. A port that keeps
    // GLM's order compiles (all four are quaternions) and passes through the wrong points.
    quat::test::random_rotations random;
    double glm_order_worst = 0;
    for (int n = 0; n < 100; ++n) {
        std::vector<quaternion<double>> q = quat::test::random_walk<double>(random, 4, 1.5);
        for (std::size_t i = 1; i < q.size(); ++i)
            if (quat::dot(q[i - 1], q[i]) < 0) q[i] = -q[i];
        const quaternion<double> a1 = quat::squad_control(q[0], q[1], q[2]);
        const quaternion<double> a2 = quat::squad_control(q[1], q[2], q[3]);
        const double h = random.uniform<double>(0.0, 1.0);
        const quaternion<double> glm_path = quat::normalize(quat::from_glm(glm::squad(
            quat::to_glm(q[1]), quat::to_glm(q[2]), quat::to_glm(a1), quat::to_glm(a2), h)));
        CHECK(quat::angle_between(quat::squad(q[1], a1, a2, q[2], h), glm_path) <= 1e-12);
        glm_order_worst = std::max(glm_order_worst,
                                   quat::angle_between(quat::squad(q[1], q[2], a1, a2, 1.0), q[2]));
    }
    CHECK(glm_order_worst > 0.1);  // GLM's order in quat's squad misses the end keyframe
}

TEMPLATE_TEST_CASE("squad takes t of another precision than its quaternions", "[squad]", float,
                   double) {
    using T = TestType;
    // A double t beside float quaternions (or a float t beside double ones) converts to the
    // quaternions' scalar, as slerp's does.
    quat::test::random_rotations random;
    for (int n = 0; n < 100; ++n) {
        const std::vector<quaternion<T>> q = quat::test::random_walk<T>(random, 4, 1.5);
        const quaternion<T> a1 = quat::squad_control(q[0], q[1], q[2]);
        const quaternion<T> a2 = quat::squad_control(q[1], q[2], q[3]);
        const double t = random.uniform<double>(0.0, 1.0);
        const float t_float = float(t);
        CHECK(quat::squad(q[1], a1, a2, q[2], t) == quat::squad(q[1], a1, a2, q[2], T(t)));
        CHECK(quat::squad(q[1], a1, a2, q[2], t_float) ==
              quat::squad(q[1], a1, a2, q[2], T(t_float)));
    }
}

}  // namespace test_squad
