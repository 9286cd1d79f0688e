// Specification of paths/keyframe_squad.hpp: squad through keyframes at given times, its control
// points scaled for uneven spacing. Checked against squad and squad_control (evenly spaced times),
// against the angular velocity the derivation predicts (one-sided finite differences in long
// double), and against keyframe_slerp's handling of the ends and of bad input.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

#include <quat/kinematics.hpp>
#include <quat/paths/keyframe_slerp.hpp>
#include <quat/paths/keyframe_squad.hpp>
#include <quat/paths/squad.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_keyframe_squad {

using quat::quaternion;
using quat::vec3;
using quat::test::eps;

namespace {

// Increasing times from `start`, durations in [shortest, longest).
template <class T>
std::vector<T> random_times(quat::test::random_rotations& random, std::size_t count, double start,
                            double shortest, double longest) {
    std::vector<T> times{T(start)};
    while (times.size() < count)
        times.push_back(times.back() + random.uniform<T>(shortest, longest));
    return times;
}

// Segment i of squad with Shoemake's (time-blind) control points and the end keyframes as the end
// control points: what keyframe_squad must equal for evenly spaced times.
template <class T>
quaternion<T> unscaled_segment(const std::vector<quaternion<T>>& q, std::size_t i, T u) {
    const std::size_t last = q.size() - 1;
    const quaternion<T> a1 = i == 0 ? q[0] : quat::squad_control(q[i - 1], q[i], q[i + 1]);
    const quaternion<T> a2 =
        i + 1 == last ? q[last] : quat::squad_control(q[i], q[i + 1], q[i + 2]);
    return quat::squad(q[i], a1, a2, q[i + 1], u);
}

// The segment of sorted times holding t (t inside them).
template <class T>
std::size_t segment_holding(const std::vector<T>& times, T t) {
    std::size_t i = 0;
    while (i + 2 < times.size() && !(t < times[i + 1])) ++i;
    return i;
}

// Usable in constant expressions, control points included.
constexpr double fixed_times[] = {0.0, 0.5, 2.0, 2.25};
constexpr quaternion<double> fixed_keys[] = {
    {1, 0, 0, 0}, {0.6, 0.8, 0, 0}, {0.6, 0, 0.8, 0}, {0.8, 0, 0, 0.6}};
static_assert(quat::keyframe_squad(fixed_times, fixed_keys, 2.0) == fixed_keys[2]);
static_assert(quat::keyframe_squad(fixed_times, fixed_keys, 9.0) == fixed_keys[3]);
static_assert(quat::keyframe_squad(fixed_times, fixed_keys, 1.0).w > 0);

}  // namespace

TEMPLATE_TEST_CASE("with evenly spaced times keyframe_squad is squad with squad_control's controls",
                   "[keyframe_squad]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    // Steps of 0.5 and 0.75 s from 2 s: every duration is the same exactly, so the control points
    // are squad_control's, computed by the same operations, and the results are equal.
    for (const double step : {0.5, 0.75}) {
        for (int n = 0; n < 50; ++n) {
            const std::vector<quaternion<T>> q = quat::test::random_walk<T>(random, 6, 2.5);
            std::vector<T> times;
            for (std::size_t i = 0; i < q.size(); ++i) times.push_back(T(2 + step * double(i)));
            for (int k = 0; k < 40; ++k) {
                const T t = random.uniform<T>(2.0, double(times.back()));
                const std::size_t i = segment_holding(times, t);
                const T u = (t - times[i]) / (times[i + 1] - times[i]);
                CHECK(quat::keyframe_squad(times, q, t) == unscaled_segment(q, i, u));
            }
        }
    }
    // Steps of 0.1 s are not exact in binary: the durations differ by an ulp or so, the skew of the
    // control points is a few eps instead of 0, and the paths agree to a few eps.
    T worst = 0;
    for (int n = 0; n < 50; ++n) {
        const std::vector<quaternion<T>> q = quat::test::random_walk<T>(random, 6, 2.5);
        std::vector<T> times;
        for (std::size_t i = 0; i < q.size(); ++i) times.push_back(T(0.1) * T(i));
        for (int k = 0; k < 40; ++k) {
            const T t = random.uniform<T>(0.0, double(times.back()));
            const std::size_t i = segment_holding(times, t);
            const T u = (t - times[i]) / (times[i + 1] - times[i]);
            worst = std::max(worst, quat::angle_between(quat::keyframe_squad(times, q, t),
                                                        unscaled_segment(q, i, u)));
        }
    }
    CHECK(worst <= 16 * eps<T>);
}

