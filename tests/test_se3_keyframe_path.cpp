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
#include "support/keyframe_path_rules.hpp"
#include "support/keyframe_poses.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_se3_keyframe_path {

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
    const quat::test::keyframe_misses worst =
        quat::test::misses_over_random_sets<se3_keyframe_path, T>(random);
    // Measured: 0 rad and 2.1 eps (float), 0 rad and 1.8 eps (double).
    CHECK(worst.angle <= 4 * eps<T>);
    CHECK(worst.position <= 4 * eps<T>);
}

TEMPLATE_TEST_CASE("se3_keyframe_path's velocities and accelerations are continuous (C2)",
                   "[se3_keyframe_path]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    int made = 0;
    const quat::test::jumps worst =
        quat::test::jumps_over_random_sets<se3_keyframe_path, T>(random, 200, 40, 2.5, 10.0, made);
    CHECK(made == 200);
    // Sets with rotation steps up to 2.5 rad and durations unequal by up to 10x. Measured
    // (velocity, acceleration, angular velocity, angular acceleration): 1.7e-13, 2.5e-13, 1.5e-13,
    // 5.3e-13 in double; 8.9e-5, 1.3e-4, 8.2e-5, 2.9e-4 in float (one float ulp of time moves
    // these fast paths visibly). A path whose acceleration jumps shows jumps of order 1.
    const double bound = std::is_same_v<T, float> ? 1e-3 : 1e-11;
    CHECK(worst.velocity <= bound);
    CHECK(worst.acceleration <= bound);
    CHECK(worst.angular_velocity <= bound);
    CHECK(worst.angular_acceleration <= bound);
}

TEST_CASE("se3_keyframe_path's rates are the derivatives of its poses", "[se3_keyframe_path]") {
    quat::test::random_rotations random;
    const quat::test::jumps worst =
        quat::test::derivative_errors_over_random_sets<se3_keyframe_path>(random);
    // Central differences with h = 1e-5 s are O(h^2) and, in long double, round at about 1e-19 / h
    // (1e-9 for the second difference). Measured: 1.5e-7, 6.7e-8, 8.2e-8, 5.0e-7 (velocity,
    // acceleration, angular velocity, angular acceleration), truncation: jerks of 1e4 m/s^3.
    CHECK(worst.velocity <= 2e-6);
    CHECK(worst.acceleration <= 2e-6);
    CHECK(worst.angular_velocity <= 2e-6);
    CHECK(worst.angular_acceleration <= 2e-6);
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
        coupled_angle =
            std::max(coupled_angle, double(quat::angle_between(c.pose.real, exact.real)));
        split_angle = std::max(split_angle, double(quat::angle_between(s.pose.real, exact.real)));
        coupled_position = std::max(
            coupled_position,
            double(quat::norm(quat::translation_of(c.pose) - quat::translation_of(exact))));
        split_position = std::max(split_position, double(quat::norm(quat::translation_of(s.pose) -
                                                                    quat::translation_of(exact))));
        const vec3<double> body_velocity = xi.linear;  // constant body twist
        coupled_velocity =
            std::max(coupled_velocity, double(quat::norm(c.body_velocity - body_velocity)));
        split_velocity =
            std::max(split_velocity, double(quat::norm(s.body_velocity - body_velocity)));
    }
    // Measured: coupled within 1.4e-15 rad, 8.1e-15 m and 4.0e-15 m/s; the split path has the
    // same rotations (1.4e-15 rad) but its origin runs up to 0.44 m off the helix, its body
    // velocity up to 1.95 m/s off.
    CHECK(coupled_angle <= 64 * eps<double>);
    CHECK(coupled_position <= 64 * eps<double>);
    CHECK(coupled_velocity <= 64 * eps<double>);
    CHECK(split_angle <= 64 * eps<double>);
    CHECK(split_position > 0.4);
    CHECK(split_velocity > 1.5);
}

