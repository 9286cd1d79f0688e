// The rules both keyframe paths of quat/trajectory share, as checks and measures templated on the
// path: over random keyframe sets, at the edges of their domain, and for batches.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include <quat/rigid/dual_quaternion.hpp>
#include <quat/trajectory/keyframe_path_state.hpp>

#include "catch.hpp"
#include "keyframe_poses.hpp"
#include "random.hpp"

namespace quat::test {

template <class T>
bool all_nan(const vec3<T>& v) {
    return std::isnan(v.x) && std::isnan(v.y) && std::isnan(v.z);
}
template <class T>
bool all_nan(const quaternion<T>& q) {
    return std::isnan(q.w) && std::isnan(q.x) && std::isnan(q.y) && std::isnan(q.z);
}
template <class T>
bool all_nan(const dual_quaternion<T>& x) {
    return all_nan(x.real) && all_nan(x.dual);
}
template <class T>
bool all_nan(const keyframe_path_state<T>& s) {
    return all_nan(s.pose) && all_nan(s.velocity) && all_nan(s.acceleration) &&
           all_nan(s.angular_velocity) && all_nan(s.angular_acceleration) &&
           all_nan(s.body_velocity) && all_nan(s.body_acceleration) &&
           all_nan(s.body_angular_velocity) && all_nan(s.body_angular_acceleration);
}

/// Every member of a path without keyframes gives NaN, at any time, singly and in batches.
template <class Path>
void check_evaluates_to_nan(const Path& path) {
    using T = double;
    for (const T t : {T(-1), T(0), T(0.5), T(1), T(2)}) {
        INFO("t = " << t);
        CHECK(all_nan(path(t)));
        CHECK(all_nan(path.state(t)));
    }
    const std::vector<T> ts{T(0), T(0.5), T(1)};
    std::vector<dual_quaternion<T>> poses(ts.size(), dual_quaternion<T>::identity());
    std::vector<keyframe_path_state<T>> states(ts.size());
    path.evaluate(ts, poses);
    path.evaluate(ts, states);
    for (std::size_t k = 0; k < ts.size(); ++k) {
        CHECK(all_nan(poses[k]));
        CHECK(all_nan(states[k]));
    }
}

/// try_make's refusals, NaN times, moved-from paths, and (release builds) bad sizes.
template <template <class> class Path>
void check_edge_rules() {
    using DQ = dual_quaternion<double>;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double infinity = std::numeric_limits<double>::infinity();
    const DQ a = DQ::identity();
    const DQ b = to_dual_quaternion(quaternion<double>{0.6, 0.8, 0.0, 0.0}, vec3<double>{1, 2, 3});
    const auto make = [](const std::vector<double>& times, const std::vector<DQ>& poses) {
        return Path<double>::try_make(times, poses).has_value();
    };
    CHECK(make({0.0, 1.0, 2.0}, {a, b, a}));
    CHECK(make({0.0, 1.0}, {a, b * 2.0}));  // any non-zero scale, normalized
    CHECK(make({0.0, 1.0}, {a, -b}));       // either sign
    CHECK_FALSE(make({}, {}));
    CHECK_FALSE(make({0.0}, {a}));
    CHECK_FALSE(make({0.0, 1.0, 2.0}, {a, b}));
    CHECK_FALSE(make({0.0, 1.0}, {a, b, a}));
    CHECK_FALSE(make({0.0, 1.0, 1.0}, {a, b, a}));  // repeated
    CHECK_FALSE(make({0.0, 2.0, 1.0}, {a, b, a}));  // unsorted
    CHECK_FALSE(make({0.0, nan, 2.0}, {a, b, a}));
    CHECK_FALSE(make({0.0, 1.0, infinity}, {a, b, a}));
    CHECK_FALSE(make({0.0, 1.0, 2.0}, {a, DQ{{nan, 0, 0, 0}, {0, 0, 0, 0}}, a}));
    CHECK_FALSE(make({0.0, 1.0, 2.0}, {a, DQ{{1, 0, 0, 0}, {0, infinity, 0, 0}}, a}));
    CHECK_FALSE(make({0.0, 1.0, 2.0}, {a, DQ{{0, 0, 0, 0}, {0, 1, 0, 0}}, a}));
    // A NaN time gives NaN; a moved-from path evaluates to NaN.
    const std::vector<double> times{0.0, 1.0, 2.0};
    const std::vector<DQ> poses{a, b, a};
    Path<double> path(times, poses);
    CHECK(all_nan(path(nan)));
    CHECK(all_nan(path.state(nan)));
    const Path<double> moved_to(std::move(path));
    CHECK(moved_to(1.0) == normalize(b));
    check_evaluates_to_nan(path);  // NOLINT(bugprone-use-after-move): the state under test
#ifdef NDEBUG
    // Debug builds stop at these preconditions; release builds give the documented NaN, or for
    // unsorted, repeated or non-finite times and NaN poses some values, never undefined behaviour
    // (run under AddressSanitizer and UBSan in CI).
    check_evaluates_to_nan(Path<double>(std::vector<double>{}, std::vector<DQ>{}));
    check_evaluates_to_nan(Path<double>(std::vector<double>{0.0}, std::vector<DQ>{a}));
    check_evaluates_to_nan(Path<double>(std::vector<double>{0.0, 1.0, 2.0}, std::vector<DQ>{a, b}));
    check_evaluates_to_nan(Path<double>(std::vector<double>{0.0, 1.0}, std::vector<DQ>{a, b, a}));
    for (const std::vector<double>& bad :
         {std::vector<double>{0.0, 1.0, 1.0, 3.0}, std::vector<double>{0.0, 2.0, 1.0, 3.0},
          std::vector<double>{0.0, nan, 1.0, 3.0}, std::vector<double>{0.0, 1.0, 2.0, infinity}}) {
        const Path<double> odd(bad, std::vector<DQ>{a, b, a, b});
        static_cast<void>(odd.state(0.5));
        static_cast<void>(odd(2.5));
    }
    const Path<double> nan_pose(std::vector<double>{0.0, 1.0, 2.0},
                                std::vector<DQ>{a, DQ{{nan, 0, 0, 0}, {0, 0, 0, 0}}, a});
    CHECK_FALSE(std::isfinite(nan_pose.state(0.5).velocity.x));
    // A shorter output is filled up to its length.
    const Path<double> good(times, poses);
    std::vector<DQ> out(2, DQ::identity());
    good.evaluate(std::vector<double>{0.0, 1.0, 2.0}, out);
    CHECK(out[1] == normalize(b));
#endif
}

/// evaluate gives what single calls give, for poses and states, in any order of times: 30 random
/// keyframes, 440 times from before the first to after the last, a keyframe and the end.
template <template <class> class Path>
void check_batch(random_rotations& random) {
    std::vector<double> times, ts;
    std::vector<dual_quaternion<double>> poses;
    random_pose_keyframes(random, 30, 1.5, 1.0, 10.0, times, poses);
    for (int k = -20; k < 420; ++k)
        ts.push_back(times.front() + (times.back() - times.front()) * k / 400.0);
    ts.push_back(times[7]);
    ts.push_back(times.back());
    const Path<double> path(times, poses);
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<dual_quaternion<double>> batch_poses(ts.size());
        std::vector<keyframe_path_state<double>> states(ts.size());
        path.evaluate(ts, batch_poses);
        path.evaluate(ts, states);
        bool same = true;
        for (std::size_t k = 0; k < ts.size(); ++k) {
            const keyframe_path_state<double> s = path.state(ts[k]);
            same = same && batch_poses[k] == path(ts[k]) && states[k].pose == s.pose &&
                   states[k].velocity == s.velocity && states[k].acceleration == s.acceleration &&
                   states[k].body_angular_acceleration == s.body_angular_acceleration;
        }
        CHECK(same);
        std::reverse(ts.begin(), ts.end());
    }
}

