// The rows of `quat_accuracy --trajectory` measured through poses alone, in double against the
// library's own long double evaluation:
// - split_bspline's body twist (R^T p', omega) and its derivative against Richardson differences
//   in time of log(X(t)^-1 X(t + s)) and of the long double twist (K = 4, 5, 6);
// - split_keyframe_path's and se3_keyframe_path's linear velocity and acceleration (world frame)
//   and body angular velocity and acceleration against Richardson differences in time of the
//   position, of log(R(t)^-1 R(t + s)) and of the long double rates (one-sided at keyframes, where
//   the paths are only C^2), and how far each path misses its keyframes.
// Sample classes as the B-splines': random times inside segments and the knots (keyframes) of
// random points, then both kinds of time for steps near the identity and near a half turn.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <quat/lie/se3.hpp>
#include <quat/lie/so3.hpp>
#include <quat/trajectory/se3_keyframe_path.hpp>
#include <quat/trajectory/split_bspline.hpp>
#include <quat/trajectory/split_keyframe_path.hpp>

#include "measure_trajectory_bspline.hpp"
#include "support/keyframe_poses.hpp"
#include "support/random.hpp"
#include "trajectory_differences.hpp"

namespace accuracy {
namespace trajectory {

// The keyframe paths pass through their keyframes within 4 eps (the tests' bound).
constexpr double bound_keyframes = 4;

template <class S>
std::array<S, 3> flat3(const quat::vec3<S>& v) {
    return {v.x, v.y, v.z};
}

// ---- split_bspline ------------------------------------------------------------------------------

/// Positions for the control points of class `kind`: a random walk of steps about 1, or of steps
/// below 1e-7 from the origin (near identity); half turns move as the random class.
inline std::vector<quat::vec3<double>> positions(quat::test::random_rotations& random, int kind,
                                                 std::size_t count) {
    const double reach = kind == 1 ? 1e-7 : 1;
    std::vector<quat::vec3<double>> out{kind == 1 ? quat::vec3<double>{0, 0, 0}
                                                  : random.vector<double>(reach)};
    while (out.size() < count) out.push_back(out.back() + random.vector<double>(reach));
    return out;
}

template <int K>
void measure_split_set(const std::vector<quat::quaternion<double>>& rotations,
                       const std::vector<quat::vec3<double>>& places, int point_class, double t0,
                       double dt, const std::vector<sample_time>& times,
                       std::vector<measured_row>& rows, std::size_t column,
                       const std::string& set) {
    std::vector<quat::quaternion<ld>> wide_rotations(rotations.begin(), rotations.end());
    std::vector<quat::vec3<ld>> wide_places(places.begin(), places.end());
    const quat::split_bspline<double, K> spline(rotations, places, t0, dt);
    const quat::split_bspline<ld, K> wide(wide_rotations, wide_places, ld(t0), ld(dt));
    const auto pose = [&](ld t) {
        const quat::split_bspline_sample<ld> s = wide.evaluate(t);
        return to_dual_quaternion(s.rotation, s.position);
    };
    // The twist's and its rate's largest entries over the set's times (scaled_error's scale).
    ld twist_scale = 0, rate_scale = 0;
    for (const sample_time& st : times) {
        const quat::split_bspline_sample<ld> s = wide.evaluate(ld(st.t));
        twist_scale = std::max(twist_scale, largest_entry(se3_kind::flat(s.body_velocity)));
        rate_scale = std::max(rate_scale, largest_entry(se3_kind::flat(s.body_acceleration)));
    }
    for (const sample_time& st : times) {
        const int cls = point_class == 0 ? (st.knot ? 1 : 0) : point_class + 1;
        char at[96];
        std::snprintf(at, sizeof at, "%s, t = %.17g", set.c_str(), st.t);
        const quat::split_bspline_sample<double> s = spline.evaluate(st.t);
        const ld t = st.t, h = 1e-3L * dt;
        const int side = !st.knot ? 0 : (st.t == spline.end_time() ? -1 : 1);
        const quat::dual_quaternion<ld> base = pose(t);
        const auto twist = time_rate<6>(
            [&](ld step) { return se3_kind::flat(quat::se3::minus(pose(t + step), base)); }, h,
            side);
        const auto rate = time_rate<6>(
            [&](ld step) { return se3_kind::flat(wide.evaluate(t + step).body_velocity); }, h,
            side);
        rows[0].columns[column][static_cast<std::size_t>(cls)].add(
            scaled_error(se3_kind::flat(s.body_velocity), twist, twist_scale), at);
        rows[1].columns[column][static_cast<std::size_t>(cls)].add(
            scaled_error(se3_kind::flat(s.body_acceleration), rate, rate_scale), at);
    }
}

/// split_bspline's two twist rows at K = 4, 5, 6.
inline std::vector<measured_row> measure_split_bspline(int sets, int random_times,
                                                       std::uint64_t seed) {
    std::vector<measured_row> rows;
    for (const char* quantity : {"ξ vs time differences of the pose", "ξ′ vs time differences"})
        rows.push_back({"split_bspline", quantity, "relative", bound_differences,
                        std::vector<std::array<worst_error, class_count>>(3)});
    const auto order = [&](auto k, std::size_t column, double t0, double dt) {
        constexpr int K = decltype(k)::value;
        quat::test::random_rotations random(seed + 211 * column);
        for (int point_class = 0; point_class < 3; ++point_class)
            for (int n = 0; n < sets; ++n) {
                const auto rotations = so3_kind::points(random, point_class, 12);
                const auto places = positions(random, point_class, 12);
                const auto times = sample_times<K>(random, 12, t0, dt, random_times);
                const std::string set = "K=" + std::to_string(K) + " " + set_names[point_class] +
                                        " set " + std::to_string(n);
                measure_split_set<K>(rotations, places, point_class, t0, dt, times, rows, column,
                                     set);
            }
    };
    order(std::integral_constant<int, 4>{}, 0, 0.25, 0.5);
    order(std::integral_constant<int, 5>{}, 1, -1.0, 0.75);
    order(std::integral_constant<int, 6>{}, 2, 2.0, 0.3125);
    return rows;
}

// ---- keyframe paths -----------------------------------------------------------------------------

/// Keyframes X_(i+1) = X_i (step): rotation steps up to 2 rad and translation steps of about 1
/// (kind 0), both below 1e-7 from the identity (1), rotation steps of pi - 1e-2 rad (2);
/// durations 0.05 to 0.5 (log-uniform); random signs.
inline void keyframes(quat::test::random_rotations& random, int kind, std::size_t count,
                      std::vector<double>& times,
                      std::vector<quat::dual_quaternion<double>>& poses) {
    const double low = kind == 2 ? pi - 1e-2 : 0, high = kind == 0 ? 2 : kind == 1 ? 1e-7 : low;
    const double reach = kind == 1 ? 1e-7 : 1;
    times.assign(1, 0.0);
    poses.assign(
        1, kind == 1 ? quat::dual_quaternion<double>::identity() : random.rigid_motion<double>());
    while (poses.size() < count) {
        times.push_back(times.back() +
                        0.05 * std::exp(std::log(10.0) * random.uniform<double>(0, 1)));
        const quat::vec3<double> axis = random.unit_vector<double>();
        const quat::vec3<double> step = axis * random.uniform<double>(low, high);
        const quat::vec3<double> shift = random.vector<double>(reach);
        const quat::dual_quaternion<double> next =
            poses.back() * to_dual_quaternion(from_rotation_vector(step), shift);
        poses.push_back(random.uniform<double>(0, 1) < 0.5 ? -next : next);
    }
}

template <template <class> class Path>
void measure_path_set(const std::vector<double>& times,
                      const std::vector<quat::dual_quaternion<double>>& poses, int point_class,
                      int random_times, quat::test::random_rotations& random,
                      std::vector<measured_row>& rows, std::size_t column, const std::string& set) {
    const Path<double> path(times, poses);
    const Path<ld> wide(std::vector<ld>(times.begin(), times.end()),
                        quat::test::converted<ld>(poses));
    std::vector<sample_time> samples;
    for (const double t : times) samples.push_back({t, true});
    for (int n = 0; n < random_times; ++n) {
        const auto i = static_cast<std::size_t>(
            std::floor(random.uniform<double>(0, static_cast<double>(times.size() - 1))));
        samples.push_back(
            {times[i] + random.uniform<double>(0.05, 0.95) * (times[i + 1] - times[i]), false});
    }
    const auto cell = [&](std::size_t r, bool knot) -> worst_error& {
        const int cls = point_class == 0 ? (knot ? 1 : 0) : point_class + 1;
        return rows[r].columns[column][static_cast<std::size_t>(cls)];
    };
    // Each rate's largest entry over the set's times (scaled_error's scale).
    std::array<ld, 4> scale{};
    for (const sample_time& st : samples) {
        const quat::keyframe_path_state<ld> w = wide.state(ld(st.t));
        const std::array<std::array<ld, 3>, 4> rates{flat3(w.velocity), flat3(w.acceleration),
                                                     flat3(w.body_angular_velocity),
                                                     flat3(w.body_angular_acceleration)};
        for (std::size_t k = 0; k < 4; ++k) scale[k] = std::max(scale[k], largest_entry(rates[k]));
    }
    for (const sample_time& st : samples) {
        char at[96];
        std::snprintf(at, sizeof at, "%s, t = %.17g", set.c_str(), st.t);
        // The step is 1e-3 of the duration of the segment the differences read.
        const auto next = static_cast<std::size_t>(
            std::upper_bound(times.begin(), times.end(), st.t) - times.begin());
        const bool last = st.t == times.back();
        const std::size_t i = last ? times.size() - 1 : next;
        const double duration = times[i] - times[i - 1];
        const int side = !st.knot ? 0 : (last ? -1 : 1);
        const ld t = st.t, h = 1e-3L * duration;
        const quat::keyframe_path_state<double> s = path.state(st.t);
        const quat::keyframe_path_state<ld> base = wide.state(t);
        const auto state = [&](ld step) { return wide.state(t + step); };
        const auto velocity =
            time_rate<3>([&](ld step) { return flat3(translation_of(state(step).pose)); }, h, side);
        const auto angular = time_rate<3>(
            [&](ld step) { return flat3(quat::so3::minus(state(step).pose.real, base.pose.real)); },
            h, side);
        const auto acceleration =
            time_rate<3>([&](ld step) { return flat3(state(step).velocity); }, h, side);
        const auto angular_rate = time_rate<3>(
            [&](ld step) { return flat3(state(step).body_angular_velocity); }, h, side);
        cell(0, st.knot).add(scaled_error(flat3(s.velocity), velocity, scale[0]), at);
        cell(1, st.knot).add(scaled_error(flat3(s.acceleration), acceleration, scale[1]), at);
        cell(2, st.knot).add(scaled_error(flat3(s.body_angular_velocity), angular, scale[2]), at);
        cell(3, st.knot)
            .add(scaled_error(flat3(s.body_angular_acceleration), angular_rate, scale[3]), at);
    }
    const quat::test::keyframe_misses m = quat::test::misses_at_keyframes(path, times, poses);
    constexpr double eps = std::numeric_limits<double>::epsilon();
    cell(4, true).add(m.angle / eps, set);
    cell(5, true).add(m.position / eps, set);
}

/// The keyframe paths' rows: column 0 split_keyframe_path, column 1 se3_keyframe_path; `sets` sets
/// of 12 keyframes per class, every keyframe and `random_times` random times each.
inline std::vector<measured_row> measure_keyframe_paths(int sets, int random_times,
                                                        std::uint64_t seed) {
    std::vector<measured_row> rows;
    const auto add = [&](const char* quantity, const char* unit, double bound) {
        rows.push_back({"keyframe paths", quantity, unit, bound,
                        std::vector<std::array<worst_error, class_count>>(2)});
    };
    add("v (world) vs time differences of the position", "relative", bound_differences);
    add("a (world) vs time differences of v", "relative", bound_differences);
    add("ω (body) vs time differences of the rotation", "relative", bound_differences);
    add("ω′ (body) vs time differences of ω", "relative", bound_differences);
    add("keyframes reproduced: rotation angle", "eps", bound_keyframes);
    add("keyframes reproduced: position / (1 + \\|p\\|)", "eps", bound_keyframes);
    for (std::size_t column = 0; column < 2; ++column) {
        quat::test::random_rotations random(seed + 307 * column);
        std::vector<double> times;
        std::vector<quat::dual_quaternion<double>> poses;
        for (int point_class = 0; point_class < 3; ++point_class)
            for (int n = 0; n < sets; ++n) {
                keyframes(random, point_class, 12, times, poses);
                const std::string set = std::string(column == 0 ? "split" : "se3") + " " +
                                        set_names[point_class] + " set " + std::to_string(n);
                if (column == 0)
                    measure_path_set<quat::split_keyframe_path>(
                        times, poses, point_class, random_times, random, rows, column, set);
                else
                    measure_path_set<quat::se3_keyframe_path>(
                        times, poses, point_class, random_times, random, rows, column, set);
            }
    }
    return rows;
}

}  // namespace trajectory
}  // namespace accuracy
