// Specification of paths/rotation_spline.hpp: scipy 1.10's RotationSpline solved to convergence,
// checked against scipy's answers (committed reference data, tools/scipy_spline_reference.py),
// finite differences of the path, and the C2 conditions it is built from.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include <quat/kinematics.hpp>
#include <quat/paths/interpolation.hpp>
#include <quat/paths/rotation_spline.hpp>
#include <quat/quaternion.hpp>

#include "data/scipy_spline_reference.hpp"
#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_rotation_spline {

using quat::quaternion;
using quat::rotation_spline;
using quat::vec3;
using quat::test::eps;

namespace {

template <class T>
quaternion<T> quaternion_from(const double (&q)[4]) {
    return {T(q[0]), T(q[1]), T(q[2]), T(q[3])};
}

template <class T>
vec3<T> vector_from(const double (&v)[3]) {
    return {T(v[0]), T(v[1]), T(v[2])};
}

// The measure for rates: |difference| / (1 + |value|).
template <class T>
T rate_difference(const vec3<T>& a, const vec3<T>& reference) {
    return quat::norm(a - reference) / (1 + quat::norm(reference));
}

template <class T>
rotation_spline<T> spline_of(const quat::test::scipy::spline_case& c) {
    std::vector<T> times(c.times, c.times + c.count);
    std::vector<quaternion<T>> rotations;
    for (std::size_t i = 0; i < c.count; ++i)
        rotations.push_back(quaternion_from<T>(c.rotations[i]));
    return rotation_spline<T>(times, rotations);
}

struct differences {
    double angle = 0, velocity = 0, acceleration = 0;
};

// The largest differences between quat's spline and one of scipy's answers over the samples.
template <class T>
differences compare(const quat::test::scipy::spline_case& c, const double (*rotation)[4],
                    const double (*velocity)[3], const double (*acceleration)[3]) {
    const rotation_spline<T> spline = spline_of<T>(c);
    differences d;
    for (std::size_t k = 0; k < c.samples; ++k) {
        const T t = T(c.sample_times[k]);
        d.angle = std::max(d.angle,
                           double(quat::angle_between(spline(t), quaternion_from<T>(rotation[k]))));
        d.velocity = std::max(d.velocity, double(rate_difference(spline.angular_velocity(t),
                                                                 vector_from<T>(velocity[k]))));
        d.acceleration =
            std::max(d.acceleration, double(rate_difference(spline.angular_acceleration(t),
                                                            vector_from<T>(acceleration[k]))));
    }
    return d;
}

// Keyframes q_(i+1) = q_i exp(step_i) with |step_i| <= max_angle, random signs, and durations
// from `shortest` to `shortest * ratio`, log-uniform.
template <class T>
void random_keyframes(quat::test::random_rotations& random, std::size_t count, double max_angle,
                      double ratio, std::vector<T>& times, std::vector<quaternion<T>>& rotations) {
    times.assign(1, T(0));
    rotations.assign(1, random.unit_quaternion<T>());
    while (rotations.size() < count) {
        times.push_back(times.back() +
                        T(0.05 * std::exp(std::log(ratio) * random.uniform<double>(0, 1))));
        const vec3<T> axis = random.unit_vector<T>();  // one statement each: a fixed order
        const vec3<T> step = axis * random.uniform<T>(0.0, max_angle);
        const quaternion<T> next =
            quat::normalize(rotations.back() * quat::from_rotation_vector(step));
        rotations.push_back(random.uniform<double>(0, 1) < 0.5 ? -next : next);
    }
}

}  // namespace

TEST_CASE("rotation_spline agrees with scipy's RotationSpline where scipy's solver converges",
          "[rotation_spline][scipy]") {
    // The bound: 1e-9 for rotations (angle, rad) and rates (|difference| / (1 + |value|)).
    differences worst;
    int compared = 0;
    for (const auto& c : quat::test::scipy::spline_cases) {
        if (!c.scipy_converged) continue;
        INFO(c.name);
        const differences d =
            compare<double>(c, c.rotation, c.angular_velocity, c.angular_acceleration);
        CHECK(d.angle <= 1e-9);
        CHECK(d.velocity <= 1e-9);
        CHECK(d.acceleration <= 1e-9);
        worst = {std::max(worst.angle, d.angle), std::max(worst.velocity, d.velocity),
                 std::max(worst.acceleration, d.acceleration)};
        ++compared;
    }
    CHECK(compared >= 10);
}

