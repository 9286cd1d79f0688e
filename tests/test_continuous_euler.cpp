// Specification of continuous_euler.hpp: fed its previous output, to_euler(q, previous) returns a
// smooth trajectory of angles as the same smooth trajectory, through +-pi, through the mirror
// triple and through gimbal lock, in all 24 conventions.
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include <quat/constants.hpp>
#include <quat/continuous_euler.hpp>

#include "support/catch.hpp"
#include "support/conventions.hpp"
#include "support/random.hpp"

namespace test_continuous_euler {

using quat::euler;
using quat::frame;
using quat::quaternion;
using quat::sequence;
using quat::test::for_each_convention;

namespace {

template <sequence S>
constexpr bool is_proper = quat::detail::axes_of(S).first == quat::detail::axes_of(S).third;

// A smooth motion whose first and third angles wind past +-pi several times and whose middle
// angle swings across its canonical range (through the mirror triple, close to the locks).
template <class E>
E smooth_path(double t) {
    using T = std::remove_reference_t<decltype(E{}[0])>;
    return E{T(3 * std::sin(0.7 * t) + 1.3 * t), T(2.2 * std::sin(0.5 * t + 0.3)),
             T(-1.1 * t + 2 * std::cos(0.8 * t))};
}

// Sine of the middle angle's distance from its lock: a and c separately are only determined to
// about epsilon / this.
template <sequence S, class T>
T lock_distance(T middle) {
    return std::abs(is_proper<S> ? std::sin(middle) : std::cos(middle));
}

template <class T, sequence S, frame F>
T largest_step(const euler<T, S, F>& a, const euler<T, S, F>& b) {
    return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

}  // namespace

TEMPLATE_TEST_CASE("a smooth trajectory comes back as itself, not wrapped or mirrored",
                   "[euler][continuous]", float, double) {
    using T = TestType;
    const T eps = std::numeric_limits<T>::epsilon();
    for_each_convention<T>([&](auto convention) {
        using E = decltype(convention);
        constexpr sequence S = E::axis_sequence;
        constexpr frame F = E::rotation_frame;
        INFO("sequence " << static_cast<int>(S) << ", frame " << static_cast<int>(F));
        E previous = smooth_path<E>(0);
        E previous_plain = previous;
        T worst = 0, plain_jump = 0, worst_round_trip = 0;
        for (int n = 1; n <= 4000; ++n) {
            const E truth = smooth_path<E>(0.005 * n);
            const quaternion<T> q = quat::to_quaternion(truth);
            const E out = quat::to_euler(q, previous);
            const T scale =
                1 + std::max({std::abs(truth[0]), std::abs(truth[1]), std::abs(truth[2])});
            // Every output is q's rotation, whichever triple and turns it picked.
            worst_round_trip = std::max(
                worst_round_trip, quat::angle_between(quat::to_quaternion(out), q) / (eps * scale));
            // Away from the lock each angle is the truth to its conditioning: a few eps of the
            // angle's size, divided by the distance from the lock for the first and third.
            const T conditioning = std::max(lock_distance<S>(truth[1]), T(1e-3));
            worst = std::max(worst, largest_step(out, truth) / (eps * scale / conditioning));
            const E plain = quat::to_euler<S, F>(q);
            plain_jump = std::max(plain_jump, largest_step(plain, previous_plain));
            previous = out;
            previous_plain = plain;
        }
        // Measured, float and double: at most 1.2 of the scaled bound, round trips within 1.7 eps
        // of the angles' size; the plain extraction jumps by 2 pi on every convention.
        CHECK(worst <= 4);
        CHECK(worst_round_trip <= 4);
        CHECK(plain_jump > 6);
    });
}

TEMPLATE_TEST_CASE("through gimbal lock the free angle keeps its previous value",
                   "[euler][continuous]", float, double) {
    using T = TestType;
    const T eps = std::numeric_limits<T>::epsilon();
    const T pi = quat::numbers::pi_v<T>;
    for_each_convention<T>([&](auto convention) {
        using E = decltype(convention);
        constexpr sequence S = E::axis_sequence;
        constexpr frame F = E::rotation_frame;
        INFO("sequence " << static_cast<int>(S) << ", frame " << static_cast<int>(F));
        for (const T lock : {is_proper<S> ? T(0) : pi / 2, is_proper<S> ? pi : -pi / 2}) {
            // Sit exactly at the lock while the body keeps turning about the locked axis; q
            // fixes only the combination of the first and third angles there.
            E previous{T(0.4), lock, T(-0.7)};
            for (int n = 1; n <= 50; ++n) {
                const E truth{T(0.4) + T(0.05) * T(n), lock, T(-0.7) - T(0.03) * T(n)};
                const quaternion<T> q = quat::to_quaternion(truth);
                const E out = quat::to_euler(q, previous);
                CHECK(quat::angle_between(quat::to_quaternion(out), q) <= 8 * eps);
                CHECK(out[2] == previous[2]);                     // the free angle stays
                CHECK(std::abs(out[1] - lock) <= 8 * eps);        // no jump to a mirror
                CHECK(std::abs(out[0] - previous[0]) <= T(0.2));  // the rest moves smoothly
                previous = out;
            }
        }
    });
}

TEMPLATE_TEST_CASE("exactly at the lock the free angle is held whatever its size",
                   "[euler][continuous]", float, double) {
    // A hold that needs |middle-angle distance to the lock| * |change of the third angle| <= 2 eps
    // misses a middle angle extracted a few ulp off the lock with a third angle of 1.5 rad, and
    // the output jumps to the plain extraction's split (third angle 0).
    using T = TestType;
    const T eps = std::numeric_limits<T>::epsilon();
    const T pi = quat::numbers::pi_v<T>;
    quat::test::random_rotations random;
    for_each_convention<T>([&](auto convention) {
        using E = decltype(convention);
        constexpr sequence S = E::axis_sequence;
        INFO("sequence " << static_cast<int>(S) << ", frame "
                         << static_cast<int>(E::rotation_frame));
        int held = 0;
        T worst = 0;
        const int count = 2000;
        for (int n = 0; n < count; ++n) {
            const T lock =
                is_proper<S> ? (n % 2 == 0 ? T(0) : pi) : (n % 2 == 0 ? pi / 2 : -pi / 2);
            const E truth{random.uniform<T>(-3.1, 3.1), lock, random.uniform<T>(-3.1, 3.1)};
            const quaternion<T> q = quat::to_quaternion(truth);
            const E out = quat::to_euler(q, truth);
            held += out[2] == truth[2] ? 1 : 0;
            worst = std::max(worst, quat::angle_between(quat::to_quaternion(out), q) / eps);
        }
        CHECK(held == count);
        CHECK(worst <= 10);
    });
}

TEST_CASE("angles far from the canonical range stay where previous was", "[euler][continuous]") {
    const quaternion<double> q = quat::to_quaternion(euler<double>{0.3, 0.2, -0.1});
    const euler<double> previous{0.3 + 200 * quat::numbers::pi, 0.2 - 4 * quat::numbers::pi,
                                 -0.1 + 318 * quat::numbers::pi};
    const euler<double> out = quat::to_euler(q, previous);
    CHECK(largest_step(out, previous) <= 1e-12);
    // The mirror triple, unwrapped, when previous is nearer to it.
    const euler<double> mirrored{0.3 + quat::numbers::pi, quat::numbers::pi - 0.2,
                                 -0.1 + quat::numbers::pi};
    CHECK(largest_step(quat::to_euler(q, mirrored), mirrored) <= 1e-14);
}

TEST_CASE("continuous Euler angles of NaN input or previous are NaN", "[euler][continuous]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const euler<double> good{0.1, 0.2, 0.3};
    const euler<double> from_bad_q = quat::to_euler(quaternion<double>{nan, 0, 0, 1}, good);
    CHECK((std::isnan(from_bad_q[0]) || std::isnan(from_bad_q[1]) || std::isnan(from_bad_q[2])));
    const euler<double> from_bad_previous =
        quat::to_euler(quat::to_quaternion(good), euler<double>{nan, 0.2, 0.3});
    CHECK(std::isnan(from_bad_previous[0]));
    const euler<double> from_infinite_previous =
        quat::to_euler(quat::to_quaternion(good),
                       euler<double>{0.1, std::numeric_limits<double>::infinity(), 0.3});
    CHECK(std::isnan(from_infinite_previous[1]));
}

TEST_CASE("continuous Euler angles are constexpr", "[euler][continuous][constexpr]") {
    constexpr euler<double> previous{3.0, 0.1, -3.0};
    constexpr euler<double> out =
        quat::to_euler(quat::to_quaternion(euler<double>{-3.2, 0.1, 3.1}), previous);
    static_assert(out[0] > 3.0 && out[2] < -3.0, "unwrapped past pi at compile time");
    CHECK(out[0] == Approx(-3.2 + 2 * quat::numbers::pi));
}

}  // namespace test_continuous_euler
