// Specification of paths/keyframe_slerp.hpp: piecewise slerp through keyframes at given times,
// against scipy 1.10's Slerp (committed reference data, tools/scipy_spline_reference.py).
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

#include <quat/paths/keyframe_slerp.hpp>

#include "data/scipy_spline_reference.hpp"
#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_keyframe_slerp {

using quat::quaternion;
using quat::test::eps;

namespace {

template <class T>
quaternion<T> from_row(const double (&q)[4]) {
    return {T(q[0]), T(q[1]), T(q[2]), T(q[3])};
}

}  // namespace

TEMPLATE_TEST_CASE("keyframe_slerp gives scipy's Slerp(times, rotations)(t)", "[keyframe_slerp]",
                   float, double) {
    using T = TestType;
    // Measured: 9.7e-16 rad in double; 4.7e-6 rad in float, where rounding the times (tens of
    // seconds) and keyframes to float moves the path itself.
    const T tolerance = std::is_same_v<T, float> ? T(1e-5) : T(1e-14);
    T worst = 0;
    for (const auto& c : quat::test::scipy::slerp_cases) {
        INFO(c.name);
        // Times near 1000 round to 6e-5 in float: that moves the keyframes, not quat's result.
        if (std::is_same_v<T, float> && std::abs(c.times[c.count - 1]) > 100) continue;
        std::vector<T> times(c.times, c.times + c.count);
        std::vector<quaternion<T>> rotations;
        for (std::size_t i = 0; i < c.count; ++i) rotations.push_back(from_row<T>(c.rotations[i]));
        for (std::size_t k = 0; k < c.samples; ++k) {
            const T angle =
                quat::angle_between(quat::keyframe_slerp(times, rotations, T(c.sample_times[k])),
                                    from_row<T>(c.rotation[k]));
            worst = std::max(worst, angle);
            CHECK(angle <= tolerance);
        }
    }
    CHECK(worst > 0);  // the comparison ran
}

TEMPLATE_TEST_CASE("keyframe_slerp is each keyframe at its time and slerp in between",
                   "[keyframe_slerp]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    std::vector<T> times{T(0)};
    std::vector<quaternion<T>> rotations{random.unit_quaternion<T>()};
    for (int i = 1; i < 20; ++i) {
        times.push_back(times.back() + random.uniform<T>(0.01, 3.0));
        rotations.push_back(random.unit_quaternion<T>());
    }
    for (std::size_t i = 0; i < times.size(); ++i)
        CHECK(quat::keyframe_slerp(times, rotations, times[i]) == rotations[i]);
    for (int n = 0; n < 1000; ++n) {
        const std::size_t i = std::size_t(random.uniform<double>(0, double(times.size() - 1)));
        const T u = random.uniform<T>(0.0, 1.0);
        const T t = times[i] + u * (times[i + 1] - times[i]);
        const T fraction = (t - times[i]) / (times[i + 1] - times[i]);
        CHECK(quat::keyframe_slerp(times, rotations, t) ==
              quat::slerp(rotations[i], rotations[i + 1], fraction));
    }
}

TEST_CASE("keyframe_slerp holds the end keyframes outside the times", "[keyframe_slerp]") {
    const double times[] = {1.0, 2.0, 4.0};
    const quaternion<double> rotations[] = {
        quat::from_rotation_vector(quat::vec3<double>{0.1, 0.0, 0.0}),
        quat::from_rotation_vector(quat::vec3<double>{0.0, 0.2, 0.0}),
        quat::from_rotation_vector(quat::vec3<double>{0.0, 0.0, 0.3})};
    const double infinity = std::numeric_limits<double>::infinity();
    CHECK(quat::keyframe_slerp(times, rotations, 0.5) == rotations[0]);
    CHECK(quat::keyframe_slerp(times, rotations, -infinity) == rotations[0]);
    CHECK(quat::keyframe_slerp(times, rotations, 9.0) == rotations[2]);
    CHECK(quat::keyframe_slerp(times, rotations, infinity) == rotations[2]);
}

TEST_CASE("keyframe_slerp of one keyframe is that keyframe; a NaN time or keyframe gives NaN",
          "[keyframe_slerp][nan]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<double> one_time{2.0};
    const std::vector<quaternion<double>> one{quaternion<double>{0.6, 0.8, 0.0, 0.0}};
    CHECK(quat::keyframe_slerp(one_time, one, -5.0) == one[0]);
    CHECK(std::isnan(quat::keyframe_slerp(one_time, one, nan).w));
    const std::vector<double> times{0.0, 1.0, 2.0, 3.0};
    std::vector<quaternion<double>> rotations(4, quaternion<double>::identity());
    CHECK(std::isnan(quat::keyframe_slerp(times, rotations, nan).w));
    rotations[2] = {nan, 0.0, 0.0, 0.0};
    CHECK(std::isnan(quat::keyframe_slerp(times, rotations, 1.5).w));
}

#ifdef NDEBUG
// Debug builds stop at these preconditions (tests/contracts); release builds must not read
// through a null pointer or past the shorter array, but return NaN.
TEST_CASE("a release-build keyframe_slerp of no keyframes or unequal sizes is NaN",
          "[keyframe_slerp][nan]") {
    using Q = quaternion<double>;
    const std::vector<double> no_times, two_times{0.0, 1.0};
    const std::vector<Q> no_rotations, three(3, Q::identity());
    for (const double t : {-1.0, 0.5, 2.0}) {
        CHECK(std::isnan(quat::keyframe_slerp(no_times, no_rotations, t).w));
        CHECK(std::isnan(quat::keyframe_slerp(two_times, three, t).w));
        CHECK(std::isnan(quat::keyframe_slerp(no_times, three, t).w));
    }
}

TEST_CASE("a release-build keyframe_slerp converts a double time beyond float's range to infinity",
          "[keyframe_slerp]") {
    // Not an undefined cast: the time is float's infinity, and the keyframe before it is held up
    // to there (debug builds stop at the non-finite time).
    const double far_times[] = {0.0, 1.0, 1e300};
    const quaternion<float> three[] = {quaternion<float>::identity(), quat::rotation_x(1.0f),
                                       quat::rotation_y(1.0f)};
    CHECK(quat::keyframe_slerp(far_times, three, 2.0) == three[1]);
    CHECK(quat::keyframe_slerp(far_times, three, 0.5) == quat::slerp(three[0], three[1], 0.5f));
}
#endif

TEST_CASE("keyframe_slerp takes times and t of another precision than its rotations",
          "[keyframe_slerp]") {
    // float rotations at double times, with a double t: both are converted to float, the
    // rotations' scalar, and the result is the all-float call's.
    quat::test::random_rotations random;
    std::vector<float> times{0.0f};
    std::vector<quaternion<float>> rotations{random.unit_quaternion<float>()};
    for (int i = 1; i < 10; ++i) {
        times.push_back(times.back() + random.uniform<float>(0.01, 3.0));
        rotations.push_back(random.unit_quaternion<float>());
    }
    const std::vector<double> double_times(times.begin(), times.end());
    for (int n = 0; n < 200; ++n) {
        const double t = random.uniform<double>(-1.0, double(times.back()) + 1.0);
        const quaternion<float> q = quat::keyframe_slerp(double_times, rotations, t);
        static_assert(std::is_same_v<decltype(q), const quaternion<float>>);
        CHECK(q == quat::keyframe_slerp(times, rotations, float(t)));
    }
}

}  // namespace test_keyframe_slerp
