// Cumulative B-splines on SO(3) (quat/trajectory/so3_bspline.hpp): the definition and the
// interface. The cumulative basis against its closed form (K = 4) and Cox-de Boor's recursion
// (K = 4, 5, 6); the domain rules (NaN from evaluate, an empty optional from try_evaluate, views
// that cannot be evaluated anywhere); noexcept, a trivially copyable view and constexpr evaluation.
// The rates, the Jacobians and their references are in tests/test_so3_bspline_derivatives.cpp.
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include <quat/quat.hpp>
#include <quat/trajectory/so3_bspline.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"

namespace test_so3_bspline {

namespace {

using namespace quat;
using ld = long double;

}  // namespace

TEST_CASE(
    "so3_bspline's cumulative basis: the closed form for K = 4 and Cox-de Boor for K = 4, 5, 6") {
    constexpr auto table = detail::cumulative_basis_table<4>();
    static_assert(table[0][0][0] == 6 && table[0][0][1] == 0 && table[0][0][3] == 0);
    static_assert(table[0][1][0] == 5 && table[0][1][1] == 3 && table[0][1][2] == -3 &&
                  table[0][1][3] == 1);
    static_assert(table[0][2][0] == 1 && table[0][2][1] == 3 && table[0][2][2] == 3 &&
                  table[0][2][3] == -2);
    static_assert(table[0][3][3] == 1 && table[1][3][2] == 3 && table[3][3][0] == 6);
    const auto cox_de_boor = [](int k, int s, ld x) {  // B-spline s of order k, knots 0, 1, 2, ...
        std::vector<ld> b(static_cast<std::size_t>(s + k), 0);
        for (int i = 0; i < s + k; ++i)
            b[static_cast<std::size_t>(i)] = (i <= x && x < i + 1) ? 1 : 0;
        for (int o = 2; o <= k; ++o)
            for (int i = 0; i + o <= s + k; ++i) {
                const auto u = static_cast<std::size_t>(i);
                b[u] = (x - i) / (o - 1) * b[u] + (i + o - x) / (o - 1) * b[u + 1];
            }
        return b[static_cast<std::size_t>(s)];
    };
    const auto check = [&](auto order) {
        constexpr std::size_t K = decltype(order)::value;
        for (const ld u : {0.0L, 0.125L, 0.5L, 0.75L, 0.999L}) {
            const auto w = detail::cumulative_weights_at<ld, K>(u, 1.0L);
            for (int j = 0; j < static_cast<int>(K); ++j) {
                // b~_j(u) = sum of the B-splines s >= j over the segment [K-1, K) of control points 0..K-1.
                ld expected = 0;
                for (int s = j; s < static_cast<int>(K); ++s)
                    expected += cox_de_boor(K, s, K - 1 + u);
                CHECK(std::abs(w.b[0][static_cast<std::size_t>(j)] - expected) <= 1e-18L);
            }
        }
    };
    check(std::integral_constant<int, 4>{});
    check(std::integral_constant<int, 5>{});
    check(std::integral_constant<int, 6>{});
}

TEST_CASE(
    "so3_bspline domain: t in [t0, t0 + (count - K + 1) dt], else NaN from evaluate and an "
    "empty optional from try_evaluate") {
    test::random_rotations random;
    const std::vector<quaternion<double>> points = test::random_walk<double>(random, 7, 1.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const auto is_nan_sample = [](const so3_bspline_sample<double>& s) {
        return s.first == 0 && std::isnan(s.rotation.w) && std::isnan(s.rotation.z) &&
               std::isnan(s.angular_velocity.x) && std::isnan(s.angular_acceleration.y) &&
               std::isnan(s.angular_jerk.z);
    };
    const so3_bspline<double, 4> spline(points, 1.0, 0.5);  // 7 points: 4 segments, [1, 3]
    CHECK(spline.valid());
    CHECK(spline.start_time() == 1.0);
    CHECK(spline.end_time() == 3.0);
    CHECK(spline.size() == 7);
    for (const double t : {1.0, 1.7, 2.5, 3.0}) {
        CHECK(spline.try_evaluate(t).has_value());
        CHECK(!is_nan_sample(spline.evaluate(t)));
    }
    CHECK(spline.evaluate(3.0).first == 3);  // the end belongs to the last segment
    CHECK(spline.evaluate(2.5).first == 3);  // a knot starts its segment
    CHECK(spline.evaluate(1.0).first == 0);
    for (const double t : {std::nextafter(1.0, 0.0), std::nextafter(3.0, 4.0), -inf, inf, nan}) {
        INFO("t = " << t);
        so3_bspline<double, 4>::jacobian_blocks J{};
        CHECK(is_nan_sample(spline.evaluate(t, &J)));
        CHECK(std::isnan(J[0](0, 0)));
        CHECK(std::isnan(J[3](2, 2)));
        CHECK(std::isnan(spline(t).w));
        CHECK(!spline.try_evaluate(t, &J).has_value());
    }
    // Views that cannot be evaluated anywhere.
    const so3_bspline<double, 4> too_few(points.data(), 3, 1.0, 0.5);
    const so3_bspline<double, 4> zero_spacing(points, 1.0, 0.0);
    const so3_bspline<double, 4> negative_spacing(points, 1.0, -0.5);
    const so3_bspline<double, 4> infinite_spacing(points, 1.0, inf);
    const so3_bspline<double, 4> nan_spacing(points, 1.0, nan);
    const so3_bspline<double, 4> nan_start(points, nan, 0.5);
    const so3_bspline<double, 4> null_points(nullptr, 7, 1.0, 0.5);
    for (const so3_bspline<double, 4>* s :
         {&too_few, &zero_spacing, &negative_spacing, &infinite_spacing, &nan_spacing, &nan_start,
          &null_points}) {
        CHECK(!s->valid());
        CHECK(std::isnan(s->end_time()));
        CHECK(is_nan_sample(s->evaluate(1.0)));
        CHECK(!s->try_evaluate(1.0).has_value());
    }
    // A non-finite control point: try_evaluate is empty where the segment reads it.
    std::vector<quaternion<double>> bad = points;
    bad[5] = {nan, 0, 0, 0};
    const so3_bspline<double, 4> with_nan(bad, 1.0, 0.5);
    CHECK(with_nan.try_evaluate(1.2).has_value());   // points 0..3
    CHECK(!with_nan.try_evaluate(2.2).has_value());  // points 2..5
}

TEST_CASE("so3_bspline: noexcept, a trivially copyable view, constexpr evaluation") {
    using spline = so3_bspline<double, 4>;
    static_assert(std::is_trivially_copyable_v<spline>);
    static_assert(noexcept(std::declval<const spline&>().evaluate(0.0)));
    static_assert(noexcept(std::declval<const spline&>().try_evaluate(0.0)));
    static_assert(noexcept(std::declval<const spline&>()(0.0)));
    static_assert(
        !std::is_constructible_v<spline, std::vector<quaternion<double>>&&, double, double>);
    static constexpr quaternion<double> points[5] = {
        {1, 0, 0, 0}, {1, 0, 0, 0}, {0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}};
    constexpr spline s(points, 0.0, 1.0);
    // Points 0..3 hold the first segment: d_1 = 0, d_2 = pi z, d_3 = 0, so R(1/2) = exp(b~_2(1/2) pi z)
    // with b~_2(u) = (1 + 3u + 3u^2 - 2u^3) / 6 = 1/2: a quarter turn about z.
    constexpr quaternion<double> q = s(0.5);
    static_assert(q.x == 0 && q.y == 0 && q.w > 0.7071 && q.w < 0.7072 && q.z > 0.7071 &&
                  q.z < 0.7072);
    CHECK(std::abs(q.w - std::sqrt(0.5)) <= 2e-16);
    CHECK(std::abs(q.z - std::sqrt(0.5)) <= 2e-16);
}

}  // namespace test_so3_bspline
