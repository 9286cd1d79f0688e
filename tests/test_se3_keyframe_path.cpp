// Specification of trajectory/se3_keyframe_path.hpp: a C2 path of cubic twists through (time,
// pose) keyframes, checked at its keyframes, by one-sided limits at them, against central
// differences of its own evaluation in long double, and against the split path.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include <quat/lie/se3.hpp>
#include <quat/paths/rotation_spline.hpp>
#include <quat/rigid/sclerp.hpp>
#include <quat/trajectory.hpp>

#include "support/catch.hpp"
#include "support/keyframe_poses.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

using quat::dual_quaternion;
using quat::keyframe_path_state;
using quat::quaternion;
using quat::se3_keyframe_path;
using quat::split_keyframe_path;
using quat::vec3;
using quat::test::eps;

TEMPLATE_TEST_CASE("se3_keyframe_path passes through its keyframes", "[se3_keyframe_path]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    std::vector<T> times;
    std::vector<dual_quaternion<T>> poses;
    quat::test::keyframe_misses worst;
    for (int n = 0; n < 50; ++n) {
        quat::test::random_pose_keyframes(random, 2 + std::size_t(n % 30), 2.5, 1.0, 10.0, times,
                                          poses);
        const se3_keyframe_path<T> path(times, poses);
        const quat::test::keyframe_misses m = quat::test::misses_at_keyframes(path, times, poses);
        worst = {std::max(worst.angle, m.angle), std::max(worst.position, m.position)};
    }
    WARN("misses " << worst.angle << " " << worst.position);
    CHECK(worst.angle <= 4 * eps<T>);
    CHECK(worst.position <= 4 * eps<T>);
}

TEMPLATE_TEST_CASE("se3_keyframe_path's velocities and accelerations are continuous (C2)",
                   "[se3_keyframe_path]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    std::vector<T> times;
    std::vector<dual_quaternion<T>> poses;
    quat::test::jumps worst;
    for (int n = 0; n < 200; ++n) {
        quat::test::random_pose_keyframes(random, 3 + std::size_t(n % 40), 2.5, 1.0, 10.0, times,
                                          poses);
        const std::optional<se3_keyframe_path<T>> path =
            se3_keyframe_path<T>::try_make(times, poses);
        REQUIRE(path);
        const quat::test::jumps j = quat::test::jumps_at_keyframes(*path, times);
        worst = {std::max(worst.velocity, j.velocity), std::max(worst.acceleration, j.acceleration),
                 std::max(worst.angular_velocity, j.angular_velocity),
                 std::max(worst.angular_acceleration, j.angular_acceleration)};
    }
    WARN("jumps " << worst.velocity << " " << worst.acceleration << " " << worst.angular_velocity
                  << " " << worst.angular_acceleration);
}

TEST_CASE("se3_keyframe_path's rates are the derivatives of its poses", "[se3_keyframe_path]") {
    quat::test::random_rotations random;
    std::vector<double> times;
    std::vector<dual_quaternion<double>> poses;
    quat::test::jumps worst;
    for (int n = 0; n < 20; ++n) {
        quat::test::random_pose_keyframes(random, 10, 2.0, 1.0, 5.0, times, poses);
        const se3_keyframe_path<double> path(times, poses);
        const se3_keyframe_path<long double> reference(
            std::vector<long double>(times.begin(), times.end()),
            quat::test::converted<long double>(poses));
        std::vector<double> ts;
        for (int k = 0; k < 50; ++k) ts.push_back(random.uniform<double>(times.front(), times.back()));
        const quat::test::jumps e = quat::test::derivative_errors(path, reference, ts, 1e-5L);
        worst = {std::max(worst.velocity, e.velocity), std::max(worst.acceleration, e.acceleration),
                 std::max(worst.angular_velocity, e.angular_velocity),
                 std::max(worst.angular_acceleration, e.angular_acceleration)};
    }
    WARN("derivatives " << worst.velocity << " " << worst.acceleration << " "
                        << worst.angular_velocity << " " << worst.angular_acceleration);
}

TEST_CASE("se3_keyframe_path follows a screw exactly; the split path cuts it short",
          "[se3_keyframe_path]") {
    // X(t) = X0 exp(t xi): a body turning at 1.3 rad/s about an axis 2 m from its origin while
    // sliding 0.4 m/s along it, keyframed at uneven times.
    const quat::se3::twist<double> xi{{0.4, -2.6, 0.2}, {0.1, 0.3, 1.3}};
    const dual_quaternion<double> x0 =
        quat::to_dual_quaternion(quat::rotation_y(0.3), vec3<double>{1, 2, 3});
    const std::vector<double> times{0, 0.4, 1.5, 1.9, 3.0, 4.2};
    std::vector<dual_quaternion<double>> poses;
    for (const double t : times) poses.push_back(x0 * quat::se3::exp(xi * t));
    const se3_keyframe_path<double> coupled(times, poses);
    const split_keyframe_path<double> split(times, poses);
    double coupled_angle = 0, coupled_position = 0, split_angle = 0, split_position = 0;
    double coupled_velocity = 0, split_velocity = 0;
    for (int k = 0; k <= 420; ++k) {
        const double t = 0.01 * k;
        const dual_quaternion<double> exact = x0 * quat::se3::exp(xi * t);
        const keyframe_path_state<double> c = coupled.state(t), s = split.state(t);
        coupled_angle = std::max(coupled_angle, double(quat::angle_between(c.pose.real, exact.real)));
        split_angle = std::max(split_angle, double(quat::angle_between(s.pose.real, exact.real)));
        coupled_position = std::max(coupled_position, double(quat::norm(quat::translation_of(c.pose) - quat::translation_of(exact))));
        split_position = std::max(split_position, double(quat::norm(quat::translation_of(s.pose) - quat::translation_of(exact))));
        const vec3<double> body_velocity = xi.linear;  // constant body twist
        coupled_velocity = std::max(coupled_velocity, double(quat::norm(c.body_velocity - body_velocity)));
        split_velocity = std::max(split_velocity, double(quat::norm(s.body_velocity - body_velocity)));
    }
    WARN("screw coupled " << coupled_angle << " " << coupled_position << " " << coupled_velocity
                          << " split " << split_angle << " " << split_position << " "
                          << split_velocity);
}
