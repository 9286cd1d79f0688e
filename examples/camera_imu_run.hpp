// A simulated camera-IMU run for the camera_imu_spline example (not part of the library): an
// analytic truth trajectory, and the readings of a gyroscope, an accelerometer and a camera moving
// with it, each with its noise, from a fixed seed.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <quat/lie/so3.hpp>
#include <quat/quat.hpp>

namespace camera_imu {

using quat::dual_quaternion;
using quat::quatd;
using v3 = quat::vec3<double>;

/// A small deterministic generator (SplitMix64 with Box-Muller), so the picture is the same on
/// every platform: std::normal_distribution's algorithm differs between standard libraries.
class generator {
public:
    explicit generator(std::uint64_t seed) : state_(seed) {}
    /// Uniform in (0, 1].
    double uniform() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return static_cast<double>(((z ^ (z >> 31)) >> 11) + 1) * 0x1.0p-53;
    }
    /// Standard normal.
    double gaussian() {
        const double radius = std::sqrt(-2 * std::log(uniform()));
        return radius * std::cos(2 * quat::numbers::pi * uniform());
    }
    /// Each component normal with standard deviation sigma.
    v3 gaussian(double sigma) {
        // Declarators are initialised in order: x, y, z draw the same numbers on every compiler.
        const double x = gaussian(), y = gaussian(), z = gaussian();
        return v3{x, y, z} * sigma;
    }

private:
    std::uint64_t state_;
};

/// The true state of the body (the IMU's frame) at one time.
struct state {
    quatd rotation;       ///< body to world
    v3 position;          ///< world frame, metres
    v3 velocity;          ///< p', world frame
    v3 acceleration;      ///< p'', world frame
    v3 angular_velocity;  ///< body frame, rad/s
};

/// The truth: a figure-eight 4 m by 2.4 m wide, bobbing 0.3 m, once in 10 s, while the body yaws
/// by up to 115 degrees, pitches by 17 and rolls by 23 (yaw, pitch, roll about z, y', x'').
/// Everything in closed form, so velocity, acceleration and angular velocity are exact.
inline state truth(double t) {
    const double w = 2 * quat::numbers::pi / 10;
    const double s1 = std::sin(w * t), c1 = std::cos(w * t);
    const double s2 = std::sin(2 * w * t), c2 = std::cos(2 * w * t);
    const double s3 = std::sin(3 * w * t), c3 = std::cos(3 * w * t);
    state x{};
    x.position = {2 * s1, 1.2 * s2, 1 + 0.3 * s3};
    x.velocity = {2 * w * c1, 2.4 * w * c2, 0.9 * w * c3};
    x.acceleration = {-2 * w * w * s1, -4.8 * w * w * s2, -2.7 * w * w * s3};
    const double yaw = 2 * s1, yaw_rate = 2 * w * c1;
    const double pitch = 0.3 * std::sin(1.1 * t), pitch_rate = 0.33 * std::cos(1.1 * t);
    const double roll = 0.4 * std::sin(1.7 * t + 0.5), roll_rate = 0.68 * std::cos(1.7 * t + 0.5);
    const quatd turn_pitch = quat::rotation_y(pitch), turn_roll = quat::rotation_x(roll);
    x.rotation = quat::rotation_z(yaw) * turn_pitch * turn_roll;
    // R^T R' for R = Rz Ry Rx: each rate about its own axis, brought into the body frame by the
    // rotations that follow it.
    x.angular_velocity = quat::rotate(quat::conjugate(turn_pitch * turn_roll), v3{0, 0, yaw_rate}) +
                         quat::rotate(quat::conjugate(turn_roll), v3{0, pitch_rate, 0}) +
                         v3{roll_rate, 0, 0};
    return x;
}

/// The sensors' rates, noises and biases, and the camera's mount and clock.
struct sensor_setup {
    double imu_rate = 200, camera_rate = 20, duration = 10;
    double gyroscope_noise = 0.005;     ///< rad/s, standard deviation of each sample and axis
    double accelerometer_noise = 0.05;  ///< m/s^2, the same
    v3 gyroscope_bias{0.02, -0.015, 0.01};
    v3 accelerometer_bias{0.1, -0.08, 0.12};
    double camera_position_noise = 0.01;                        ///< metres, each axis
    double camera_angle_noise = 0.5 * quat::numbers::pi / 180;  ///< radians, each axis
    /// The camera's pose in the body frame (camera pose = body pose * extrinsic): it looks along
    /// the body's x axis (its own z), 10 cm ahead of the IMU.
    dual_quaternion<double> extrinsic = quat::to_dual_quaternion(
        quat::rotation_z(-quat::numbers::pi / 2) * quat::rotation_x(-quat::numbers::pi / 2),
        v3{0.1, 0.02, -0.05});
    /// A camera stamp reads this much later than the IMU's clock at the same instant.
    double time_offset = 0.005;
    v3 gravity{0, 0, -9.81};
};

struct imu_reading {
    double time;
    v3 gyroscope, accelerometer;
};