TEST_CASE("rotation_spline is the converged spline where scipy stops after 10 iterations",
          "[rotation_spline][scipy]") {
    // scipy's own fixed-point iteration, run for up to 100000 steps to a tolerance of 1e-14, gives
    // the spline quat's Newton solve finds; scipy's default 10 steps leave it far away on these.
    int compared = 0;
    for (const auto& c : quat::test::scipy::spline_cases) {
        if (!c.reference_converged) continue;
        INFO(c.name);
        const differences converged =
            compare<double>(c, c.converged_rotation, c.converged_angular_velocity,
                            c.converged_angular_acceleration);
        CHECK(converged.angle <= 1e-11);
        CHECK(converged.velocity <= 1e-11);
        CHECK(converged.acceleration <= 1e-11);
        if (!c.scipy_converged) {
            const differences scipy =
                compare<double>(c, c.rotation, c.angular_velocity, c.angular_acceleration);
            CHECK(converged.angle < scipy.angle);
        }
        ++compared;
    }
    CHECK(compared >= 20);
}

TEST_CASE("rotation_spline in float is the double spline of the same keyframes to float precision",
          "[rotation_spline][scipy]") {
    // Not scipy's answers: rounding the times to float (6e-8 relative) moves the C2 spline itself
    // by up to 2e-4 rad within these sets, more than float arithmetic does. So the reference is the
    // double spline through the float-rounded keyframes, compared within the keyframes' span
    // (extrapolated far, where the rotation vector grows, float measured 1.3e-4 rad).
    differences worst;
    for (const auto& c : quat::test::scipy::spline_cases) {
        INFO(c.name);
        const rotation_spline<float> spline = spline_of<float>(c);
        const rotation_spline<double> reference(
            std::vector<double>(spline.times().begin(), spline.times().end()),
            std::vector<quaternion<double>>(spline.rotations().begin(), spline.rotations().end()));
        for (std::size_t k = 0; k < c.samples; ++k) {
            const float t = float(c.sample_times[k]);
            if (t < spline.times().front() || t > spline.times().back()) continue;
            worst.angle =
                std::max(worst.angle,
                         double(quat::angle_between(quaternion<double>(spline(t)), reference(t))));
            worst.velocity = std::max(
                worst.velocity, double(rate_difference(vec3<double>(spline.angular_velocity(t)),
                                                       reference.angular_velocity(t))));
            worst.acceleration =
                std::max(worst.acceleration,
                         double(rate_difference(vec3<double>(spline.angular_acceleration(t)),
                                                reference.angular_acceleration(t))));
        }
    }
    CHECK(worst.angle <= 5e-6);
    CHECK(worst.velocity <= 1e-5);
    CHECK(worst.acceleration <= 1e-5);
}

TEST_CASE("rotation_spline converges where scipy's fixed-point iteration wanders",
          "[rotation_spline][scipy]") {
    for (const auto& c : quat::test::scipy::spline_cases) {
        if (c.reference_converged) continue;
        INFO(c.name);
        std::vector<double> times(c.times, c.times + c.count);
        std::vector<quaternion<double>> rotations;
        for (std::size_t i = 0; i < c.count; ++i)
            rotations.push_back(quaternion_from<double>(c.rotations[i]));
        const std::optional<rotation_spline<double>> spline =
            rotation_spline<double>::try_make(times, rotations);
        REQUIRE(spline);
        for (std::size_t i = 1; i + 1 < c.count; ++i) {
            const double before = std::nextafter(times[i], -1e300);
            CHECK(rate_difference(spline->angular_acceleration(before),
                                  spline->angular_acceleration(times[i])) <= 1e-8);
        }
    }
}

TEMPLATE_TEST_CASE("rotation_spline passes through its keyframes", "[rotation_spline]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    std::vector<T> times;
    std::vector<quaternion<T>> rotations;
    for (int n = 0; n < 50; ++n) {
        random_keyframes(random, 2 + std::size_t(n % 30), 3.0, 10.0, times, rotations);
        const rotation_spline<T> spline(times, rotations);
        for (std::size_t i = 0; i < times.size(); ++i)
            CHECK(quat::angle_between(spline(times[i]), rotations[i]) <= 4 * eps<T>);
    }
}

