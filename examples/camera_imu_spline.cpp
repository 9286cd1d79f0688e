// camera_imu_spline: a continuous-time trajectory fitted to a simulated camera-IMU run with Ceres
// (quat/interop/ceres_trajectory.hpp's residuals on trajectory/'s B-splines). Over 10 s a body
// flies a figure-eight while yawing, pitching and rolling (camera_imu_run.hpp has it in closed
// form). It carries
//   an IMU at 200 Hz: gyroscope = angular velocity + bias (0.02, -0.015, 0.01) rad/s + white noise
//     0.005 rad/s; accelerometer = R^T (p'' - g) + bias (0.1, -0.08, 0.12) m/s^2 + white noise
//     0.05 m/s^2 (standard deviations per sample and axis), g = (0, 0, -9.81);
//   a camera at 20 Hz, mounted 10 cm ahead looking along the body's x axis (the extrinsic, known),
//     measuring its pose with 1 cm and 0.5 degree of noise per axis, its stamps 5 ms late on the
//     IMU's clock (the offset, known).
// Each camera pose becomes a body pose (times the extrinsic's inverse) at the IMU time of the
// exposure (stamp - offset). A cubic (K = 4) spline with knots every 0.1 s, its control points
// interpolated from those body poses and both biases zero at the start, is fitted to all
// measurements: the IMU's weighted by their inverse standard deviations, the body poses' by the
// inverse Cholesky factor of their covariance (the camera's turn also moves the body through the
// lever arm: camera_imu_run.hpp's body_pose_covariance). Once as split_bspline (SO(3) x R^3,
// drawn) and once as se3_bspline (printed beside it). Ceres: sparse normal Cholesky, one thread,
// at most 50 iterations; the biases' standard errors from ceres::Covariance.
// Run: example_camera_imu_spline [output directory]  -> camera_imu_spline.svg
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ceres/covariance.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <Eigen/Cholesky>
#include <quat/interop/ceres_trajectory.hpp>
#include <quat/quat.hpp>

#include "camera_imu_run.hpp"
#include "camera_imu_spline_picture.hpp"
#include "check.hpp"

using namespace quat;
using camera_imu::state;
using camera_imu::v3;

namespace {

constexpr std::size_t order = 4;
constexpr double degree = numbers::pi / 180;
constexpr double knot_spacing = 0.1;

struct pose_measurement {
    double time;  ///< IMU clock
    dual_quaternion<double> pose;
};

/// The body pose at `time` from the measurements on either side: slerp and lerp between them, the
/// end measurement beyond the ends.
dual_quaternion<double> interpolate(const std::vector<pose_measurement>& poses, double time) {
    std::size_t k = 0;
    while (k + 2 < poses.size() && poses[k + 1].time <= time) ++k;
    const double u =
        std::clamp((time - poses[k].time) / (poses[k + 1].time - poses[k].time), 0.0, 1.0);
    const dual_quaternion<double>&a = poses[k].pose, &b = poses[k + 1].pose;
    return to_dual_quaternion(slerp(rotation_of(a), rotation_of(b), u),
                              lerp(translation_of(a), translation_of(b), u));
}

struct fit_result {
    std::vector<state> fitted;  ///< at the IMU's times
    v3 gyroscope_bias{}, accelerometer_bias{};
    v3 gyroscope_sigma{}, accelerometer_sigma{};  ///< standard errors; zero if not computed
    int iterations = 0, residual_blocks = 0;
    double seconds = 0, initial_cost = 0, final_cost = 0;
    /// 2 cost / (residuals - parameters): near 1 when the residuals are at the noise level.
    double cost_per_freedom = 0;
    bool converged = false;
};

/// The run and the fit's settings shared by both spline kinds.
struct run {
    camera_imu::sensor_setup setup;
    std::vector<camera_imu::imu_reading> imu;
    std::vector<pose_measurement> body_poses;
    std::size_t control_points;

