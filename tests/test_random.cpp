// Specification of random.hpp: random_rotation is uniform over rotations (the Haar measure).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <quat/random.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_random {

using quat::quaternion;
using quat::vec3;
using quat::test::tolerance;

namespace {

constexpr int sample_count = 100000;

// Kolmogorov-Smirnov statistic: the largest distance between the empirical distribution function of
// the samples and the distribution function cdf.
template <class Cdf>
double kolmogorov_smirnov(std::vector<double> samples, Cdf cdf) {
    std::sort(samples.begin(), samples.end());
    const double n = static_cast<double>(samples.size());
    double worst = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const double f = cdf(samples[i]);
        worst =
            std::max({worst, f - static_cast<double>(i) / n, static_cast<double>(i + 1) / n - f});
    }
    return worst;
}

// The statistic a correct sampler stays below with probability 0.999: 1.95 / sqrt(n).
const double critical_value = 1.95 / std::sqrt(double(sample_count));

// The rotation angle in [0, pi] has density (1 - cos(angle)) / pi under the Haar measure.
double angle_cdf(double angle) { return (angle - std::sin(angle)) / quat::numbers::pi; }

template <class T>
double rotation_angle(const quaternion<T>& q) {
    return 2 * std::atan2(std::sqrt(double(q.x) * q.x + double(q.y) * q.y + double(q.z) * q.z),
                          std::abs(double(q.w)));
}

// The common wrong sampler (drake issue #10319, glam's Quat::random before its fix): a uniform
// axis and a uniform angle. It overweights small angles.
quat::quatd uniform_axis_uniform_angle(quat::test::random_rotations& random) {
    const vec3<double> axis = random.unit_vector<double>();
    const double half = random.uniform<double>(0, quat::numbers::pi) / 2;
    return {std::cos(half), axis.x * std::sin(half), axis.y * std::sin(half),
            axis.z * std::sin(half)};
}

struct statistics {
    double angle, rotated_z, azimuth;  // KS statistics
};

// KS statistics of n rotations from `draw`: their angles, and the z component (uniform on [-1, 1],
// Archimedes) and azimuth (uniform on [-pi, pi]) of the rotated z axis.
template <class Draw>
statistics measure(Draw draw) {
    std::vector<double> angles, heights, azimuths;
    for (int n = 0; n < sample_count; ++n) {
        const auto q = draw();
        angles.push_back(rotation_angle(q));
        const auto v = quat::rotate(q, decltype(quat::rotate(q, {0, 0, 1})){0, 0, 1});
        heights.push_back(double(v.z));
        azimuths.push_back(std::atan2(double(v.y), double(v.x)));
    }
    return {kolmogorov_smirnov(angles, angle_cdf),
            kolmogorov_smirnov(heights, [](double z) { return (z + 1) / 2; }),
            kolmogorov_smirnov(azimuths, [](double a) {
                return (a + quat::numbers::pi) / (2 * quat::numbers::pi);
            })};
}

template <class T, class Engine>
void check_uniform(Engine engine) {
    const statistics s = measure([&engine] { return quat::random_rotation<T>(engine); });
    INFO("KS statistics: angle " << s.angle << ", rotated z " << s.rotated_z << ", azimuth "
                                 << s.azimuth << "; critical " << critical_value);
    CHECK(s.angle < critical_value);
    CHECK(s.rotated_z < critical_value);
    CHECK(s.azimuth < critical_value);
}

}  // namespace

TEMPLATE_TEST_CASE("random_rotation is uniform over rotations with each standard engine",
                   "[random][sweep]", float, double) {
    using T = TestType;
    // 10^5 samples each, KS critical value 0.00617 (alpha = 0.001). Measured statistics (angle,
    // rotated z, azimuth), g++ 12 / libstdc++: float mt19937 0.0032 0.0024 0.0031, mt19937_64
    // 0.0031 0.0024 0.0024, minstd_rand 0.0047 0.0018 0.0023; double mt19937 0.0044 0.0023 0.0016,
    // mt19937_64 0.0031 0.0024 0.0024, minstd_rand 0.0019 0.0024 0.0031.
    SECTION("std::mt19937") { check_uniform<T>(std::mt19937(quat::test::seed)); }
    SECTION("std::mt19937_64") { check_uniform<T>(std::mt19937_64(quat::test::seed)); }
    SECTION("std::minstd_rand") { check_uniform<T>(std::minstd_rand(quat::test::seed)); }
}