TEMPLATE_TEST_CASE("keyframe_squad is each keyframe at its time, exactly", "[keyframe_squad]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 100; ++n) {
        const std::vector<quaternion<T>> q = quat::test::random_walk<T>(random, 7, 2.5);
        const std::vector<T> times = random_times<T>(random, q.size(), -3.0, 0.01, 5.0);
        for (std::size_t i = 0; i < q.size(); ++i)
            CHECK(quat::keyframe_squad(times, q, times[i]) == q[i]);
    }
}

TEST_CASE("keyframe_squad's angular velocity is continuous across keyframes at uneven times",
          "[keyframe_squad]") {
    // One-sided derivatives in long double at each keyframe: both sides of an inner keyframe must
    // give the documented tangent (log(q_(i-1)* q_i) + log(q_i* q_(i+1))) / (h_(i-1) + h_i), as an
    // angular velocity twice that, and the end keyframes their segment's slerp velocity. The same
    // keyframes with squad_control's time-blind controls jump by about the ratio of the
    // durations: the check would catch unscaled tangents.
    using L = long double;
    quat::test::random_rotations random;
    // The body angular velocity at keyframe i from one side: v(s) = log(q_i* path(t_i + s)) * 2
    // vanishes at s = 0, and (4 v(h) - v(2 h)) / (2 h) is its derivative there to O(h^2), from
    // the right for h > 0 and from the left for h < 0.
    const auto one_sided = [](const auto& path, const quaternion<L>& key, L h) {
        const vec3<L> once = quat::body_angular_velocity(key, path(h), L(1));
        const vec3<L> twice = quat::body_angular_velocity(key, path(h + h), L(1));
        return (once * L(4) - twice) / (h + h);
    };
    // Truncation (h / duration)^2 times the path's higher derivatives, about 1e-10 relative here,
    // and rounding, eps / (h / duration) (1e-12 for x86's long double, 2e-9 where it is double).
    const L tolerance = 1e-8L + 1e9L * eps<L>;
    L worst_scaled = 0, least_unscaled_jump = std::numeric_limits<L>::infinity();
    const auto check = [&](const std::vector<L>& times, const std::vector<quaternion<L>>& q) {
        const std::size_t last = q.size() - 1;
        for (std::size_t i = 0; i <= last; ++i) {
            const L before = i == 0 ? 0 : times[i] - times[i - 1];
            const L after = i == last ? 0 : times[i + 1] - times[i];
            const L h = 1e-7L * (i == 0 ? after : i == last ? before : std::min(before, after));
            const vec3<L> expected = i == 0 ? quat::body_angular_velocity(q[0], q[1], after)
                                     : i == last
                                         ? quat::body_angular_velocity(q[last - 1], q[last], before)
                                         : (quat::body_angular_velocity(q[i - 1], q[i], L(1)) +
                                            quat::body_angular_velocity(q[i], q[i + 1], L(1))) /
                                               (before + after);
            const L scale = quat::norm(expected);
            INFO("keyframe " << i << ", durations " << before << " and " << after);
            const auto squad_at = [&](L s) { return quat::keyframe_squad(times, q, times[i] + s); };
            vec3<L> left = expected, right = expected;
            if (i > 0) left = one_sided(squad_at, q[i], -h);
            if (i < last) right = one_sided(squad_at, q[i], h);
            CHECK(quat::norm(left - expected) <= tolerance * scale);
            CHECK(quat::norm(right - expected) <= tolerance * scale);
            if (i == 0 || i == last) continue;
            worst_scaled = std::max(worst_scaled, quat::norm(right - left) / scale);
            // squad_control's controls, each segment's parameter scaled by its own duration.
            const vec3<L> unscaled_left = one_sided(
                [&](L s) { return unscaled_segment(q, i - 1, 1 + s / before); }, q[i], -h);
            const vec3<L> unscaled_right =
                one_sided([&](L s) { return unscaled_segment(q, i, s / after); }, q[i], h);
            least_unscaled_jump =
                std::min(least_unscaled_jump, quat::norm(unscaled_right - unscaled_left) / scale);
        }
    };
    // The durations 0.1, 1 and 3 s of the issue, then random sets with durations unequal by up to
    // 1000x and steps up to 2.5 rad (the control points stay within a quarter turn of their
    // keyframe whatever the spacing, so no slerp inside wraps round).
    for (int n = 0; n < 20; ++n) {
        const std::vector<L> times{0.0L, 0.1L, 1.1L, 4.1L};
        std::vector<quaternion<L>> q;
        for (const auto& k : quat::test::random_walk<double>(random, times.size(), 1.5))
            q.push_back(quat::normalize(quaternion<L>(k)));  // unit in long double
        check(times, q);
    }
    CHECK(worst_scaled <= 2 * tolerance);
    CHECK(least_unscaled_jump >= 0.5L);
    for (int n = 0; n < 50; ++n) {
        const std::vector<L> times = random_times<L>(random, 6, 0.0, 0.01, 10.0);
        std::vector<quaternion<L>> q;
        for (const auto& k : quat::test::random_walk<double>(random, times.size(), 2.5))
            q.push_back(quat::normalize(quaternion<L>(k)));  // unit in long double
        check(times, q);
    }
    CHECK(worst_scaled <= 2 * tolerance);
}