    /// The time control point j weighs most: its basis function peaks there.
    [[nodiscard]] double centre_of(std::size_t j) const {
        return (static_cast<double>(j) - (order - 2) / 2.0) * knot_spacing;
    }
    /// The weight of a reading whose axes each have standard deviation sigma, uncorrelated.
    [[nodiscard]] matrix3<double> weight(double sigma) const {
        return matrix3<double>::identity() * (1 / sigma);
    }
    /// S with S C S^T = I for the covariance C of a body pose measured with `rotation`
    /// (body_pose_covariance): L^-1 for C = L L^T.
    [[nodiscard]] matrix6<double> pose_weight(const quatd& rotation, bool world_position) const {
        const matrix6<double> c = camera_imu::body_pose_covariance(setup, rotation, world_position);
        Eigen::Matrix<double, 6, 6> covariance;
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) covariance(i, j) = c(i, j);
        const Eigen::Matrix<double, 6, 6> inverse_factor =
            covariance.llt().matrixL().solve(Eigen::Matrix<double, 6, 6>::Identity());
        matrix6<double> s{};
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j) s(i, j) = inverse_factor(i, j);
        return s;
    }
};

/// Solves `problem`, then fills the result's solver figures and the biases' standard errors.
void solve(ceres::Problem& problem, double* gyroscope_bias, double* accelerometer_bias,
           fit_result& result) {
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    options.max_num_iterations = 50;
    options.num_threads = 1;
    ceres::Solver::Summary summary;
    result.residual_blocks = problem.NumResidualBlocks();
    const auto start = std::chrono::steady_clock::now();
    ceres::Solve(options, &problem, &summary);
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
    result.initial_cost = summary.initial_cost;
    result.final_cost = summary.final_cost;
    result.converged = summary.termination_type == ceres::CONVERGENCE;
    result.cost_per_freedom =
        2 * summary.final_cost / (summary.num_residuals - summary.num_effective_parameters);
    result.gyroscope_bias = vec3_from_parameters(gyroscope_bias);
    result.accelerometer_bias = vec3_from_parameters(accelerometer_bias);
    ceres::Covariance::Options covariance_options;
    covariance_options.num_threads = 1;
    ceres::Covariance covariance(covariance_options);
    const std::vector<std::pair<const double*, const double*>> blocks{
        {gyroscope_bias, gyroscope_bias}, {accelerometer_bias, accelerometer_bias}};
    if (!covariance.Compute(blocks, &problem)) return;  // sigmas stay zero: the checks fail
    double c[9];
    const auto sigmas = [&] { return v3{std::sqrt(c[0]), std::sqrt(c[4]), std::sqrt(c[8])}; };
    covariance.GetCovarianceBlock(gyroscope_bias, gyroscope_bias, c);
    result.gyroscope_sigma = sigmas();
    covariance.GetCovarianceBlock(accelerometer_bias, accelerometer_bias, c);
    result.accelerometer_sigma = sigmas();
}

