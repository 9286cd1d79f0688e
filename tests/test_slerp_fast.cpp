// The fast-slerp family (nlerp from paths/interpolation.hpp, corrected_nlerp and slerp_fast from
// paths/slerp_fast.hpp) against the exact slerp: each method's largest rotation-angle error stays
// within its documented bound in float and double, and the approximations are exact at t = 0 and t
// = 1.
#include <algorithm>
#include <cmath>

#include <quat/paths/slerp_fast.hpp>
#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_slerp_fast {

namespace {

// The documented bounds in radians (include/quat/paths/slerp_fast.hpp); the benchmark labels
// (bench/bench_other.cpp) and `quat_accuracy --slerp-fast` (tools/accuracy/measure_slerp_fast.hpp)
// repeat them. The largest errors over 1.3 million samples there: nlerp 0.142 (its supremum, at a
// half turn); corrected_nlerp 5.83e-4 (the fitted polynomial's); slerp_fast 2.7e-7 in float, where
// rounding dominates (the exact slerp's own float error reaches 4.6e-7), and 3.33e-8 in double.
template <class T>
struct bound {
    static constexpr double nlerp = 0.143;
    static constexpr double corrected_nlerp = 5.9e-4;
    static constexpr double slerp_fast = sizeof(T) == sizeof(float) ? 4e-7 : 3.4e-8;
};

struct largest {
    double angle = 0;   // rotation angle to the exact slerp, rad
    double length = 0;  // | |r| - 1 |
};

quat::quatd widen(const quat::quatf& q) {
    return {double(q.w), double(q.x), double(q.y), double(q.z)};
}
quat::quatd widen(const quat::quatd& q) { return q; }

// The largest errors of method(a, b, t) over pairs of five kinds (random; b = a turned by 10^-1 to
// 10^-7 rad; nearly opposite, the rotations pi - 2e-3 apart; b = -a; b nearly -a) at t = 0, t = 1
// and 31 random t between. The reference is the exact slerp in double of the same inputs,
// normalized in double; the result's angle is taken after normalizing it (angle_between of a
// quaternion that is not unit counts the length error as angle too).
template <class T, class Method>
largest largest_errors(Method method) {
    quat::test::random_rotations random;
    largest worst;
    for (int pair = 0; pair < 3000; ++pair) {
        const quat::quaternion<T> a = random.unit_quaternion<T>();
        quat::quaternion<T> b = random.unit_quaternion<T>();
        const quat::vec3<double> axis = random.unit_vector<double>();
        const int kind = pair % 5;
        if (kind == 1 || kind == 4) {
            const double half = 0.5 * std::pow(10.0, -1 - pair % 7);
            const quat::quatd turn{std::cos(half), axis.x * std::sin(half), axis.y * std::sin(half),
                                   axis.z * std::sin(half)};
            const quat::quatd near = quat::normalize(widen(a) * turn);
            b = {T(near.w), T(near.x), T(near.y), T(near.z)};
            if (kind == 4) b = -b;
        }
        if (kind == 2) {
            // a (0, axis) is a half turn away from a; the 1e-3 keeps |a . b| far above rounding, so
            // float and double agree on which of b, -b is nearer.
            const quat::quatd opposite =
                quat::normalize(widen(a) * quat::quatd{1e-3, axis.x, axis.y, axis.z});
            b = {T(opposite.w), T(opposite.x), T(opposite.y), T(opposite.z)};
        }
        if (kind == 3) b = -a;
        const quat::quatd wide_a = quat::normalize(widen(a)), wide_b = quat::normalize(widen(b));
        for (int i = 0; i <= 32; ++i) {
            const T t = i == 0 ? T(0) : i == 32 ? T(1) : random.uniform<T>(0, 1);
            const quat::quatd exact = quat::slerp(wide_a, wide_b, double(t));
            const quat::quatd got = widen(method(a, b, t));
            worst.angle = std::max(worst.angle, quat::angle_between(quat::normalize(got), exact));
            worst.length = std::max(worst.length, std::abs(quat::norm(got) - 1));
        }
    }
    return worst;
}

}  // namespace

TEMPLATE_TEST_CASE("nlerp is within 0.143 rad of slerp", "[slerp_fast]", float, double) {
    using T = TestType;
    const largest worst =
        largest_errors<T>([](const auto& a, const auto& b, T t) { return quat::nlerp(a, b, t); });
    INFO("largest angle " << worst.angle << " rad, largest | |r| - 1 | " << worst.length);
    CHECK(worst.angle <= bound<T>::nlerp);
    CHECK(worst.angle >= 0.13);  // the bound is nearly reached: the correction below is needed
    CHECK(worst.length <= double(quat::test::tolerance<T>::unit_norm));
}

