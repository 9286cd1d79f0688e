// Batch operations (quat/batch/rotations.hpp) give the scalar results: rotate over arrays of
// structs and structs of arrays, compose over a span, slerp at many parameters.
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include <quat/batch/rotations.hpp>
#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_rotations {

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
    // Every size to 40 (the AVX steps of 16 and 8 points and each tail), sizes around the block
    // length (256) and odd ones, so every path runs.
    std::vector<std::size_t> sizes = {255u, 256u, 257u, 1000u, 1025u};
    for (std::size_t n = 0; n <= 40; ++n) sizes.push_back(n);
    for (const std::size_t n : sizes) {
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
            // Not bit-exact: a compiler may contract the vectorized a * b + c into FMAs
            // differently.
            CHECK(max_difference(by_m[i], quat::rotate(m, in[i])) <=
                  64 * quat::test::tolerance<T>::rotate);
        }
    }
}

TEMPLATE_TEST_CASE("batch rotate, struct of arrays, matches array of structs", "[batch]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    // Every size to 40 (whole vectors of lanes and each tail), and longer ones; from 2053 float
    // points on, past detail::prefetch_bytes, the loop prefetches its outputs.
    std::vector<std::size_t> sizes = {256u, 777u, 2053u};
    for (std::size_t n = 0; n <= 40; ++n) sizes.push_back(n);
    for (const std::size_t n : sizes) {
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
    // In place gives what out of place gives, bit for bit, at every size of the 16- and 8-point
    // steps and their tails (AVX-512 builds move the last, overlapping 16 points from a copy).
    for (std::size_t n = 0; n <= 50; ++n) {
        const std::vector<quat::vec3<float>> original = random_points<float>(random, n);
        std::vector<quat::vec3<float>> points = original, expected(n);
        quat::rotate(q, original, expected);
        quat::rotate(q, points, points);
        CHECK(points == expected);
    }
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

TEST_CASE("batch rotate: a NaN or infinite point gives NaN in its own output only", "[batch]") {
    quat::test::random_rotations random;
    const quat::quatf q = random.unit_quaternion<float>();
    for (const float bad :
         {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        for (std::size_t at = 0; at < 40; at += 3) {  // every position in a 16- and 8-point step
            std::vector<quat::vec3<float>> points = random_points<float>(random, 40);
            points[at].y = bad;
            std::vector<quat::vec3<float>> out(points.size());
            quat::rotate(q, points, out);
            for (std::size_t i = 0; i < points.size(); ++i) {
                const quat::vec3<float> expected = quat::rotate(q, points[i]);
                if (i == at) {
                    CHECK_FALSE(std::isfinite(out[i].x + out[i].y + out[i].z));
                } else {
                    CHECK(max_difference(out[i], expected) <=
                          64 * quat::test::tolerance<float>::rotate);
                }
            }
        }
    }
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

namespace {

// Independent reference for the batch slerp: the textbook formula in long double,
// sin((1 - t) h) / sin(h) a + sin(t h) / sin(h) b, with b's sign chosen for the shorter arc and the
// angle h between a and b taken from the chord, 2 atan2(|a - b|, |a + b|).
template <class T>
quat::quaternion<long double> reference_slerp(const quat::quaternion<T>& a_in,
                                              const quat::quaternion<T>& b_in, long double t) {
    const quat::quaternion<long double> a{a_in.w, a_in.x, a_in.y, a_in.z};
    quat::quaternion<long double> b{b_in.w, b_in.x, b_in.y, b_in.z};
    if (quat::dot(a, b) < 0) b = -b;
    const long double h =
        2 * std::atan2(std::sqrt(quat::squared_norm(a - b)), std::sqrt(quat::squared_norm(a + b)));
    if (h == 0) return a;
    return a * (std::sin((1 - t) * h) / std::sin(h)) + b * (std::sin(t * h) / std::sin(h));
}

/// Largest component difference of q from the reference r.
template <class T>
long double component_error(const quat::quaternion<T>& q, const quat::quaternion<long double>& r) {
    long double worst = 0;
    for (const long double d : {q.w - r.w, q.x - r.x, q.y - r.y, q.z - r.z})
        if (std::abs(d) > worst) worst = std::abs(d);
    return worst;
}

}  // namespace

TEMPLATE_TEST_CASE("batch slerp matches a long double slerp, polynomial path and fallbacks",
                   "[batch]", float, double) {
    using T = TestType;
    const long double eps = std::numeric_limits<T>::epsilon();
    quat::test::random_rotations random;
    // The polynomial path runs (float and double) when every t is in [0, 1] and the 4D angle h
    // between a and b has h^4 >= eps; otherwise each value falls back to the scalar slerp. Pairs
    // 0-2 take the fallback; all others the polynomial: rotation angles spread over 0.01 ... 3.13
    // rad (h up to just below pi/2, where the shorter arc is still decided in T), then random
    // pairs.
    std::vector<T> t(301);
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = T(i) / T(300);
    long double worst_polynomial = 0, worst_fallback = 0;
    for (int pair = 0; pair < 200; ++pair) {
        const quat::quaternion<T> a = random.unit_quaternion<T>();
        quat::quaternion<T> b = random.unit_quaternion<T>();
        if (pair == 0) b = a;   // equal: fallback
        if (pair == 1) b = -a;  // the same rotation with the far sign: fallback
        if (pair >= 3 && pair < 100) {
            const T rotation_angle = T(0.01 + (3.13 - 0.01) * (pair - 3) / 96.0);
            const quat::vec3<T> axis = random.unit_vector<T>();
            const quat::quaternion<T> turn{
                std::cos(rotation_angle / 2), axis.x * std::sin(rotation_angle / 2),
                axis.y * std::sin(rotation_angle / 2), axis.z * std::sin(rotation_angle / 2)};
            b = quat::normalize(a * turn);
        }
        std::vector<T> ts = t;
        if (pair == 2) ts[7] = T(1.5);  // outside [0, 1]: fallback for every value
        std::vector<quat::quaternion<T>> out(ts.size());
        quat::slerp(a, b, ts, out);
        for (std::size_t i = 0; i < ts.size(); ++i) {
            const long double e = component_error(out[i], reference_slerp(a, b, ts[i])) / eps;
            long double& worst = pair < 3 ? worst_fallback : worst_polynomial;
            if (e > worst) worst = e;
        }
        // Exact ends on both paths.
        CHECK(out.front() == a);
        CHECK(out.back() == (quat::dot(a, b) < 0 ? -b : b));
    }
    // Measured: polynomial path 2.8 (float) and 2.6 (double) eps, fallback 1.1 and 0.9 eps.
    INFO(sizeof(T) * 8 << "-bit: largest component error: polynomial path "
                       << double(worst_polynomial) << " eps, fallback " << double(worst_fallback)
                       << " eps");
    CHECK(worst_polynomial <= 4);
    CHECK(worst_fallback <= 4);
}

TEST_CASE(
    "the streaming threshold is half the last-level cache, at most 16 MiB (16 MiB where none is "
    "known), and at least 128 KiB",
    "[batch]") {
    const std::size_t cache = quat::detail::last_level_cache_bytes();
    INFO("last-level cache: " << cache << " bytes");
    CHECK(quat::detail::last_level_cache_bytes() == cache);  // read once, the same every time
    const std::size_t largest = std::size_t(16) << 20;
    const std::size_t half = cache == 0 || cache / 2 > largest ? largest : cache / 2;
    const std::size_t threshold = quat::detail::streaming_threshold_bytes();
    CHECK(threshold == (half < (std::size_t(128) << 10) ? std::size_t(128) << 10 : half));
    CHECK(quat::detail::streams_output(threshold) == quat::detail::has_streaming_stores);
    CHECK_FALSE(quat::detail::streams_output(threshold - 1));
}

TEST_CASE(
    "batch rotate of a float array beyond the streaming threshold (non-temporal stores on x86) "
    "equals the scalar rotate",
    "[batch]") {
    quat::test::random_rotations random;
    const quat::quatf q = random.unit_quaternion<float>();
    const quat::rotation_matrix<float> m = quat::to_matrix(q);
    const std::size_t n =
        quat::detail::streaming_threshold_bytes() / sizeof(quat::vec3<float>) + 101;  // odd tail
    std::vector<quat::vec3<float>> points(n);
    for (std::size_t i = 0; i < n; ++i)
        points[i] = {float(i % 97) - 48.0f, float(i % 89) * 0.5f, 1.0f};
    std::vector<quat::vec3<float>> out(n);
    quat::rotate(q, points, out);
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (!(max_difference(out[i], quat::rotate(m, points[i])) <= 1e-4f))
            ++mismatches;  // |p| < 60
    CHECK(mismatches == 0);
    quat::rotate(m, points, points);  // in place
    CHECK(points == out);
}

TEST_CASE(
    "batch rotate and transform of floats: every offset of input and output from a cache "
    "line, every size to 40",
    "[batch]") {
    // AVX-512 builds start their 16-point kernel on the first 64-byte boundary of the input and do
    // the points before it plainly; input and output start k points (12 k bytes) into their
    // buffers, which meets every offset from a line.
    const quat::quatf q = quat::normalize(quat::quatf{0.6f, 0.1f, -0.3f, 0.4f});
    const quat::rotation_matrix<float> m = quat::to_matrix(q);
    const quat::vec3<float> t{0.5f, -1.0f, 2.0f};
    std::vector<quat::vec3<float>> source(100);
    for (std::size_t i = 0; i < source.size(); ++i)
        source[i] = {float(i % 13) - 6.0f, float(i % 7) * 0.25f, -float(i % 5)};
    const quat::vec3<float> sentinel{9, 9, 9};
    std::size_t mismatches = 0, overwritten = 0;
    for (std::size_t in_offset = 0; in_offset < 16; ++in_offset) {
        for (std::size_t out_offset = 0; out_offset < 16; ++out_offset) {
            for (std::size_t count = 0; count <= 41; ++count) {
                const quat::vec3<float>* in = source.data() + in_offset;
                std::vector<quat::vec3<float>> buffer(60, sentinel);
                quat::vec3<float>* out = buffer.data() + out_offset + 1;
                quat::rotate(m, in, out, count);
                for (std::size_t i = 0; i < count; ++i)
                    if (!(max_difference(out[i], quat::rotate(m, in[i])) <= 1e-5f)) ++mismatches;
                std::vector<quat::vec3<float>> moved(60, sentinel);
                quat::vec3<float>* moved_out = moved.data() + out_offset + 1;
                quat::detail::transform_points<true>(m, t, in, moved_out, count);
                for (std::size_t i = 0; i < count; ++i)
                    if (!(max_difference(moved_out[i], quat::rotate(m, in[i]) + t) <= 1e-5f))
                        ++mismatches;
                if (!(out[-1] == sentinel && out[count] == sentinel && moved_out[-1] == sentinel &&
                      moved_out[count] == sentinel))
                    ++overwritten;
            }
        }
    }
    CHECK(mismatches == 0);
    CHECK(overwritten == 0);  // nothing written before or past the output
}

TEST_CASE("streamed batch rotate: every offset of the output from a cache line, every short tail",
          "[batch]") {
    // The streaming path (called directly here, whatever this machine's threshold) stores plainly
    // up to a 64-byte boundary of the output, then streams: an output starting k points (12 k
    // bytes) into a buffer meets the boundary after a different number of points for each k < 16.
    const quat::quatf q = quat::normalize(quat::quatf{0.6f, 0.1f, -0.3f, 0.4f});
    const quat::rotation_matrix<float> m = quat::to_matrix(q);
    const quat::vec3<float> t{0.5f, -1.0f, 2.0f};
    std::vector<quat::vec3<float>> points(3000), buffer(3100);
    for (std::size_t i = 0; i < points.size(); ++i)
        points[i] = {float(i % 13) - 6.0f, float(i % 7) * 0.25f, -float(i % 5)};
    for (std::size_t offset = 0; offset < 16; ++offset) {
        for (const std::size_t count : {0u, 1u, 7u, 15u, 16u, 17u, 255u, 256u, 257u, 2999u}) {
            quat::vec3<float>* out = buffer.data() + offset;
            const quat::vec3<float> sentinel{9, 9, 9};
            out[count] = sentinel;
            quat::detail::transform_streaming<true>(m, t, points.data(), out, count);
            std::size_t mismatches = 0;
            for (std::size_t i = 0; i < count; ++i)
                if (!(max_difference(out[i], quat::rotate(m, points[i]) + t) <= 1e-5f))
                    ++mismatches;
            INFO("offset " << offset << " points, " << count << " points");
            CHECK(mismatches == 0);
            CHECK(out[count] == sentinel);  // nothing written past the end
        }
    }
}

TEST_CASE(
    "struct-of-arrays rotate beyond the streaming threshold (streaming stores) equals the scalar "
    "rotate",
    "[batch]") {
    const quat::quatf q = quat::normalize(quat::quatf{0.3f, -0.5f, 0.7f, 0.2f});
    const quat::rotation_matrix<float> m = quat::to_matrix(q);
    const std::size_t n = quat::detail::streaming_threshold_bytes() / (3 * sizeof(float)) + 77;
    std::vector<float> x(n), y(n), z(n), ox(n), oy(n), oz(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = float(i % 31), y[i] = -float(i % 17), z[i] = 0.5f;
    quat::rotate(q, quat::soa_points<const float>{x.data(), y.data(), z.data(), n},
                 quat::soa_points<float>{ox.data(), oy.data(), oz.data(), n});
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const quat::vec3<float> expected = quat::rotate(m, quat::vec3<float>{x[i], y[i], z[i]});
        if (!(max_difference(quat::vec3<float>{ox[i], oy[i], oz[i]}, expected) <= 1e-4f))
            ++mismatches;
    }
    CHECK(mismatches == 0);
}

TEMPLATE_TEST_CASE("batch slerp: a and b may be elements of the output (taken by value)", "[batch]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    const quat::quaternion<T> a = random.unit_quaternion<T>();
    const quat::quaternion<T> b = random.unit_quaternion<T>();
    // More parameters than one block (128), so later blocks run after out[0] was written; no t is
    // 0 or 1, where the result would be a or b exactly whatever was read.
    std::vector<T> t(301);
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = (T(i) + T(0.5)) / T(301);
    std::vector<quat::quaternion<T>> expected(t.size());
    quat::slerp(a, b, t, expected);
    std::vector<quat::quaternion<T>> out(t.size());
    out[0] = a;
    out.back() = b;
    quat::slerp(out[0], out.back(), t, out);  // a is overwritten first, b last
    CHECK(out == expected);
    out[0] = a;
    out.back() = b;
    quat::slerp(out[0], out.back(), t.data(), out.data(), t.size());  // pointer form
    CHECK(out == expected);
}

TEST_CASE("batch slerp: float rotations at double times, and double rotations at float times",
          "[batch]") {
    quat::test::random_rotations random;
    const quat::quatf af = random.unit_quaternion<float>(), bf = random.unit_quaternion<float>();
    const quat::quatd ad{af}, bd{bf};
    std::vector<double> td(301);
    std::vector<float> tf(td.size());
    for (std::size_t i = 0; i < td.size(); ++i) {
        td[i] = double(i) / 300.0;
        tf[i] = float(td[i]);
    }
    // The scalar type is the rotations'; each t converts to it, so float rotations at double times
    // are float rotations at the times rounded to float.
    std::vector<quat::quatf> from_double(td.size()), from_float(td.size());
    quat::slerp(af, bf, td, from_double);
    quat::slerp(af, bf, tf, from_float);
    CHECK(from_double == from_float);
    quat::slerp(af, bf, td.data(), from_double.data(), td.size());
    CHECK(from_double == from_float);
    // Outside [0, 1] (the scalar fallback) too.
    td[5] = 1.5;
    tf[5] = 1.5f;
    quat::slerp(af, bf, td, from_double);
    quat::slerp(af, bf, tf, from_float);
    CHECK(from_double == from_float);
    // Double rotations at float times: the float times are exact in double.
    std::vector<quat::quatd> at_float(tf.size()), at_double(tf.size());
    std::vector<double> widened(tf.begin(), tf.end());
    quat::slerp(ad, bd, tf, at_float);
    quat::slerp(ad, bd, widened, at_double);
    CHECK(at_float == at_double);
    // A C array of double times and a std::array output.
    const double times[3] = {0.0, 0.25, 1.0};
    std::array<quat::quatf, 3> three{};
    quat::slerp(af, bf, times, three);
    CHECK(three[0] == af);
    CHECK(quat::approx_equal(three[1], quat::slerp(af, bf, 0.25f), 1e-6f));  // a few ulp
}

TEMPLATE_TEST_CASE("struct-of-arrays rotate in place: soa_points<T> is also the const input",
                   "[batch]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    const quat::quaternion<T> q = random.unit_quaternion<T>();
    const std::size_t n = 37;
    std::vector<T> x(n), y(n), z(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = T(i), y[i] = T(1) - T(i), z[i] = T(0.5) * T(i);
    std::vector<quat::vec3<T>> expected(n);
    for (std::size_t i = 0; i < n; ++i)
        expected[i] = quat::rotate(q, quat::vec3<T>{x[i], y[i], z[i]});
    const quat::soa_points<T> points{x.data(), y.data(), z.data(), n};
    static_assert(std::is_convertible_v<quat::soa_points<T>, quat::soa_points<const T>>);
    static_assert(!std::is_convertible_v<quat::soa_points<const T>, quat::soa_points<T>>);
    quat::rotate(q, points, points);
    for (std::size_t i = 0; i < n; ++i)
        CHECK(max_difference(quat::vec3<T>{x[i], y[i], z[i]}, expected[i]) <=
              T(64) * std::numeric_limits<T>::epsilon());
    quat::rotate(quat::to_matrix(quat::conjugate(q)), points, points);  // and back, by the matrix
    for (std::size_t i = 0; i < n; ++i)
        CHECK(std::abs(x[i] - T(i)) <= T(64) * std::numeric_limits<T>::epsilon());
}

}  // namespace test_rotations