TEMPLATE_TEST_CASE("rotation_spline's angular velocity and acceleration are continuous (C2)",
                   "[rotation_spline]", float, double) {
    using T = TestType;
    // Both are evaluated just before each inner keyframe (the end of the segment before it) and at
    // it (the start of the next); sets with steps up to 3 rad and durations unequal by up to 10x.
    const T bound = std::is_same_v<T, float> ? T(2e-4) : T(1e-11);
    quat::test::random_rotations random;
    std::vector<T> times;
    std::vector<quaternion<T>> rotations;
    for (int n = 0; n < 200; ++n) {
        random_keyframes(random, 3 + std::size_t(n % 40), 3.0, 10.0, times, rotations);
        const std::optional<rotation_spline<T>> spline =
            rotation_spline<T>::try_make(times, rotations);
        REQUIRE(spline);
        for (std::size_t i = 1; i + 1 < times.size(); ++i) {
            const T before = std::nextafter(times[i], T(-1e30));
            CHECK(rate_difference(spline->angular_velocity(before),
                                  spline->angular_velocity(times[i])) <= bound);
            CHECK(rate_difference(spline->angular_acceleration(before),
                                  spline->angular_acceleration(times[i])) <= bound);
        }
    }
}

TEST_CASE("rotation_spline's rates are the derivatives of its rotations", "[rotation_spline]") {
    // Central differences of the path: omega ~ body velocity from R(t - h) to R(t + h) over 2h, and
    // alpha ~ (omega(t + h) - omega(t - h)) / 2h, both O(h^2); here h = 1e-5 s (measured: 1.4e-7
    // and 1.6e-6 at most).
    quat::test::random_rotations random;
    std::vector<double> times;
    std::vector<quaternion<double>> rotations;
    const double h = 1e-5;
    for (int n = 0; n < 20; ++n) {
        random_keyframes(random, 10, 2.0, 5.0, times, rotations);
        const rotation_spline<double> spline(times, rotations);
        for (int k = 0; k < 50; ++k) {
            const double t = random.uniform<double>(times.front(), times.back());
            const vec3<double> velocity =
                quat::body_angular_velocity(spline(t - h), spline(t + h), 2 * h);
            CHECK(rate_difference(spline.angular_velocity(t), velocity) <= 1e-6);
            const vec3<double> acceleration =
                (spline.angular_velocity(t + h) - spline.angular_velocity(t - h)) / (2 * h);
            CHECK(rate_difference(spline.angular_acceleration(t), acceleration) <= 1e-5);
        }
    }
}

TEMPLATE_TEST_CASE("a rotation_spline through two keyframes is their slerp", "[rotation_spline]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int n = 0; n < 200; ++n) {
        const quaternion<T> a = random.unit_quaternion<T>(), b = random.unit_quaternion<T>();
        const T start = random.uniform<T>(-5.0, 5.0), duration = random.uniform<T>(0.1, 4.0);
        const T times[] = {start, start + duration};
        const quaternion<T> rotations[] = {a, b};
        const rotation_spline<T> spline(times, rotations);
        const T u = random.uniform<T>(0.0, 1.0);
        CHECK(quat::angle_between(spline(start + u * duration), quat::slerp(a, b, u)) <=
              64 * eps<T>);
        const vec3<T> velocity = quat::body_angular_velocity(a, b, duration);
        CHECK(rate_difference(spline.angular_velocity(start + u * duration), velocity) <=
              64 * eps<T>);
        CHECK(quat::norm(spline.angular_acceleration(start + u * duration)) <= 64 * eps<T>);
    }
}

TEST_CASE("rotation_spline's solve converges on every realistic keyframe set",
          "[rotation_spline]") {
    // 1000 random sets: 3 to 60 keyframes, steps up to a half turn, durations unequal by up to
    // 10x. (With durations unequal by 100x about 1 set in 100 fails, by 1000x about 6 in 100: the
    // Newton iteration stalls where the jumps' Jacobian is singular; try_make reports those.)
    quat::test::random_rotations random;
    std::vector<double> times;
    std::vector<quaternion<double>> rotations;
    int failed = 0;
    for (int n = 0; n < 1000; ++n) {
        random_keyframes(random, 3 + std::size_t(n % 58), 3.14159, 10.0, times, rotations);
        failed += rotation_spline<double>::try_make(times, rotations) ? 0 : 1;
    }
    CHECK(failed == 0);
}

TEST_CASE("rotation_spline::evaluate gives the same rotations in any order of times",
          "[rotation_spline]") {
    quat::test::random_rotations random;
    std::vector<double> times;
    std::vector<quaternion<double>> rotations;
    random_keyframes(random, 40, 1.5, 10.0, times, rotations);
    const rotation_spline<double> spline(times, rotations);
    std::vector<double> ts;
    for (int k = -20; k < 420; ++k)
        ts.push_back(times.front() + (times.back() - times.front()) * k / 400.0);
    ts.push_back(times[7]);
    ts.push_back(times.back());
    std::vector<quaternion<double>> out(ts.size());
    spline.evaluate(ts, out);
    for (std::size_t k = 0; k < ts.size(); ++k) CHECK(out[k] == spline(ts[k]));
    std::reverse(ts.begin(), ts.end());
    spline.evaluate(ts, out);
    for (std::size_t k = 0; k < ts.size(); ++k) CHECK(out[k] == spline(ts[k]));
}