TEMPLATE_TEST_CASE("corrected_nlerp is within 5.9e-4 rad of slerp and unit", "[slerp_fast]", float,
                   double) {
    using T = TestType;
    const largest worst = largest_errors<T>(
        [](const auto& a, const auto& b, T t) { return quat::corrected_nlerp(a, b, t); });
    INFO("largest angle " << worst.angle << " rad, largest | |r| - 1 | " << worst.length);
    CHECK(worst.angle <= bound<T>::corrected_nlerp);
    CHECK(worst.length <= double(quat::test::tolerance<T>::unit_norm));
}

TEMPLATE_TEST_CASE(
    "slerp_fast is within 4e-7 rad of slerp in float, 3.4e-8 in double, and as "
    "close to unit",
    "[slerp_fast]", float, double) {
    using T = TestType;
    const largest worst = largest_errors<T>(
        [](const auto& a, const auto& b, T t) { return quat::slerp_fast(a, b, t); });
    INFO("largest angle " << worst.angle << " rad, largest | |r| - 1 | " << worst.length);
    CHECK(worst.angle <= bound<T>::slerp_fast);
    CHECK(worst.length <= bound<T>::slerp_fast);
}

TEMPLATE_TEST_CASE(
    "corrected_nlerp and slerp_fast are exact at t = 0 and t = 1 and take the "
    "shorter arc",
    "[slerp_fast]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int i = 0; i < 200; ++i) {
        const quat::quaternion<T> a = random.unit_quaternion<T>();
        const quat::quaternion<T> b = i % 10 == 0 ? -a : random.unit_quaternion<T>();
        const T t = random.uniform<T>(0, 1);
        // The sign bit of a . b picks -b (at a . b = +-0 both arcs are equally short).
        const quat::quaternion<T> near = std::signbit(quat::dot(a, b)) ? -b : b;
        CHECK(quat::corrected_nlerp(a, b, T(0)) == a);
        CHECK(quat::corrected_nlerp(a, b, T(1)) == near);
        CHECK(quat::slerp_fast(a, b, T(0)) == a);
        CHECK(quat::slerp_fast(a, b, T(1)) == near);
        // b and -b are the same rotation and give the same path, bit for bit, and it stays on a's
        // side: both weights are non-negative and a . near >= 0.
        CHECK(quat::corrected_nlerp(a, -b, t) == quat::corrected_nlerp(a, b, t));
        CHECK(quat::slerp_fast(a, -b, t) == quat::slerp_fast(a, b, t));
        CHECK(quat::dot(a, quat::corrected_nlerp(a, b, t)) >= T(0));
        CHECK(quat::dot(a, quat::slerp_fast(a, b, t)) >= T(0));
    }
}

// constexpr: the ends of a quarter turn, evaluated by the compiler.
static_assert(quat::slerp_fast(quat::quatd{1, 0, 0, 0}, quat::quatd{0.6, 0, 0.8, 0}, 0.0) ==
              quat::quatd{1, 0, 0, 0});
static_assert(quat::slerp_fast(quat::quatd{1, 0, 0, 0}, quat::quatd{-0.6, 0, -0.8, 0}, 1.0) ==
              quat::quatd{0.6, 0, 0.8, 0});
static_assert(quat::corrected_nlerp(quat::quatf{1, 0, 0, 0}, quat::quatf{0, 0.6f, 0, 0.8f}, 0.0f) ==
              quat::quatf{1, 0, 0, 0});
static_assert(quat::corrected_nlerp(quat::quatf{1, 0, 0, 0}, quat::quatf{0, 0.6f, 0, 0.8f}, 1.0f) ==
              quat::quatf{0, 0.6f, 0, 0.8f});

TEST_CASE(
    "slerp, nlerp, corrected_nlerp and slerp_fast take a plain double or int t with float "
    "rotations",
    "[interpolation][first-use]") {
    quat::test::random_rotations random;
    const quat::quatf a = random.unit_quaternion<float>();
    const quat::quatf b = random.unit_quaternion<float>();
    CHECK(quat::slerp(a, b, 0.5) == quat::slerp(a, b, 0.5f));
    CHECK(quat::nlerp(a, b, 0.25) == quat::nlerp(a, b, 0.25f));
    CHECK(quat::corrected_nlerp(a, b, 0.25) == quat::corrected_nlerp(a, b, 0.25f));
    CHECK(quat::slerp_fast(a, b, 0.75) == quat::slerp_fast(a, b, 0.75f));
    CHECK(quat::slerp(a, b, 1) == quat::slerp(a, b, 1.0f));
    CHECK(quat::slerp(a, b, 0.375) == quat::slerp(a, b, static_cast<float>(0.375)));
    const quat::rotation_matrix<float> m = quat::to_matrix(a);
    CHECK(quat::try_to_quaternion(m, 0.125) == quat::try_to_quaternion(m, 0.125f));
}

}  // namespace test_slerp_fast