TEMPLATE_TEST_CASE("keyframe_squad holds the end keyframes outside the times", "[keyframe_squad]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 50; ++n) {
        const std::vector<quaternion<T>> q = quat::test::random_walk<T>(random, 5, 1.5);
        const std::vector<T> times = random_times<T>(random, q.size(), 1.0, 0.1, 3.0);
        const T first = times.front(), last = times.back(),
                infinity = std::numeric_limits<T>::infinity();
        for (const T t : {first - T(1), -infinity, first})
            CHECK(quat::keyframe_squad(times, q, t) == q.front());
        for (const T t : {last + T(1), infinity, last})
            CHECK(quat::keyframe_squad(times, q, t) == q.back());
    }
}

TEMPLATE_TEST_CASE("keyframe_squad of two keyframes is keyframe_slerp; of one, that keyframe",
                   "[keyframe_squad]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 100; ++n) {
        const std::vector<quaternion<T>> q = quat::test::random_walk<T>(random, 2, 3.0);
        const std::vector<T> times = random_times<T>(random, 2, -1.0, 0.1, 3.0);
        const T t = random.uniform<T>(-2.0, 3.0);
        CHECK(quat::keyframe_squad(times, q, t) == quat::keyframe_slerp(times, q, t));
        const T one_time[] = {times[0]};
        const quaternion<T> one[] = {q[0]};
        CHECK(quat::keyframe_squad(one_time, one, t) == q[0]);
    }
}

TEMPLATE_TEST_CASE("keyframe_squad depends on the rotations, not on quaternion signs",
                   "[keyframe_squad]", float, double) {
    // Each control point takes its neighbours on its keyframe's hemisphere, as squad_control does,
    // and every slerp takes the shorter arc: negating keyframes changes the sign of the result at
    // most. Keyframes up to 2.5 rad apart, so some neighbours start on opposite hemispheres.
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 200; ++n) {
        std::vector<quaternion<T>> q = quat::test::random_walk<T>(random, 6, 2.5);
        const std::vector<T> times = random_times<T>(random, q.size(), 0.0, 0.05, 4.0);
        std::vector<T> ts;
        std::vector<quaternion<T>> path;
        for (int k = 0; k < 10; ++k) {
            ts.push_back(random.uniform<T>(0.0, double(times.back())));
            path.push_back(quat::keyframe_squad(times, q, ts.back()));
        }
        for (quaternion<T>& key : q)
            if (random.uniform<double>(0.0, 1.0) < 0.5) key = -key;
        for (std::size_t k = 0; k < ts.size(); ++k)
            CHECK(quat::angle_between(quat::keyframe_squad(times, q, ts[k]), path[k]) <=
                  64 * eps<T>);
    }
}