TEST_CASE("se3_keyframe_path does not depend on the body's origin; the split path does",
          "[se3_keyframe_path]") {
    quat::test::random_rotations random;
    std::vector<double> times;
    std::vector<dual_quaternion<double>> poses, moved;
    double coupled = 0, split = 0;
    for (int n = 0; n < 20; ++n) {
        quat::test::random_pose_keyframes(random, 3 + std::size_t(n % 10), 2.0, 1.0, 5.0, times,
                                          poses);
        const dual_quaternion<double> h = random.rigid_motion<double>(1.0);
        moved.clear();
        for (const dual_quaternion<double>& x : poses) moved.push_back(x * h);
        const se3_keyframe_path<double> a(times, poses), b(times, moved);
        const split_keyframe_path<double> c(times, poses), d(times, moved);
        for (int k = 0; k <= 100; ++k) {
            const double t = times.front() + (times.back() - times.front()) * k / 100.0;
            const auto gap = [](const dual_quaternion<double>& x,
                                const dual_quaternion<double>& y) {
                return std::max(
                    double(quat::angle_between(x.real, y.real)),
                    double(quat::norm(quat::translation_of(x) - quat::translation_of(y))));
            };
            coupled = std::max(coupled, gap(a(t) * h, b(t)));
            split = std::max(split, gap(c(t) * h, d(t)));
        }
    }
    // Keyframes X_i H give the path X(t) H. Measured: 9.3e-15 (rad or m) for se3_keyframe_path,
    // 1.6 for the split path, whose origin moves on a cubic of its own.
    CHECK(coupled <= 1e-13);
    CHECK(split > 1.0);
}

TEST_CASE("a dolly with a pan: the split path keeps the line, se3_keyframe_path bends it",
          "[se3_keyframe_path]") {
    // A camera moving along x at 1 m/s while it pans about its own z at 0.8 rad/s.
    const std::vector<double> times{0, 0.5, 1.2, 2.0, 2.6, 3.5};
    std::vector<dual_quaternion<double>> poses;
    for (const double t : times)
        poses.push_back(quat::to_dual_quaternion(quat::rotation_z(0.8 * t), vec3<double>{t, 0, 0}));
    const se3_keyframe_path<double> coupled(times, poses);
    const split_keyframe_path<double> split(times, poses);
    double coupled_off = 0, split_off = 0;
    for (int k = 0; k <= 350; ++k) {
        const double t = 0.01 * k;
        const vec3<double> line{t, 0, 0};
        coupled_off =
            std::max(coupled_off, double(quat::norm(quat::translation_of(coupled(t)) - line)));
        split_off = std::max(split_off, double(quat::norm(quat::translation_of(split(t)) - line)));
    }
    // Measured: the split path stays on the line within 1.4e-15 m; se3_keyframe_path's origin
    // swings off it by up to 0.055 m (each segment is a screw about an axis beside the camera).
    CHECK(split_off <= 16 * eps<double> * 3.5);
    CHECK(coupled_off > 0.04);
}

TEMPLATE_TEST_CASE("an se3_keyframe_path through two keyframes is their sclerp",
                   "[se3_keyframe_path]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    double angle = 0, position = 0, velocity = 0, acceleration = 0;
    for (int n = 0; n < 200; ++n) {
        const dual_quaternion<T> a = random.rigid_motion<T>(1.0), b = random.rigid_motion<T>(1.0);
        const T start = random.uniform<T>(-5.0, 5.0), duration = random.uniform<T>(0.1, 4.0);
        const T times[] = {start, start + duration};
        const dual_quaternion<T> poses[] = {a, b};
        const se3_keyframe_path<T> path(times, poses);
        const T u = random.uniform<T>(0.0, 1.0);
        // The reference in double, at the parameter of the float times as stored: times[1] is
        // start + duration rounded.
        const T t = start + u * duration;
        const keyframe_path_state<T> s = path.state(t);
        const double stored = double(times[1]) - double(times[0]);
        const dual_quaternion<T> expected(quat::sclerp(dual_quaternion<double>(a),
                                                       dual_quaternion<double>(b),
                                                       (double(t) - double(start)) / stored));
        angle = std::max(angle, double(quat::angle_between(s.pose.real, expected.real)));
        position =
            std::max(position, double(quat::test::relative_difference(
                                   quat::translation_of(s.pose), quat::translation_of(expected))));
        const quat::se3::twist<T> twist =
            quat::se3::log(quat::se3::between(quat::normalize(a), quat::normalize(b)));
        velocity = std::max(velocity, double(quat::test::relative_difference(
                                          s.body_velocity, twist.linear / T(stored))));
        velocity = std::max(velocity, double(quat::test::relative_difference(
                                          s.body_angular_velocity, twist.angular / T(stored))));
        acceleration = std::max(acceleration, double(quat::norm(s.body_angular_acceleration)));
    }
    // Measured (angle, position, rates): 2.9, 2.5, 3.0 eps in float; 3.9, 5.2, 3.9 eps in double.
    // The angular acceleration of a screw segment is exactly zero.
    CHECK(angle <= 16 * eps<T>);
    CHECK(position <= 16 * eps<T>);
    CHECK(velocity <= 16 * eps<T>);
    CHECK(acceleration == 0);
}