TEST_CASE("rotation_spline::try_make rejects bad keyframes", "[rotation_spline][nan]") {
    using Q = quaternion<double>;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double infinity = std::numeric_limits<double>::infinity();
    const Q q = Q::identity(), r{0.6, 0.8, 0.0, 0.0};
    const auto make = [](const std::vector<double>& times, const std::vector<Q>& rotations) {
        return rotation_spline<double>::try_make(times, rotations).has_value();
    };
    CHECK(make({0.0, 1.0, 2.0}, {q, r, q}));
    CHECK(make({0.0, 1.0}, {q, Q{2.0, 0.0, 0.0, 0.0}}));  // any non-zero scale
    CHECK_FALSE(make({}, {}));
    CHECK_FALSE(make({0.0}, {q}));
    CHECK_FALSE(make({0.0, 1.0, 2.0}, {q, r}));
    CHECK_FALSE(make({0.0, 1.0, 1.0}, {q, r, q}));
    CHECK_FALSE(make({0.0, 2.0, 1.0}, {q, r, q}));
    CHECK_FALSE(make({0.0, nan, 2.0}, {q, r, q}));
    CHECK_FALSE(make({0.0, 1.0, infinity}, {q, r, q}));
    CHECK_FALSE(make({0.0, 1.0, 2.0}, {q, Q{nan, 0.0, 0.0, 0.0}, q}));
    CHECK_FALSE(make({0.0, 1.0, 2.0}, {q, Q{infinity, 0.0, 0.0, 0.0}, q}));
    CHECK_FALSE(make({0.0, 1.0, 2.0}, {q, Q{0.0, 0.0, 0.0, 0.0}, q}));
}

TEST_CASE(
    "rotation_spline at a NaN time is NaN; outside the keyframes it continues the end "
    "cubics",
    "[rotation_spline][nan]") {
    const double times[] = {0.0, 1.0, 3.0};
    const quaternion<double> rotations[] = {
        quaternion<double>::identity(), quat::from_rotation_vector(vec3<double>{0.0, 0.0, 1.0}),
        quat::from_rotation_vector(vec3<double>{0.0, 1.0, 1.0})};
    const rotation_spline<double> spline(times, rotations);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK(std::isnan(spline(nan).w));
    CHECK(std::isnan(spline.angular_velocity(nan).x));
    CHECK(std::isnan(spline.angular_acceleration(nan).x));
    // Past the ends the velocity keeps changing smoothly: the end cubic's values, not a hold.
    const vec3<double> end = spline.angular_velocity(3.0), beyond = spline.angular_velocity(3.01);
    CHECK(quat::norm(beyond - end) > 0);
    CHECK(quat::norm(beyond - end) < 0.1);
}