/// The worst misses at the keyframes over 50 random sets of 2 to 31 keyframes (rotation steps up
/// to 2.5 rad, durations unequal by up to 10x).
template <template <class> class Path, class T>
keyframe_misses misses_over_random_sets(random_rotations& random) {
    std::vector<T> times;
    std::vector<dual_quaternion<T>> poses;
    keyframe_misses worst;
    for (int n = 0; n < 50; ++n) {
        random_pose_keyframes(random, 2 + std::size_t(n % 30), 2.5, 1.0, 10.0, times, poses);
        const keyframe_misses m = misses_at_keyframes(Path<T>(times, poses), times, poses);
        worst = {std::max(worst.angle, m.angle), std::max(worst.position, m.position)};
    }
    return worst;
}

/// The worst jumps at the inner keyframes over `sets` random sets of 3 to 2 + `sizes` keyframes
/// (rotation steps up to `max_angle` rad, durations unequal by up to `ratio`), and in `made` the
/// number of sets try_make gave a path for (the others are skipped).
template <template <class> class Path, class T>
jumps jumps_over_random_sets(random_rotations& random, int sets, int sizes, double max_angle,
                             double ratio, int& made) {
    std::vector<T> times;
    std::vector<dual_quaternion<T>> poses;
    jumps worst;
    made = 0;
    for (int n = 0; n < sets; ++n) {
        random_pose_keyframes(random, 3 + std::size_t(n % sizes), max_angle, 1.0, ratio, times,
                              poses);
        const std::optional<Path<T>> path = Path<T>::try_make(times, poses);
        if (!path) continue;
        ++made;
        worst = worse(worst, jumps_at_keyframes(*path, times));
    }
    return worst;
}