TEMPLATE_TEST_CASE("se3_keyframe_path turns as the rotation spline through its rotations",
                   "[se3_keyframe_path]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    std::vector<T> times;
    std::vector<dual_quaternion<T>> poses;
    double angle = 0, rate = 0, second = 0, split_gap = 0;
    for (int n = 0; n < 30; ++n) {
        quat::test::random_pose_keyframes(random, 3 + std::size_t(n % 20), 2.5, 1.0, 10.0, times,
                                          poses);
        std::vector<quaternion<T>> rotations;
        for (const dual_quaternion<T>& x : poses) rotations.push_back(quat::normalize(x).real);
        const quat::rotation_spline<T> spline(times, rotations);
        const se3_keyframe_path<T> path(times, poses);
        const split_keyframe_path<T> split(times, poses);
        for (int k = 0; k <= 50; ++k) {
            const T t = times.front() + (times.back() - times.front()) * T(k) / T(50);
            const keyframe_path_state<T> s = path.state(t);
            angle = std::max(angle, double(quat::angle_between(s.pose.real, spline(t))));
            rate = std::max(rate, double(quat::test::relative_difference(
                                      s.body_angular_velocity, spline.angular_velocity(t))));
            second =
                std::max(second, double(quat::test::relative_difference(
                                     s.body_angular_acceleration, spline.angular_acceleration(t))));
            split_gap = std::max(split_gap, double(quat::angle_between(split(t).real, spline(t))));
        }
    }
    // The split path holds the rotation spline itself. se3_keyframe_path rebuilds its cubics from
    // the spline's velocities at the keyframes. Measured: 2.4e-15 rad, 4.4e-15 and 4.3e-14
    // (relative rates) in double; 1.1e-6 rad, 1.9e-6 and 4.1e-6 in float.
    CHECK(split_gap == 0);
    CHECK(angle <= 16 * eps<T>);
    CHECK(rate <= 512 * eps<T>);
    CHECK(second <= 512 * eps<T>);
}

TEMPLATE_TEST_CASE("without rotation se3_keyframe_path is the split path", "[se3_keyframe_path]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    std::vector<T> times;
    std::vector<dual_quaternion<T>> poses;
    double position = 0, velocity = 0, acceleration = 0;
    for (int n = 0; n < 30; ++n) {
        quat::test::random_pose_keyframes(random, 3 + std::size_t(n % 20), 0.0, 1.0, 10.0, times,
                                          poses);
        const quaternion<T> q = poses.front().real;
        for (dual_quaternion<T>& x : poses)
            x = quat::to_dual_quaternion(q, quat::translation_of(x));
        const se3_keyframe_path<T> a(times, poses);
        const split_keyframe_path<T> b(times, poses);
        for (int k = 0; k <= 50; ++k) {
            const T t = times.front() + (times.back() - times.front()) * T(k) / T(50);
            const keyframe_path_state<T> s = a.state(t), r = b.state(t);
            position = std::max(
                position, double(quat::test::relative_difference(quat::translation_of(s.pose),
                                                                 quat::translation_of(r.pose))));
            velocity =
                std::max(velocity, double(quat::test::relative_difference(s.velocity, r.velocity)));
            acceleration =
                std::max(acceleration,
                         double(quat::test::relative_difference(s.acceleration, r.acceleration)));
        }
    }
    // Both are then the clamped C2 cubic spline of the positions. Measured: 1.4e-15, 8.2e-15,
    // 1.6e-14 (position, velocity, acceleration) in double; 1.05e-6, 2.8e-6, 2.6e-6 in float.
    const double bound = std::is_same_v<T, float> ? 2e-5 : 1e-13;
    CHECK(position <= 32 * eps<T>);
    CHECK(velocity <= bound);
    CHECK(acceleration <= bound);
}

