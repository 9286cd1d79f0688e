// Specification of rotation_spline.hpp: scipy 1.10's RotationSpline solved to convergence, checked
// against scipy's answers (committed reference data, tools/scipy_spline_reference.py), finite
// differences of the path, and the C2 conditions it is built from.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include <quat/interpolation.hpp>
#include <quat/kinematics.hpp>
#include <quat/rotation_spline.hpp>

#include "data/scipy_spline_reference.hpp"
#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

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