fit_result fit_split(const run& r) {
    const std::size_t n = r.control_points;
    std::vector<double> rotations(4 * n), positions(3 * n);
    double gyroscope_bias[3] = {0, 0, 0}, accelerometer_bias[3] = {0, 0, 0};
    for (std::size_t j = 0; j < n; ++j) {
        const dual_quaternion<double> x = interpolate(r.body_poses, r.centre_of(j));
        write_parameters(rotation_of(x), &rotations[4 * j]);
        write_parameters(translation_of(x), &positions[3 * j]);
    }
    // segment_at reads only the knots, so a view of the initial points finds every segment.
    std::vector<quatd> start(n);
    for (std::size_t j = 0; j < n; ++j) start[j] = quaternion_from_parameters(&rotations[4 * j]);
    const so3_bspline<double, order> knots(start, 0.0, knot_spacing);
    const auto blocks = [&](std::size_t first, bool with_positions, double* bias) {
        std::vector<double*> b;
        for (std::size_t m = 0; m < order; ++m) b.push_back(&rotations[4 * (first + m)]);
        for (std::size_t m = 0; with_positions && m < order; ++m)
            b.push_back(&positions[3 * (first + m)]);
        if (bias != nullptr) b.push_back(bias);
        return b;
    };
    ceres::Problem::Options problem_options;
    problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(problem_options);
    const camera_imu::sensor_setup& s = r.setup;
    for (const pose_measurement& z : r.body_poses) {
        const std::optional<bspline_segment<double>> at = knots.segment_at(z.time);
        if (!at) continue;  // outside the spline's [0, 10 s]: no reading is
        const auto [first, offset] = *at;
        problem.AddResidualBlock(
            new split_bspline_pose_cost<order>(offset, knot_spacing, z.pose,
                                               r.pose_weight(rotation_of(z.pose), true)),
            nullptr, blocks(first, true, nullptr));
    }
    for (const camera_imu::imu_reading& z : r.imu) {
        const std::optional<bspline_segment<double>> at = knots.segment_at(z.time);
        if (!at) continue;  // outside the spline's [0, 10 s]: no reading is
        const auto [first, offset] = *at;
        problem.AddResidualBlock(
            new so3_bspline_gyroscope_cost<order>(offset, knot_spacing, z.gyroscope,
                                                  r.weight(s.gyroscope_noise)),
            nullptr, blocks(first, false, gyroscope_bias));
        problem.AddResidualBlock(
            new split_bspline_accelerometer_cost<order>(offset, knot_spacing, z.accelerometer,
                                                        s.gravity, r.weight(s.accelerometer_noise)),
            nullptr, blocks(first, true, accelerometer_bias));
    }
    quaternion_manifold manifold;
    for (std::size_t j = 0; j < n; ++j) problem.SetManifold(&rotations[4 * j], &manifold);
    fit_result result;
    solve(problem, gyroscope_bias, accelerometer_bias, result);
    std::vector<quatd> q(n);
    std::vector<v3> p(n);
    for (std::size_t j = 0; j < n; ++j) {
        q[j] = quaternion_from_parameters(&rotations[4 * j]);
        p[j] = vec3_from_parameters(&positions[3 * j]);
    }
    const split_bspline<double, order> spline(q, p, 0.0, knot_spacing);
    for (const camera_imu::imu_reading& z : r.imu) {
        const split_bspline_sample<double> x = spline.evaluate(z.time);
        result.fitted.push_back(
            {x.rotation, x.position, x.linear_velocity, x.linear_acceleration, x.angular_velocity});
    }
    return result;
}