struct camera_reading {
    double stamp;                  ///< the camera's clock
    dual_quaternion<double> pose;  ///< camera to world, noisy
};

/// The IMU's readings at imu_rate over [0, duration): angular velocity and specific force
/// R^T (p'' - g) in the body frame, each plus its bias and white noise.
inline std::vector<imu_reading> simulate_imu(const sensor_setup& s, generator& g) {
    std::vector<imu_reading> out;
    const int count = static_cast<int>(std::lround(s.duration * s.imu_rate));
    for (int i = 0; i < count; ++i) {
        const double t = i / s.imu_rate;
        const state x = truth(t);
        const v3 gyroscope_noise = g.gaussian(s.gyroscope_noise);
        const v3 accelerometer_noise = g.gaussian(s.accelerometer_noise);
        out.push_back({t, x.angular_velocity + s.gyroscope_bias + gyroscope_noise,
                       quat::rotate(quat::conjugate(x.rotation), x.acceleration - s.gravity) +
                           s.accelerometer_bias + accelerometer_noise});
    }
    return out;
}

/// The camera's pose (body pose times extrinsic), turned by a random small rotation in its own
/// frame and moved by a random shift, stamped on the camera's clock: stamps k / camera_rate for
/// k = 1 .. duration * camera_rate, taken at IMU time stamp - time_offset.
inline std::vector<camera_reading> simulate_camera(const sensor_setup& s, generator& g) {
    std::vector<camera_reading> out;
    const int count = static_cast<int>(std::lround(s.duration * s.camera_rate));
    for (int k = 1; k <= count; ++k) {
        const double stamp = k / s.camera_rate;
        const state x = truth(stamp - s.time_offset);
        const dual_quaternion<double> camera =
            quat::to_dual_quaternion(x.rotation, x.position) * s.extrinsic;
        const v3 turn = g.gaussian(s.camera_angle_noise);
        const v3 shift = g.gaussian(s.camera_position_noise);
        out.push_back({stamp, quat::to_dual_quaternion(
                                  quat::rotation_of(camera) * quat::from_rotation_vector(turn),
                                  quat::translation_of(camera) + shift)});
    }
    return out;
}

/// The covariance of a body pose made from a camera reading (camera pose times the extrinsic's
/// inverse), as the 6-vector (position error, rotation error), the rotation error a rotation
/// vector in the body frame, the position error in the world frame (world_position, the split
/// residual's p - p_Z) or in the measured body frame (the SE(3) residual's linear part, to first
/// order). The camera's turn n (camera frame) turns the body by R_x n and, through the lever arm
/// t_x, moves it by R_b [t_x]x R_x n besides the camera's own shift: 1.0 mm against 10 mm here, but
/// correlated with the rotation error, so the weights model it rather than drop it.
inline quat::matrix6<double> body_pose_covariance(const sensor_setup& s, const quatd& body_rotation,
                                                  bool world_position) {
    const quat::matrix3<double> R_x =
        quat::to_matrix3(quat::to_matrix(quat::rotation_of(s.extrinsic)));
    quat::matrix3<double> A = quat::so3::hat(quat::translation_of(s.extrinsic)) * R_x;
    if (world_position) A = quat::to_matrix3(quat::to_matrix(body_rotation)) * A;
    const double position = s.camera_position_noise * s.camera_position_noise;
    const double angle = s.camera_angle_noise * s.camera_angle_noise;
    const quat::matrix3<double> pp =
        quat::matrix3<double>::identity() * position + A * quat::transpose(A) * angle;
    const quat::matrix3<double> pr = A * quat::transpose(R_x) * angle;
    quat::matrix6<double> c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            c(i, j) = pp(i, j);
            c(i, j + 3) = pr(i, j);
            c(i + 3, j) = pr(j, i);
            c(i + 3, j + 3) = i == j ? angle : 0.0;
        }
    return c;
}

/// Root-mean-square errors of estimated states against the truth.
struct rms_errors {
    double position = 0, orientation = 0, velocity = 0, acceleration = 0, angular_velocity = 0;

    /// Over corresponding elements of `estimated` and `truth`; orientation as the angle between.
    static rms_errors between(const std::vector<state>& estimated,
                              const std::vector<state>& truth) {
        rms_errors e;
        for (std::size_t i = 0; i < estimated.size(); ++i) {
            const state &a = estimated[i], &b = truth[i];
            e.position += quat::squared_norm(a.position - b.position);
            e.orientation += std::pow(quat::angle_between(a.rotation, b.rotation), 2);
            e.velocity += quat::squared_norm(a.velocity - b.velocity);
            e.acceleration += quat::squared_norm(a.acceleration - b.acceleration);
            e.angular_velocity += quat::squared_norm(a.angular_velocity - b.angular_velocity);
        }
        const double count = static_cast<double>(estimated.size());
        double* const sums[] = {&e.position, &e.orientation, &e.velocity, &e.acceleration,
                                &e.angular_velocity};
        for (double* x : sums) *x = std::sqrt(*x / count);
        return e;
    }
};

}  // namespace camera_imu