TEST_CASE("the same test rejects a uniform axis with a uniform angle", "[random][sweep]") {
    // The check above must be able to fail: this sampler's angle distribution function is
    // angle / pi, off by up to 1 / pi = 0.32 from the right one. Measured KS statistics: angle
    // 0.318, rotated z 0.251 (it leaves the axis near where it was).
    quat::test::random_rotations random;
    const statistics s = measure([&random] { return uniform_axis_uniform_angle(random); });
    INFO("KS statistics: angle " << s.angle << ", rotated z " << s.rotated_z);
    CHECK(s.angle > 10 * critical_value);
    CHECK(s.rotated_z > 10 * critical_value);
}

TEMPLATE_TEST_CASE("random_rotation is unit with w >= 0 and depends only on the engine's state",
                   "[random]", float, double) {
    using T = TestType;
    std::mt19937_64 engine(quat::test::seed), copy(quat::test::seed);
    std::minstd_rand small(quat::test::seed), small_copy(quat::test::seed);
    for (int n = 0; n < 10000; ++n) {
        const quaternion<T> q = quat::random_rotation<T>(engine);
        CHECK(q.w >= 0);
        CHECK(std::abs(quat::norm(q) - 1) <= tolerance<T>::unit_norm);
        CHECK(quat::random_rotation<T>(copy) == q);
        CHECK(quat::random_rotation<T>(small) == quat::random_rotation<T>(small_copy));
    }
    // Three uniforms, each from as many calls as std::generate_canonical makes: one call of a
    // 64-bit engine per uniform.
    std::mt19937_64 counted(quat::test::seed);
    (void)quat::random_rotation<T>(counted);
    std::mt19937_64 reference(quat::test::seed);
    reference.discard(3);
    CHECK(counted == reference);
}

namespace {

// An engine stuck at its largest value: std::generate_canonical may then round up to 1.
struct stuck_engine {
    using result_type = std::uint32_t;
    static constexpr result_type min() { return 0; }
    static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }
    result_type operator()() noexcept { return max(); }
};

}  // namespace

TEMPLATE_TEST_CASE("random_rotation stays unit and finite at the ends of the engine's range",
                   "[random]", float, double) {
    using T = TestType;
    stuck_engine engine;
    const quaternion<T> q = quat::random_rotation<T>(engine);
    CHECK(std::isfinite(q.w));
    CHECK(q.w >= 0);
    CHECK(std::abs(quat::norm(q) - 1) <= tolerance<T>::unit_norm);
    static_assert(noexcept(quat::random_rotation<T>(engine)));
}

namespace {

/// A 32-bit generator that replays fixed outputs: one call per float uniform.
struct replay_generator {
    using result_type = std::uint32_t;
    static constexpr result_type min() { return 0; }
    static constexpr result_type max() { return 0xffffffffu; }
    const std::uint32_t* values;
    std::size_t next = 0;
    result_type operator()() { return values[next++ % 3]; }
};

}  // namespace

TEST_CASE("random_rotation<float> keeps w >= 0 at the ends of the third uniform",
          "[random][edge]") {
    // u3 = 2^-31 (the case) put theta2 just past -pi/2 with float's rounded pi: w < 0.
    for (std::uint32_t g3 : {0u, 1u, 2u, 3u, 255u, 0xffffffffu, 0xfffffffeu, 0xffffff00u}) {
        const std::uint32_t values[3] = {0x80000000u, 0x12345678u, g3};
        replay_generator generator{values};
        const quaternion<float> q = quat::random_rotation<float>(generator);
        INFO("third output " << g3);
        CHECK(q.w >= 0.0f);
        CHECK(std::abs(quat::norm(q) - 1.0f) <= 4 * std::numeric_limits<float>::epsilon());
    }
}

}  // namespace test_random
