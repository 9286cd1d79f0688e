// Batch operations (quat/batch.hpp) give the scalar results: rotate over arrays of structs and
// structs of arrays, compose over a span, slerp at many parameters.
#include <array>
#include <cmath>
#include <vector>

#include <quat/batch.hpp>
#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace {

using quat::test::max_difference;

template <class T>
std::vector<quat::vec3<T>> random_points(quat::test::random_rotations& random, std::size_t n) {
    std::vector<quat::vec3<T>> p(n);
    for (auto& v : p) v = random.vector<T>(10.0);
    return p;
}

}  // namespace

TEMPLATE_TEST_CASE("batch rotate equals the scalar rotate, array of structs, every size", "[batch]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    // Sizes around the block length (256) and odd ones, so every tail path runs.
    for (const std::size_t n : {0u, 1u, 2u, 3u, 7u, 255u, 256u, 257u, 1000u, 1025u}) {
        const quat::quaternion<T> q = random.unit_quaternion<T>();
        const quat::rotation_matrix<T> m = quat::to_matrix(q);
        const std::vector<quat::vec3<T>> in = random_points<T>(random, n);
        std::vector<quat::vec3<T>> by_q(n), by_m(n);
        quat::rotate(q, in, by_q);
        quat::rotate(m, in.data(), by_m.data(), n);
        for (std::size_t i = 0; i < n; ++i) {
            // Points have length up to ~40, so the tolerance scales with it.
            CHECK(max_difference(by_q[i], quat::rotate(q, in[i])) <=
                  64 * quat::test::tolerance<T>::rotate);
            // Not bit-exact: a compiler may contract the vectorized a * b + c into FMAs differently.
            CHECK(max_difference(by_m[i], quat::rotate(m, in[i])) <=
                  64 * quat::test::tolerance<T>::rotate);
        }
    }
}

TEMPLATE_TEST_CASE("batch rotate, struct of arrays, matches array of structs", "[batch]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (const std::size_t n : {1u, 5u, 256u, 777u}) {
        const quat::quaternion<T> q = random.unit_quaternion<T>();
        const std::vector<quat::vec3<T>> in = random_points<T>(random, n);
        std::vector<T> x(n), y(n), z(n), ox(n), oy(n), oz(n);
        for (std::size_t i = 0; i < n; ++i) x[i] = in[i].x, y[i] = in[i].y, z[i] = in[i].z;
        std::vector<quat::vec3<T>> aos(n);
        quat::rotate(q, in, aos);
        quat::rotate(q, quat::soa_points<const T>{x.data(), y.data(), z.data(), n},
                     quat::soa_points<T>{ox.data(), oy.data(), oz.data(), n});
        for (std::size_t i = 0; i < n; ++i) {
            CHECK(max_difference(quat::vec3<T>{ox[i], oy[i], oz[i]}, aos[i]) <=
                  64 * quat::test::tolerance<T>::rotate);
        }
    }
}

TEST_CASE("batch rotate works in place (output == input), the documented aliasing rule",
          "[batch]") {
    quat::test::random_rotations random;
    const quat::quatf q = random.unit_quaternion<float>();
    std::vector<quat::vec3<float>> points = random_points<float>(random, 600);
    const std::vector<quat::vec3<float>> original = points;
    std::vector<quat::vec3<float>> expected(points.size());
    quat::rotate(q, original, expected);
    quat::rotate(q, points, points);
    CHECK(points == expected);

    std::vector<float> x(600), y(600), z(600);
    for (std::size_t i = 0; i < 600; ++i)
        x[i] = original[i].x, y[i] = original[i].y, z[i] = original[i].z;
    quat::rotate(q, quat::soa_points<const float>{x.data(), y.data(), z.data(), 600},
                 quat::soa_points<float>{x.data(), y.data(), z.data(), 600});
    for (std::size_t i = 0; i < 600; ++i)
        CHECK(max_difference(quat::vec3<float>{x[i], y[i], z[i]}, expected[i]) <=
              64 * quat::test::tolerance<float>::rotate);
}

TEST_CASE("batch rotate accepts std::array and C arrays", "[batch]") {
    const quat::quatd q =
        quat::to_quaternion(quat::axis_angle<double>{{0, 0, 1}, 1.5707963267948966});
    const std::array<quat::vec3<double>, 2> in{{{1, 0, 0}, {0, 1, 0}}};
    quat::vec3<double> out[2];
    quat::rotate(q, in, out);
    CHECK(max_difference(out[0], quat::vec3<double>{0, 1, 0}) <= 1e-15);
    CHECK(max_difference(out[1], quat::vec3<double>{-1, 0, 0}) <= 1e-15);
}