/// The worst derivative_errors (h = 1e-5 s, against the same path in long double) at 50 random
/// times of each of 20 random sets of 10 keyframes (rotation steps up to 2 rad, durations unequal
/// by up to 5x).
template <template <class> class Path>
jumps derivative_errors_over_random_sets(random_rotations& random) {
    std::vector<double> times;
    std::vector<dual_quaternion<double>> poses;
    jumps worst;
    for (int n = 0; n < 20; ++n) {
        random_pose_keyframes(random, 10, 2.0, 1.0, 5.0, times, poses);
        const Path<double> path(times, poses);
        const Path<long double> reference(std::vector<long double>(times.begin(), times.end()),
                                          converted<long double>(poses));
        std::vector<double> ts;
        for (int k = 0; k < 50; ++k)
            ts.push_back(random.uniform<double>(times.front(), times.back()));
        worst = worse(worst, derivative_errors(path, reference, ts, 1e-5L));
    }
    return worst;
}

}  // namespace quat::test

namespace quat::test {

template <class T>
bool is_finite_state(const keyframe_path_state<T>& s) {
    const auto finite = [](const vec3<T>& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    return std::isfinite(s.pose.real.w) && std::isfinite(s.pose.dual.x) && finite(s.velocity) &&
           finite(s.acceleration) && finite(s.body_angular_velocity) &&
           finite(s.body_angular_acceleration) && finite(s.body_velocity) &&
           finite(s.body_acceleration);
}

/// Over times scaled by powers of two across T's whole range, try_make gives a path whose
/// values between its keyframes are finite, or nothing; and both happen.
template <template <class> class Path, class T>
void check_try_make_bounds(random_rotations& random) {
    std::vector<T> times, scaled;
    std::vector<dual_quaternion<T>> poses;
    const int lowest = std::numeric_limits<T>::min_exponent - std::numeric_limits<T>::digits;
    int engaged = 0, empty = 0;
    for (int n = 0; n < 6; ++n) {
        random_pose_keyframes(random, 3 + std::size_t(n % 8), 2.5, 1.0, 10.0, times, poses);
        for (int exponent = lowest; exponent <= std::numeric_limits<T>::max_exponent;
             exponent += 8) {
            INFO("set " << n << ", times scaled by 2^" << exponent);
            scaled.clear();
            for (const T t : times) scaled.push_back(std::ldexp(t, exponent));
            const std::optional<Path<T>> path = Path<T>::try_make(scaled, poses);
            if (!path) {
                ++empty;
                continue;
            }
            ++engaged;
            bool finite = true;
            for (int k = 0; k <= 50; ++k) {
                const T t = scaled.front() + (scaled.back() - scaled.front()) * (T(k) / T(50));
                finite = finite && is_finite_state(path->state(t));
            }
            CHECK(finite);
        }
    }
    CHECK(engaged > 0);
    CHECK(empty > 0);
}

}  // namespace quat::test