fit_result fit_se3(const run& r) {
    const std::size_t n = r.control_points;
    std::vector<double> poses(7 * n);
    double gyroscope_bias[3] = {0, 0, 0}, accelerometer_bias[3] = {0, 0, 0};
    std::vector<dual_quaternion<double>> start(n);
    for (std::size_t j = 0; j < n; ++j) {
        start[j] = interpolate(r.body_poses, r.centre_of(j));
        write_parameters(start[j], &poses[7 * j]);
    }
    const se3_bspline<double, order> knots(start, 0.0, knot_spacing);
    const auto blocks = [&](std::size_t first, double* bias) {
        std::vector<double*> b;
        for (std::size_t m = 0; m < order; ++m) b.push_back(&poses[7 * (first + m)]);
        if (bias != nullptr) b.push_back(bias);
        return b;
    };
    ceres::Problem::Options problem_options;
    problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(problem_options);
    const camera_imu::sensor_setup& s = r.setup;
    for (const pose_measurement& z : r.body_poses) {
        const std::optional<bspline_segment<double>> at = knots.segment_at(z.time);
        if (!at) continue;  // outside the spline's [0, 10 s]: no reading is
        const auto [first, offset] = *at;
        problem.AddResidualBlock(
            new se3_bspline_pose_cost<order>(offset, knot_spacing, z.pose,
                                             r.pose_weight(rotation_of(z.pose), false)),
            nullptr, blocks(first, nullptr));
    }
    for (const camera_imu::imu_reading& z : r.imu) {
        const std::optional<bspline_segment<double>> at = knots.segment_at(z.time);
        if (!at) continue;  // outside the spline's [0, 10 s]: no reading is
        const auto [first, offset] = *at;
        problem.AddResidualBlock(
            new se3_bspline_gyroscope_cost<order>(offset, knot_spacing, z.gyroscope,
                                                  r.weight(s.gyroscope_noise)),
            nullptr, blocks(first, gyroscope_bias));
        problem.AddResidualBlock(
            new se3_bspline_accelerometer_cost<order>(offset, knot_spacing, z.accelerometer,
                                                      s.gravity, r.weight(s.accelerometer_noise)),
            nullptr, blocks(first, accelerometer_bias));
    }
    pose_manifold manifold;
    for (std::size_t j = 0; j < n; ++j) problem.SetManifold(&poses[7 * j], &manifold);
    fit_result result;
    solve(problem, gyroscope_bias, accelerometer_bias, result);
    std::vector<dual_quaternion<double>> x(n);
    for (std::size_t j = 0; j < n; ++j) x[j] = pose_from_parameters(&poses[7 * j]);
    const se3_bspline<double, order> spline(x, 0.0, knot_spacing);
    for (const camera_imu::imu_reading& z : r.imu) {
        const se3_bspline_sample<double> e = spline.evaluate(z.time);
        const quatd rotation = rotation_of(e.motion);
        const v3 v = e.velocity.linear, w = e.velocity.angular;
        // The body twist (R^T p', omega) and its derivative give R^T p'' = v' + omega x v.
        result.fitted.push_back({rotation, translation_of(e.motion), rotate(rotation, v),
                                 rotate(rotation, e.acceleration.linear + cross(w, v)), w});
    }
    return result;
}

}  // namespace