TEMPLATE_TEST_CASE("compose(span) is the left-to-right product, rounded differently", "[batch]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (const std::size_t n : {0u, 1u, 2u, 3u, 4u, 5u, 9u, 64u, 1023u, 1024u}) {
        std::vector<quat::quaternion<T>> factors(n);
        for (auto& f : factors) f = random.unit_quaternion<T>();
        quat::quaternion<T> sequential = quat::quaternion<T>::identity();
        for (const auto& f : factors) sequential = sequential * f;
        const quat::quaternion<T> tree = quat::compose(factors);
        // Measured: for 1024 factors the largest component difference is 2.5e-6 (float) and
        // 5.1e-15 (double), the size of the sequential product's own rounding error.
        const T bound = T(n + 4) * 4 * std::numeric_limits<T>::epsilon();
        CHECK(max_difference(tree, sequential) <= bound);
    }
}

TEMPLATE_TEST_CASE("batch slerp equals the scalar slerp at every t", "[batch]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int pair = 0; pair < 50; ++pair) {
        const quat::quaternion<T> a = random.unit_quaternion<T>();
        quat::quaternion<T> b = random.unit_quaternion<T>();
        if (pair == 0) b = a;   // equal: series path
        if (pair == 1) b = -a;  // opposite sign, same rotation
        std::vector<T> t(301);
        for (std::size_t i = 0; i < t.size(); ++i) t[i] = T(i) / T(300);
        if (pair == 2) t[7] = T(1.5);  // outside [0, 1]: scalar fallback
        std::vector<quat::quaternion<T>> out(t.size());
        quat::slerp(a, b, t, out);
        for (std::size_t i = 0; i < t.size(); ++i) {
            const quat::quaternion<T> expected = quat::slerp(a, b, t[i]);
            CHECK(max_difference(out[i], expected) <= 8 * std::numeric_limits<T>::epsilon());
        }
        CHECK(out.front() == a);
        CHECK(out.back() == quat::slerp(a, b, T(1)));
    }
}

TEST_CASE(
    "batch rotate of a float array beyond 16 MiB (streamed in AVX-512 builds) equals the scalar "
    "rotate",
    "[batch]") {
    quat::test::random_rotations random;
    const quat::quatf q = random.unit_quaternion<float>();
    const quat::rotation_matrix<float> m = quat::to_matrix(q);
    const std::size_t n = (std::size_t(16) << 20) / sizeof(quat::vec3<float>) + 101;  // odd tail
    std::vector<quat::vec3<float>> points(n);
    for (std::size_t i = 0; i < n; ++i)
        points[i] = {float(i % 97) - 48.0f, float(i % 89) * 0.5f, 1.0f};
    std::vector<quat::vec3<float>> out(n);
    quat::rotate(q, points, out);
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < n; ++i)
        mismatches +=
            max_difference(out[i], quat::rotate(m, points[i])) <= 1e-4f ? 0 : 1;  // |p| < 60
    CHECK(mismatches == 0);
    quat::rotate(m, points, points);  // in place
    CHECK(points == out);
}

TEST_CASE("struct-of-arrays rotate beyond 16 MiB (streaming stores) equals the scalar rotate",
          "[batch]") {
    const quat::quatf q = quat::normalize(quat::quatf{0.3f, -0.5f, 0.7f, 0.2f});
    const quat::rotation_matrix<float> m = quat::to_matrix(q);
    const std::size_t n = (std::size_t(16) << 20) / (3 * sizeof(float)) + 77;
    std::vector<float> x(n), y(n), z(n), ox(n), oy(n), oz(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = float(i % 31), y[i] = -float(i % 17), z[i] = 0.5f;
    quat::rotate(q, quat::soa_points<const float>{x.data(), y.data(), z.data(), n},
                 quat::soa_points<float>{ox.data(), oy.data(), oz.data(), n});
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const quat::vec3<float> expected = quat::rotate(m, quat::vec3<float>{x[i], y[i], z[i]});
        mismatches +=
            max_difference(quat::vec3<float>{ox[i], oy[i], oz[i]}, expected) <= 1e-4f ? 0 : 1;
    }
    CHECK(mismatches == 0);
}