namespace {

// True when every component of q (or v) is NaN.
template <class T>
bool all_nan(const quaternion<T>& q) {
    return std::isnan(q.w) && std::isnan(q.x) && std::isnan(q.y) && std::isnan(q.z);
}
template <class T>
bool all_nan(const vec3<T>& v) {
    return std::isnan(v.x) && std::isnan(v.y) && std::isnan(v.z);
}

// Every member of a spline without keyframes gives NaN, at any time.
template <class T>
void check_evaluates_to_nan(const rotation_spline<T>& spline) {
    for (const T t : {T(-1), T(0), T(0.5), T(1), T(2)}) {
        INFO("t = " << t);
        CHECK(all_nan(spline(t)));
        CHECK(all_nan(spline.angular_velocity(t)));
        CHECK(all_nan(spline.angular_acceleration(t)));
    }
    const std::vector<T> ts{T(0), T(0.5), T(1)};
    std::vector<quaternion<T>> out(ts.size(), quaternion<T>::identity());
    spline.evaluate(ts, out);
    for (const quaternion<T>& q : out) CHECK(all_nan(q));
}

template <class T>
bool is_finite(const vec3<T>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
template <class T>
bool is_finite(const quaternion<T>& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

}  // namespace

TEST_CASE("a rotation_spline moved from evaluates to NaN", "[rotation_spline][nan]") {
    const std::vector<double> times{0.0, 1.0, 2.0};
    const std::vector<quaternion<double>> rotations{quaternion<double>::identity(),
                                                    quat::rotation_x(1.0), quat::rotation_y(1.0)};
    rotation_spline<double> spline(times, rotations);
    const rotation_spline<double> moved_to(std::move(spline));
    CHECK(moved_to(1.0) == rotations[1]);
    check_evaluates_to_nan(spline);  // NOLINT(bugprone-use-after-move): the state under test
    rotation_spline<double> assigned(times, rotations);
    rotation_spline<double> target(times, rotations);
    target = std::move(assigned);
    check_evaluates_to_nan(assigned);  // NOLINT(bugprone-use-after-move)
}

#ifdef NDEBUG
// Debug builds stop at these preconditions (tests/contracts); release builds must not read
// through a null pointer or wrap an index, but give the documented NaN.
TEST_CASE("a release-build rotation_spline from fewer than two keyframes or unequal sizes is NaN",
          "[rotation_spline][nan]") {
    using Q = quaternion<double>;
    check_evaluates_to_nan(rotation_spline<double>(std::vector<double>{}, std::vector<Q>{}));
    check_evaluates_to_nan(
        rotation_spline<double>(std::vector<double>{0.0}, std::vector<Q>{Q::identity()}));
    check_evaluates_to_nan(rotation_spline<double>(std::vector<double>{0.0, 1.0, 2.0},
                                                   std::vector<Q>{Q::identity(), Q::identity()}));
    check_evaluates_to_nan(
        rotation_spline<double>(std::vector<double>{0.0, 1.0},
                                std::vector<Q>{Q::identity(), Q::identity(), Q::identity()}));
}
#endif

TEST_CASE("the segment search never wraps below two keyframes", "[rotation_spline][nan]") {
    // count - 2 would wrap to a huge last segment and read past the times.
    CHECK(quat::detail::segment_of(static_cast<const double*>(nullptr), 0, 1.0) == 0);
    const double one[] = {3.0};
    CHECK(quat::detail::segment_of(one, 1, 5.0) == 0);
    CHECK(quat::detail::segment_of(one, 1, 5.0, 7) == 0);
}

TEMPLATE_TEST_CASE("rotation_spline of uniformly scaled times is the same curve",
                   "[rotation_spline]", float, double) {
    using T = TestType;
    // The equations hold in any unit of time: keyframes every 1e100 s are the keyframes every
    // 1 s, their rates scaled by 1e-100 and 1e-200. float scales are powers of two, so that the
    // scaled times are the same floats; double scales are decimal, so the times round (1e-16
    // relative), which moves the C2 spline by up to 2e-14 rad (measured). Much below 1e-120 the
    // accelerations (angle / duration^2) near double's largest value, and try_make refuses.
    const std::vector<T> scales =
        std::is_same_v<T, float>
            ? std::vector<T>{std::ldexp(T(1), -43), std::ldexp(T(1), -20), std::ldexp(T(1), 20),
                             std::ldexp(T(1), 66), std::ldexp(T(1), 100)}
            : std::vector<T>{T(1e-120), T(1e-100), T(1e-20), T(1e20), T(1e100), T(1e150), T(1e300)};
    const T angle_bound = std::is_same_v<T, float> ? T(1e-5) : T(1e-12);
    const T rate_bound = std::is_same_v<T, float> ? T(1e-4) : T(1e-9);
    quat::test::random_rotations random;
    std::vector<T> times, scaled;
    std::vector<quaternion<T>> rotations;
    for (int n = 0; n < 20; ++n) {
        random_keyframes(random, 3 + std::size_t(n % 12), 3.0, 10.0, times, rotations);
        const std::optional<rotation_spline<T>> spline =
            rotation_spline<T>::try_make(times, rotations);
        REQUIRE(spline);
        for (const T scale : scales) {
            INFO("set " << n << ", scale " << scale);
            scaled.clear();
            for (const T t : times) scaled.push_back(t * scale);
            const std::optional<rotation_spline<T>> stretched =
                rotation_spline<T>::try_make(scaled, rotations);
            REQUIRE(stretched);
            T angle = 0, velocity = 0, acceleration = 0;
            for (int k = 0; k <= 100; ++k) {
                const T t = times.front() + (times.back() - times.front()) * T(k) / T(100);
                angle = std::max(angle, quat::angle_between((*stretched)(t * scale), (*spline)(t)));
                velocity = std::max(velocity,
                                    rate_difference(stretched->angular_velocity(t * scale) * scale,
                                                    spline->angular_velocity(t)));
                // The accelerations scale by scale^2: compared while that stays well in range.
                if (std::isnormal(scale * scale * T(1e4)) && std::isnormal(scale * scale / T(1e4)))
                    acceleration = std::max(
                        acceleration,
                        rate_difference(stretched->angular_acceleration(t * scale) * scale * scale,
                                        spline->angular_acceleration(t)));
            }
            CHECK(angle <= angle_bound);
            CHECK(velocity <= rate_bound);
            CHECK(acceleration <= rate_bound);
        }
    }
}

TEMPLATE_TEST_CASE("rotation_spline::try_make is empty wherever a value would not be finite",
                   "[rotation_spline][nan]", float, double) {
    using T = TestType;
    // At durations near the smallest normal numbers the rates (angle / duration) and
    // accelerations (angle / duration^2) overflow; across the whole range a duration overflows.
    // try_make returns a spline whose rotations, rates and accelerations between its keyframes are
    // finite, or nothing.
    quat::test::random_rotations random;
    std::vector<T> times, scaled;
    std::vector<quaternion<T>> rotations;
    const int lowest = std::numeric_limits<T>::min_exponent - std::numeric_limits<T>::digits;
    int engaged = 0, empty = 0;
    for (int n = 0; n < 10; ++n) {
        random_keyframes(random, 3 + std::size_t(n % 8), 3.0, 10.0, times, rotations);
        for (int exponent = lowest; exponent <= std::numeric_limits<T>::max_exponent;
             exponent += 4) {
            INFO("set " << n << ", times scaled by 2^" << exponent);
            scaled.clear();
            for (const T t : times) scaled.push_back(std::ldexp(t, exponent));
            const std::optional<rotation_spline<T>> spline =
                rotation_spline<T>::try_make(scaled, rotations);
            if (!spline) {
                ++empty;
                continue;
            }
            ++engaged;
            bool finite = true;
            for (int k = 0; k <= 50; ++k) {
                const T t = scaled.front() + (scaled.back() - scaled.front()) * (T(k) / T(50));
                finite = finite && is_finite((*spline)(t)) &&
                         is_finite(spline->angular_velocity(t)) &&
                         is_finite(spline->angular_acceleration(t));
            }
            CHECK(finite);
        }
    }
    CHECK(engaged > 0);
    CHECK(empty > 0);
    // Times whose difference overflows, or that leave float's range once converted.
    const std::vector<quaternion<T>> three{quaternion<T>::identity(), quat::rotation_x(T(1)),
                                           quat::rotation_y(T(1))};
    const T largest = std::numeric_limits<T>::max();
    CHECK_FALSE(
        rotation_spline<T>::try_make(std::vector<T>{-largest, largest / T(2), largest}, three));
    if constexpr (std::is_same_v<T, float>)
        CHECK_FALSE(rotation_spline<float>::try_make(std::vector<double>{0.0, 1.0, 1e300}, three));
}

TEST_CASE("rotation_spline::try_make stops solving after a bounded amount of work",
          "[rotation_spline]") {
    // 2000 keyframes, steps up to a half turn, durations unequal by up to 1000 times: the Newton
    // iteration stalls somewhere along so long a set. try_make reports that (measured by hand: at
    // most 400 passes over the keyframes; 10,000 such keyframes took 0.3 to 0.8 s where they took
    // 1.0 to 8.7 s with 100 steps of up to 40 halvings each).
    quat::test::random_rotations random;
    std::vector<double> times;
    std::vector<quaternion<double>> rotations;
    random_keyframes(random, 2000, 3.14159, 1000.0, times, rotations);
    const std::optional<rotation_spline<double>> spline =
        rotation_spline<double>::try_make(times, rotations);
    CHECK_FALSE(spline);
    // The constructor keeps the velocities with the smallest jumps: still through every keyframe.
    const rotation_spline<double> kept(times, rotations);
    for (std::size_t i = 0; i < times.size(); i += 97)
        CHECK(quat::angle_between(kept(times[i]), rotations[i]) <= 4 * eps<double>);
}

TEMPLATE_TEST_CASE("rotation_spline takes keyframes of any non-zero magnitude", "[rotation_spline]",
                   float, double) {
    using T = TestType;
    // normalize scales subnormal and huge quaternions first; only zero is not a rotation. Powers
    // of two scale the keyframes exactly (|q|^2 underflows to zero at the smallest normal
    // magnitude, and overflows at a quarter of the largest); subnormal components keep only some
    // of their bits, so those keyframes are the rotations their rounded components describe.
    quat::test::random_rotations random;
    std::vector<T> times;
    std::vector<quaternion<T>> rotations;
    random_keyframes(random, 6, 2.0, 5.0, times, rotations);
    const rotation_spline<T> unit(times, rotations);
    for (const T magnitude : {std::numeric_limits<T>::min(), std::numeric_limits<T>::max() / T(4),
                              std::numeric_limits<T>::denorm_min() * T(1024)}) {
        INFO("magnitude " << magnitude);
        std::vector<quaternion<T>> scaled, normalized;
        for (const quaternion<T>& q : rotations) {
            scaled.push_back(q * magnitude);
            normalized.push_back(quat::normalize(scaled.back()));
        }
        const std::optional<rotation_spline<T>> spline =
            rotation_spline<T>::try_make(times, scaled);
        REQUIRE(spline);
        const rotation_spline<T> reference(times, normalized);
        const bool exact = magnitude >= std::numeric_limits<T>::min();
        for (int k = 0; k <= 20; ++k) {
            const T t = times.front() + (times.back() - times.front()) * T(k) / T(20);
            CHECK(quat::angle_between((*spline)(t), reference(t)) <= 64 * eps<T>);
            if (exact) CHECK(quat::angle_between((*spline)(t), unit(t)) <= 64 * eps<T>);
        }
    }
}

TEST_CASE("rotation_spline takes times of another precision than its rotations",
          "[rotation_spline]") {
    // float rotations at double times: the times are converted to float, as the spline's scalar.
    quat::test::random_rotations random;
    std::vector<float> times;
    std::vector<quaternion<float>> rotations;
    random_keyframes(random, 8, 2.0, 5.0, times, rotations);
    const std::vector<double> double_times(times.begin(), times.end());
    const rotation_spline<float> reference(times, rotations);
    const rotation_spline spline(double_times, rotations);  // deduced from the rotations: float
    static_assert(std::is_same_v<decltype(spline), const rotation_spline<float>>);
    const std::optional<rotation_spline<float>> checked =
        rotation_spline<float>::try_make(double_times, rotations);
    REQUIRE(checked);
    std::vector<double> ts;
    for (int k = 0; k <= 40; ++k)
        ts.push_back(double_times.front() +
                     (double_times.back() - double_times.front()) * k / 40.0);
    std::vector<quaternion<float>> out(ts.size());
    spline.evaluate(ts, out);
    for (std::size_t k = 0; k < ts.size(); ++k) {
        const float t = float(ts[k]);
        CHECK(out[k] == reference(t));
        CHECK((*checked)(t) == reference(t));
        CHECK(spline.angular_velocity(t) == reference.angular_velocity(t));
    }
}

namespace {

// The C2 cubic spline of scalar values at times, with the end slopes of the first and last
// segments' straight lines (rotation_spline's end conditions), in long double: its slope at t.
// About one fixed axis the rotation spline is exactly this spline of the angles (the rotation
// vectors are parallel, so J(r) is the identity on them and the non-linear term vanishes).
long double clamped_spline_slope(const std::vector<long double>& times,
                                 const std::vector<long double>& values, long double t) {
    const std::size_t n = times.size();
    std::vector<long double> h(n - 1), slope(n), diagonal(n), rhs(n);
    for (std::size_t k = 0; k + 1 < n; ++k) h[k] = times[k + 1] - times[k];
    slope[0] = (values[1] - values[0]) / h[0];
    slope[n - 1] = (values[n - 1] - values[n - 2]) / h[n - 2];
    // Continuity of the second derivative at keyframe k, by the Thomas algorithm.
    for (std::size_t k = 1; k + 1 < n; ++k) {
        diagonal[k] = 4 / h[k - 1] + 4 / h[k];
        rhs[k] = 6 * (values[k] - values[k - 1]) / (h[k - 1] * h[k - 1]) +
                 6 * (values[k + 1] - values[k]) / (h[k] * h[k]);
        if (k == 1) rhs[k] -= 2 / h[0] * slope[0];
        if (k == n - 2) rhs[k] -= 2 / h[n - 2] * slope[n - 1];
        if (k > 1) {
            const long double factor = (2 / h[k - 1]) / diagonal[k - 1];
            diagonal[k] -= factor * (2 / h[k - 1]);
            rhs[k] -= factor * rhs[k - 1];
        }
    }
    for (std::size_t k = n - 2; k >= 1; --k)
        slope[k] = (rhs[k] - (k + 2 < n ? 2 / h[k] * slope[k + 1] : 0.0L)) / diagonal[k];
    std::size_t k = 0;
    while (k + 2 < n && t >= times[k + 1]) ++k;
    // The derivative of the cubic Hermite segment.
    const long double u = (t - times[k]) / h[k], rise = values[k + 1] - values[k];
    return slope[k] * (1 - 4 * u + 3 * u * u) + slope[k + 1] * (3 * u * u - 2 * u) +
           rise / h[k] * (6 * u - 6 * u * u);
}

}  // namespace

TEST_CASE("rotation_spline with durations unequal by 1e6 is the C2 spline, huge rates included",
          "[rotation_spline][edge]") {
    // Keyframes 1e-6 s apart at both ends and 1 s apart between: the end velocities are those of
    // the 1e-6 s slerps (3e5 rad/s here), and continuity of the acceleration carries rates of
    // that size into the 1 s segments. That is the C2 spline, not an artefact: about one axis
    // it is the scalar clamped spline above, computed independently in long double.
    const std::vector<double> times{0, 1e-6, 1 + 1e-6, 2 + 1e-6, 2 + 2e-6};
    const std::vector<long double> angles{0, 0.3L, 0.9L, 1.2L, 1.6L};
    std::vector<quaternion<double>> rotations;
    for (const long double a : angles) rotations.push_back(quat::rotation_z(double(a)));
    const std::optional<rotation_spline<double>> spline =
        rotation_spline<double>::try_make(times, rotations);
    REQUIRE(spline);
    const std::vector<long double> long_times(times.begin(), times.end());
    double largest = 0;
    for (int k = 0; k <= 200; ++k) {
        const double t = times.front() + (times.back() - times.front()) * k / 200.0;
        const vec3<double> w = spline->angular_velocity(t);
        const long double reference = clamped_spline_slope(long_times, angles, t);
        CAPTURE(t, w.z, double(reference));
        CHECK(std::abs(w.z - reference) <= 1e-9 * (1 + std::abs(reference)));
        CHECK(std::abs(w.x) + std::abs(w.y) <= 1e-9 * (1 + std::abs(reference)));
        largest = std::max(largest, std::abs(w.z));
    }
    CHECK(largest > 1e5);
    // Scaled by 1e-20 the accelerations (1e6 rad/s^2 here, times 1e40) pass float's largest value:
    // try_make refuses the float copy, as documented, while double takes it.
    std::vector<float> float_times;
    std::vector<double> scaled_times;
    std::vector<quaternion<float>> float_rotations;
    for (std::size_t i = 0; i < times.size(); ++i) {
        float_times.push_back(float(times[i] * 1e-20));
        scaled_times.push_back(times[i] * 1e-20);
        float_rotations.emplace_back(rotations[i]);
    }
    CHECK_FALSE(rotation_spline<float>::try_make(float_times, float_rotations));
    const std::optional<rotation_spline<double>> scaled =
        rotation_spline<double>::try_make(scaled_times, rotations);
    REQUIRE(scaled);
    const double middle = 1.5;
    CHECK(std::abs(scaled->angular_acceleration(middle * 1e-20).z) >
          double(std::numeric_limits<float>::max()));
    CHECK(std::abs(scaled->angular_velocity(middle * 1e-20).z * 1e-20 -
                   spline->angular_velocity(middle).z) <=
          1e-9 * std::abs(spline->angular_velocity(middle).z));
}

#ifdef NDEBUG
TEST_CASE("rotation_spline with times and rotations of different sizes reads neither past its end",
          "[rotation_spline][nan]") {
    // Release builds only (debug builds stop at QUAT_ASSERT); run under AddressSanitizer, a read
    // past either vector is reported. The spline evaluates to NaN; try_make is empty.
    const std::vector<double> five{0, 1, 2, 3, 4}, two{0, 1};
    const std::vector<quaternion<double>> three{quaternion<double>::identity(),
                                                quat::rotation_x(0.5), quat::rotation_y(0.5)};
    const std::vector<quaternion<double>> six(6, quaternion<double>::identity());
    const auto check_nan = [](const rotation_spline<double>& s) {
        CHECK(std::isnan(s(0.5).w));
        CHECK(std::isnan(s.angular_velocity(0.5).x));
        CHECK(std::isnan(s.angular_acceleration(0.5).x));
        CHECK(s.times().empty());
    };
    check_nan(rotation_spline<double>(five, three));
    check_nan(rotation_spline<double>(two, three));
    check_nan(rotation_spline<double>(five, six));
    CHECK_FALSE(rotation_spline<double>::try_make(five, three));
    CHECK_FALSE(rotation_spline<double>::try_make(two, three));
    CHECK_FALSE(rotation_spline<double>::try_make(five, six));
    const double c_times[] = {0, 1, 2};
    const quaternion<double> c_rotations[] = {quaternion<double>::identity(),
                                              quat::rotation_z(1.0)};
    check_nan(rotation_spline<double>(c_times, c_rotations));
    CHECK_FALSE(rotation_spline<double>::try_make(c_times, c_rotations));
}
#endif

}  // namespace test_rotation_spline
