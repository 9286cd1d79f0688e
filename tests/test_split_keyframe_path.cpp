// Specification of trajectory/split_keyframe_path.hpp: rotation_spline for the orientation and
// the clamped C2 cubic spline for the position, checked at the keyframes, by one-sided limits at
// them, against central differences of its own evaluation in long double, and at the ends.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <vector>

#include <quat/kinematics.hpp>
#include <quat/paths/interpolation.hpp>
#include <quat/trajectory/split_keyframe_path.hpp>

#include "support/catch.hpp"
#include "support/keyframe_path_rules.hpp"
#include "support/keyframe_poses.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_split_keyframe_path {

using quat::dual_quaternion;
using quat::keyframe_path_state;
using quat::split_keyframe_path;
using quat::vec3;
using quat::test::eps;

TEMPLATE_TEST_CASE("split_keyframe_path passes through its keyframes", "[split_keyframe_path]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    const quat::test::keyframe_misses worst =
        quat::test::misses_over_random_sets<split_keyframe_path, T>(random);
    // Measured: 2.5 eps (rotation: rotation_spline normalizes the normalized keyframe once more)
    // and 2.1 eps (position) in float, 2.5 and 1.8 eps in double.
    CHECK(worst.angle <= 4 * eps<T>);
    CHECK(worst.position <= 4 * eps<T>);
}

TEMPLATE_TEST_CASE("split_keyframe_path's velocities and accelerations are continuous (C2)",
                   "[split_keyframe_path]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    int made = 0;
    const quat::test::jumps worst = quat::test::jumps_over_random_sets<split_keyframe_path, T>(
        random, 200, 40, 2.5, 10.0, made);
    CHECK(made == 200);
    // Measured (velocity, acceleration, angular velocity, angular acceleration): 1.9e-13, 1.7e-13,
    // 1.5e-13, 5.3e-13 in double; 1.0e-4, 9.1e-5, 8.2e-5, 2.9e-4 in float (one float ulp of time
    // moves these fast paths visibly).
    const double bound = std::is_same_v<T, float> ? 1e-3 : 1e-11;
    CHECK(worst.velocity <= bound);
    CHECK(worst.acceleration <= bound);
    CHECK(worst.angular_velocity <= bound);
    CHECK(worst.angular_acceleration <= bound);
}

TEST_CASE("split_keyframe_path's rates are the derivatives of its poses", "[split_keyframe_path]") {
    quat::test::random_rotations random;
    const quat::test::jumps worst =
        quat::test::derivative_errors_over_random_sets<split_keyframe_path>(random);
    // h = 1e-5 s: O(h^2) truncation, long double rounding near 1e-19 / h^2 for the second
    // difference. Measured: 1.4e-7, 7.3e-9, 8.2e-8, 5.0e-7 (velocity, acceleration, angular
    // velocity, angular acceleration).
    CHECK(worst.velocity <= 2e-6);
    CHECK(worst.acceleration <= 2e-6);
    CHECK(worst.angular_velocity <= 2e-6);
    CHECK(worst.angular_acceleration <= 2e-6);
}

TEMPLATE_TEST_CASE("split_keyframe_path starts and ends as its end segments' slerp and lerp",
                   "[split_keyframe_path]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    std::vector<T> times;
    std::vector<dual_quaternion<T>> poses;
    double ends = 0, two = 0;
    for (int n = 0; n < 50; ++n) {
        quat::test::random_pose_keyframes(random, 2 + std::size_t(n % 10), 2.5, 1.0, 10.0, times,
                                          poses);
        const split_keyframe_path<T> path(times, poses);
        const std::size_t last = times.size() - 1;
        const auto position = [&](std::size_t i) {
            return quat::translation_of(quat::normalize(poses[i]));
        };
        const auto rotation = [&](std::size_t i) { return quat::normalize(poses[i]).real; };
        const T first_duration = times[1] - times[0], last_duration = times[last] - times[last - 1];
        const keyframe_path_state<T> start = path.state(times[0]), end = path.state(times[last]);
        ends = std::max(
            {ends,
             double(quat::test::relative_difference(start.velocity,
                                                    (position(1) - position(0)) / first_duration)),
             double(quat::test::relative_difference(
                 end.velocity, (position(last) - position(last - 1)) / last_duration)),
             double(quat::test::relative_difference(
                 start.body_angular_velocity,
                 quat::body_angular_velocity(rotation(0), rotation(1), first_duration))),
             double(quat::test::relative_difference(
                 end.body_angular_velocity,
                 quat::body_angular_velocity(rotation(last - 1), rotation(last), last_duration)))});
        if (times.size() == 2) {
            for (int k = 0; k <= 10; ++k) {
                const T u = T(k) / T(10), t = times[0] + u * first_duration;
                const dual_quaternion<T> x = path(t);
                const T v = (t - times[0]) / first_duration;
                two = std::max(
                    {two,
                     double(quat::angle_between(x.real, quat::slerp(rotation(0), rotation(1), v))),
                     double(quat::test::relative_difference(
                         quat::translation_of(x), position(0) + (position(1) - position(0)) * v))});
            }
        }
    }
    // Measured: 6.6 eps (float) and 9.8 eps (double) at the ends; 2.3 eps for two keyframes.
    CHECK(ends <= 32 * eps<T>);
    CHECK(two <= 8 * eps<T>);
}

TEST_CASE("split_keyframe_path's edge rules", "[split_keyframe_path][nan]") {
    quat::test::check_edge_rules<split_keyframe_path>();
}

TEST_CASE("split_keyframe_path::evaluate gives the single values in any order of times",
          "[split_keyframe_path]") {
    quat::test::random_rotations random;
    quat::test::check_batch<split_keyframe_path>(random);
}

TEST_CASE("split_keyframe_path takes times of another precision than its poses",
          "[split_keyframe_path]") {
    quat::test::random_rotations random;
    std::vector<float> times;
    std::vector<dual_quaternion<float>> poses;
    quat::test::random_pose_keyframes(random, 8, 2.0, 1.0, 5.0, times, poses);
    const std::vector<double> double_times(times.begin(), times.end());
    const split_keyframe_path<float> reference(times, poses);
    const split_keyframe_path path(double_times, poses);  // deduced from the poses: float
    static_assert(std::is_same_v<decltype(path), const split_keyframe_path<float>>);
    REQUIRE(split_keyframe_path<float>::try_make(double_times, poses));
    for (int k = 0; k <= 40; ++k) {
        const float t = times.front() + (times.back() - times.front()) * float(k) / 40.0f;
        CHECK(path(t) == reference(t));
    }
}

TEMPLATE_TEST_CASE("split_keyframe_path::try_make is empty wherever a value would not be finite",
                   "[split_keyframe_path][nan]", float, double) {
    quat::test::random_rotations random;
    quat::test::check_try_make_bounds<split_keyframe_path, TestType>(random);
}

}  // namespace test_split_keyframe_path
