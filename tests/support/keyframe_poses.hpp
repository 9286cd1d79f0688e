// Random (time, pose) keyframes and the measures the keyframe-path tests share.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include <quat/conversions.hpp>
#include <quat/quaternion.hpp>
#include <quat/rigid/dual_quaternion.hpp>
#include <quat/trajectory/keyframe_path_state.hpp>
#include <quat/vec3.hpp>

#include "random.hpp"

namespace quat::test {

/// Keyframes X_(i+1) = X_i exp-like steps: a rotation step of up to `max_angle` rad about a
/// random axis and a translation step of Gaussian components (standard deviation `reach`),
/// durations from 0.05 to 0.05 * ratio s (log-uniform), random signs of the dual quaternions.
template <class T>
void random_pose_keyframes(random_rotations& random, std::size_t count, double max_angle,
                           double reach, double ratio, std::vector<T>& times,
                           std::vector<dual_quaternion<T>>& poses) {
    times.assign(1, T(0));
    poses.assign(1, random.rigid_motion<T>(reach));
    while (poses.size() < count) {
        times.push_back(times.back() +
                        T(0.05 * std::exp(std::log(ratio) * random.uniform<double>(0, 1))));
        const vec3<T> axis = random.unit_vector<T>();  // one statement each: a fixed order
        const vec3<T> step = axis * random.uniform<T>(0.0, max_angle);
        const vec3<T> shift = random.vector<T>(reach);
        const dual_quaternion<T> next =
            poses.back() * to_dual_quaternion(from_rotation_vector(step), shift);
        poses.push_back(random.uniform<double>(0, 1) < 0.5 ? -next : next);
    }
}

/// |a - b| / (1 + |b|), the rotation_spline tests' measure for rates.
template <class T>
T relative_difference(const vec3<T>& a, const vec3<T>& b) {
    return norm(a - b) / (1 + norm(b));
}

/// The poses converted to another scalar.
template <class U, class T>
std::vector<dual_quaternion<U>> converted(const std::vector<dual_quaternion<T>>& poses) {
    std::vector<dual_quaternion<U>> out;
    for (const dual_quaternion<T>& x : poses) out.emplace_back(x);
    return out;
}

}  // namespace quat::test

namespace quat::test {

/// The largest misses of a path at its keyframes: rotation angle (rad) and position distance
/// relative to 1 + |position|.
struct keyframe_misses {
    double angle = 0, position = 0;
};

template <class Path, class T>
keyframe_misses misses_at_keyframes(const Path& path, const std::vector<T>& times,
                                    const std::vector<dual_quaternion<T>>& poses) {
    keyframe_misses worst;
    for (std::size_t i = 0; i < times.size(); ++i) {
        const dual_quaternion<T> expected = normalize(poses[i]);
        const dual_quaternion<T> pose = path(times[i]);
        const keyframe_path_state<T> state = path.state(times[i]);
        for (const dual_quaternion<T>& x : {pose, state.pose}) {
            worst.angle = std::max(worst.angle, double(angle_between(x.real, expected.real)));
            worst.position =
                std::max(worst.position,
                         double(relative_difference(translation_of(x), translation_of(expected))));
        }
    }
    return worst;
}

/// The largest jumps at the inner keyframes, state just before (the end of the segment before)
/// against state at the keyframe (the start of the next), each as relative_difference.
struct jumps {
    double velocity = 0, acceleration = 0, angular_velocity = 0, angular_acceleration = 0;
};

/// The larger of each measure of a and b.
inline jumps worse(const jumps& a, const jumps& b) {
    return {std::max(a.velocity, b.velocity), std::max(a.acceleration, b.acceleration),
            std::max(a.angular_velocity, b.angular_velocity),
            std::max(a.angular_acceleration, b.angular_acceleration)};
}

template <class Path, class T>
jumps jumps_at_keyframes(const Path& path, const std::vector<T>& times) {
    jumps worst;
    for (std::size_t i = 1; i + 1 < times.size(); ++i) {
        const keyframe_path_state<T> before =
            path.state(std::nextafter(times[i], -std::numeric_limits<T>::infinity()));
        const keyframe_path_state<T> at = path.state(times[i]);
        const auto grow = [](double& to, const vec3<T>& a, const vec3<T>& b) {
            to = std::max(to, double(relative_difference(a, b)));
        };
        grow(worst.velocity, before.velocity, at.velocity);
        grow(worst.acceleration, before.acceleration, at.acceleration);
        grow(worst.angular_velocity, before.body_angular_velocity, at.body_angular_velocity);
        grow(worst.angular_acceleration, before.body_angular_acceleration,
             at.body_angular_acceleration);
    }
    return worst;
}

/// The largest differences between a path's velocities and accelerations and central
/// differences, in long double, of `reference` (the same keyframes in long double): positions
/// (t +- h) for the linear ones, the body angular velocity from R(t - h) to R(t + h) and the
/// reference's own angular velocities (t +- h) for the angular ones. All O(h^2).
template <class Path, class Reference, class T>
jumps derivative_errors(const Path& path, const Reference& reference, const std::vector<T>& ts,
                        long double h) {
    jumps worst;
    using L = long double;
    for (const T t0 : ts) {
        const L t = L(t0);
        const keyframe_path_state<T> s = path.state(t0);
        const keyframe_path_state<L> minus = reference.state(t - h), plus = reference.state(t + h),
                                     centre = reference.state(t);
        const vec3<L> p0 = translation_of(centre.pose), pm = translation_of(minus.pose),
                      pp = translation_of(plus.pose);
        const vec3<L> velocity = (pp - pm) / (2 * h);
        const vec3<L> acceleration = (pp - p0 * L(2) + pm) / (h * h);
        const vec3<L> angular =
            to_rotation_vector(conjugate(minus.pose.real) * plus.pose.real) / (2 * h);
        const vec3<L> angular_rate =
            (plus.body_angular_velocity - minus.body_angular_velocity) / (2 * h);
        const auto grow = [](double& to, const vec3<T>& a, const vec3<L>& b) {
            to = std::max(to, double(relative_difference(vec3<L>(a), b)));
        };
        grow(worst.velocity, s.velocity, velocity);
        grow(worst.acceleration, s.acceleration, acceleration);
        grow(worst.angular_velocity, s.body_angular_velocity, angular);
        grow(worst.angular_acceleration, s.body_angular_acceleration, angular_rate);
    }
    return worst;
}

}  // namespace quat::test