TEST_CASE("se3_keyframe_path's edge rules", "[se3_keyframe_path][nan]") {
    quat::test::check_edge_rules<se3_keyframe_path>();
}

TEST_CASE("se3_keyframe_path::evaluate gives the single values in any order of times",
          "[se3_keyframe_path]") {
    quat::test::random_rotations random;
    quat::test::check_batch<se3_keyframe_path>(random);
}

TEST_CASE("se3_keyframe_path is C2 with half-turn steps and durations unequal by 1000x",
          "[se3_keyframe_path]") {
    // The translation's system is linear and stays well conditioned; only the rotation spline's
    // Newton solve can fail (then try_make is empty; measured 5 sets in 300 here, as
    // rotation_spline documents for such sets). Measured jumps: 4.3e-12, 1.3e-11, 2.9e-12,
    // 8.6e-11 (velocity, acceleration, angular velocity, angular acceleration).
    quat::test::random_rotations random;
    int made = 0;
    const quat::test::jumps worst = quat::test::jumps_over_random_sets<se3_keyframe_path, double>(
        random, 300, 40, 3.14, 1000.0, made);
    CHECK(made >= 280);
    CHECK(worst.velocity <= 1e-9);
    CHECK(worst.acceleration <= 1e-9);
    CHECK(worst.angular_velocity <= 1e-9);
    CHECK(worst.angular_acceleration <= 1e-9);
}

TEST_CASE("se3_keyframe_path of uniformly scaled times is the same curve", "[se3_keyframe_path]") {
    // The solve runs in a unit of time set by the durations. Measured from 1e-100 to 1e300: within
    // 4.8e-15 m, 7.6e-15 (relative velocity) and 1.1e-14 (relative acceleration, compared where
    // scale^2 stays in range).
    quat::test::random_rotations random;
    std::vector<double> times, scaled;
    std::vector<dual_quaternion<double>> poses;
    quat::test::random_pose_keyframes(random, 12, 2.5, 1.0, 10.0, times, poses);
    const se3_keyframe_path<double> base(times, poses);
    for (const double scale : {1e-100, 1e-20, 1e-3, 1e3, 1e20, 1e100, 1e300}) {
        INFO("scale " << scale);
        scaled.clear();
        for (const double t : times) scaled.push_back(t * scale);
        const std::optional<se3_keyframe_path<double>> path =
            se3_keyframe_path<double>::try_make(scaled, poses);
        REQUIRE(path);
        double position = 0, velocity = 0, acceleration = 0;
        for (int k = 0; k <= 100; ++k) {
            const double t = times.front() + (times.back() - times.front()) * k / 100.0;
            const keyframe_path_state<double> a = path->state(t * scale), b = base.state(t);
            position = std::max(position, double(quat::norm(quat::translation_of(a.pose) -
                                                            quat::translation_of(b.pose))));
            velocity = std::max(
                velocity, double(quat::test::relative_difference(a.velocity * scale, b.velocity)));
            if (std::isnormal(scale * scale * 1e4) && std::isnormal(scale * scale / 1e4))
                acceleration =
                    std::max(acceleration, double(quat::test::relative_difference(
                                               a.acceleration * scale * scale, b.acceleration)));
        }
        CHECK(position <= 1e-13);
        CHECK(velocity <= 1e-13);
        CHECK(acceleration <= 1e-13);
    }
}

TEMPLATE_TEST_CASE("se3_keyframe_path::try_make is empty wherever a value would not be finite",
                   "[se3_keyframe_path][nan]", float, double) {
    quat::test::random_rotations random;
    quat::test::check_try_make_bounds<se3_keyframe_path, TestType>(random);
}

}  // namespace test_se3_keyframe_path