int main(int argc, char** argv) {
    using example::expect;
    const std::string out = argc > 1 ? std::string(argv[1]) : std::string(".");
    run r;
    camera_imu::generator g(20240611);
    r.imu = camera_imu::simulate_imu(r.setup, g);
    const std::vector<camera_imu::camera_reading> camera = camera_imu::simulate_camera(r.setup, g);
    const dual_quaternion<double> to_body = inverse(r.setup.extrinsic);
    std::vector<state> measured, truth_at_camera;
    std::vector<v3> camera_positions;
    for (const camera_imu::camera_reading& z : camera) {
        r.body_poses.push_back({z.stamp - r.setup.time_offset, z.pose * to_body});
        const dual_quaternion<double>& body = r.body_poses.back().pose;
        measured.push_back({rotation_of(body), translation_of(body), {}, {}, {}});
        truth_at_camera.push_back(camera_imu::truth(r.body_poses.back().time));
        camera_positions.push_back(translation_of(body));
    }
    r.control_points =
        static_cast<std::size_t>(std::lround(r.setup.duration / knot_spacing)) + order - 1;
    std::vector<double> times;
    std::vector<state> truth;
    for (const camera_imu::imu_reading& z : r.imu) {
        times.push_back(z.time);
        truth.push_back(camera_imu::truth(z.time));
    }
    const camera_imu::rms_errors camera_error =
        camera_imu::rms_errors::between(measured, truth_at_camera);
    std::printf(
        "camera_imu_spline: %d IMU readings, %d camera poses, %d control points (K = %d, "
        "knots every %.2f s)\n",
        static_cast<int>(r.imu.size()), static_cast<int>(r.body_poses.size()),
        static_cast<int>(r.control_points), static_cast<int>(order), knot_spacing);
    std::printf(
        "  the camera's body poses against truth: position RMS %.2f mm, orientation RMS "
        "%.3f deg\n",
        1e3 * camera_error.position, camera_error.orientation / degree);

    const fit_result split = fit_split(r), se3 = fit_se3(r);
    const camera_imu::rms_errors split_error = camera_imu::rms_errors::between(split.fitted, truth);
    const camera_imu::rms_errors se3_error = camera_imu::rms_errors::between(se3.fitted, truth);
    const auto report = [&](const char* name, const fit_result& f,
                            const camera_imu::rms_errors& e) {
        std::printf(
            "  %s: cost %.1f -> %.1f (2 cost / degrees of freedom %.4f), %d iterations, "
            "%.2f s\n",
            name, f.initial_cost, f.final_cost, f.cost_per_freedom, f.iterations, f.seconds);
        std::printf(
            "    RMS against truth: position %.2f mm, orientation %.3f deg, velocity "
            "%.2f mm/s, acceleration %.4f m/s^2, angular velocity %.5f rad/s\n",
            1e3 * e.position, e.orientation / degree, 1e3 * e.velocity, e.acceleration,
            e.angular_velocity);
        const v3 dg = f.gyroscope_bias - r.setup.gyroscope_bias, sg = f.gyroscope_sigma;
        const v3 da = f.accelerometer_bias - r.setup.accelerometer_bias, sa = f.accelerometer_sigma;
        std::printf(
            "    gyroscope bias error (%.6f, %.6f, %.6f) rad/s, standard error "
            "(%.6f, %.6f, %.6f)\n",
            dg.x, dg.y, dg.z, sg.x, sg.y, sg.z);
        std::printf(
            "    accelerometer bias error (%.5f, %.5f, %.5f) m/s^2, standard error "
            "(%.5f, %.5f, %.5f)\n",
            da.x, da.y, da.z, sa.x, sa.y, sa.z);
        const auto within = [](const v3& error, const v3& sigma) {
            return sigma.x > 0 && std::abs(error.x) < 4 * sigma.x &&
                   std::abs(error.y) < 4 * sigma.y && std::abs(error.z) < 4 * sigma.z;
        };
        expect(
            static_cast<std::size_t>(f.residual_blocks) == 2 * r.imu.size() + r.body_poses.size(),
            "every reading lies in the spline's domain and has its residual");
        expect(f.converged, "Ceres converges");
        // Least squares at the true noise: 2 cost / (m - n) is chi-square over its degrees of
        // freedom, about 1 +- sqrt(2 / (m - n)) = 1 +- 0.013 here.
        expect(std::abs(f.cost_per_freedom - 1) < 0.05,
               "the residuals are at the noise level: 2 cost / (residuals - parameters) within 5% "
               "of 1");
        expect(within(dg, sg), "each gyroscope bias within 4 standard errors of the truth");
        expect(within(da, sa), "each accelerometer bias within 4 standard errors of the truth");
        expect(e.position < camera_error.position / 3,
               "position RMS below a third of the camera's");
        expect(e.orientation < camera_error.orientation / 3,
               "orientation RMS below a third of the camera's");
        expect(e.velocity < 0.01, "velocity RMS below 1 cm/s");
        expect(e.acceleration < 0.05, "acceleration RMS below 0.05 m/s^2");
        expect(e.angular_velocity < 0.003, "angular velocity RMS below 0.003 rad/s");
    };
    report("split_bspline (SO(3) x R^3)", split, split_error);
    report("se3_bspline", se3, se3_error);

    picture::table biases{{"split spline", "truth", "fitted", "error / σ"}};
    picture::add_bias_rows(biases, "gyroscope", "rad/s", r.setup.gyroscope_bias,
                           split.gyroscope_bias, split.gyroscope_sigma);
    picture::add_bias_rows(biases, "accelerometer", "m/s²", r.setup.accelerometer_bias,
                           split.accelerometer_bias, split.accelerometer_sigma);
    const std::string subtitle = picture::text(
        "10 s figure-eight; IMU at 200 Hz with biases and noise, camera poses at 20 Hz "
        "(1 cm, 0.5°); cubic split B-spline, knots every %.1f s, %d Ceres iterations",
        knot_spacing, split.iterations);
    expect(picture::draw(out + "/camera_imu_spline.svg", subtitle, times, truth, split.fitted,
                         camera_positions, biases,
                         picture::error_table(split_error, se3_error, camera_error)),
           "camera_imu_spline.svg written");
    return example::failures() == 0 ? 0 : 1;
}