TEST_CASE("keyframe_squad of a NaN t or a NaN keyframe gives NaN", "[keyframe_squad][nan]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<double> one_time{2.0};
    const std::vector<quaternion<double>> one{quaternion<double>{0.6, 0.8, 0.0, 0.0}};
    CHECK(std::isnan(quat::keyframe_squad(one_time, one, nan).w));
    const std::vector<double> times{0.0, 1.0, 2.0, 3.0, 4.0, 5.0};
    std::vector<quaternion<double>> rotations(6, quaternion<double>::identity());
    CHECK(std::isnan(quat::keyframe_squad(times, rotations, nan).w));
    // Keyframe 3 is a control-point neighbour of segments 1 and 4 and an end of segments 2 and 3.
    rotations[3] = {nan, 0.0, 0.0, 0.0};
    for (const double t : {1.0, 1.5, 2.5, 3.5, 4.5})
        CHECK(std::isnan(quat::keyframe_squad(times, rotations, t).w));
    CHECK(quat::keyframe_squad(times, rotations, 0.5) == quaternion<double>::identity());
}

#ifdef NDEBUG
// Debug builds stop at these preconditions (tests/contracts); release builds must not read
// through a null pointer or past the shorter array, but return NaN, as keyframe_slerp does.
TEST_CASE("a release-build keyframe_squad of no keyframes or unequal sizes is NaN",
          "[keyframe_squad][nan]") {
    using Q = quaternion<double>;
    const std::vector<double> no_times, two_times{0.0, 1.0};
    const std::vector<Q> no_rotations, three(3, Q::identity());
    for (const double t : {-1.0, 0.5, 2.0}) {
        CHECK(std::isnan(quat::keyframe_squad(no_times, no_rotations, t).w));
        CHECK(std::isnan(quat::keyframe_squad(two_times, three, t).w));
        CHECK(std::isnan(quat::keyframe_squad(no_times, three, t).w));
    }
}

TEST_CASE("a release-build keyframe_squad converts a double time beyond float's range to infinity",
          "[keyframe_squad]") {
    // Not an undefined cast: the time is float's infinity, the keyframe before it is held up to
    // there, and the segment before it reads no infinite duration (debug builds stop at it).
    const double far_times[] = {0.0, 1.0, 1e300};
    const quaternion<float> three[] = {quaternion<float>::identity(), quat::rotation_x(1.0f),
                                       quat::rotation_y(1.0f)};
    CHECK(quat::keyframe_squad(far_times, three, 2.0) == three[1]);
    const quaternion<float> inside = quat::keyframe_squad(far_times, three, 0.5);
    CHECK(std::isfinite(inside.w));
    CHECK(quat::angle_between(inside, quat::slerp(three[0], three[1], 0.5f)) <= 0.5f);
}
#endif

TEST_CASE("keyframe_squad takes times and t of another precision than its rotations",
          "[keyframe_squad]") {
    // float rotations at double times, with a double t: both are converted to float, the
    // rotations' scalar, and the result is the all-float call's.
    quat::test::random_rotations random;
    const std::vector<quaternion<float>> rotations =
        quat::test::random_walk<float>(random, 10, 2.0);
    const std::vector<float> times = random_times<float>(random, rotations.size(), 0.0, 0.01, 3.0);
    const std::vector<double> double_times(times.begin(), times.end());
    for (int n = 0; n < 200; ++n) {
        const double t = random.uniform<double>(-1.0, double(times.back()) + 1.0);
        const quaternion<float> q = quat::keyframe_squad(double_times, rotations, t);
        static_assert(std::is_same_v<decltype(q), const quaternion<float>>);
        CHECK(q == quat::keyframe_squad(times, rotations, float(t)));
    }
}

}  // namespace test_keyframe_squad
