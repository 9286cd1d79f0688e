// Cumulative B-splines on SO(3) x R^3 (quat/trajectory/split_bspline.hpp): its rotation fields and
// Jacobians are so3_bspline's and its position fields euclidean_bspline's, bit for bit; the pose's
// body twist and its derivative against long double differences of the pose through se3's minus
// (one-sided at knots); the domain rules, with containers of different sizes.
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <quat/lie/se3.hpp>
#include <quat/quat.hpp>
#include <quat/trajectory.hpp>

#include "support/catch.hpp"
#include "support/jacobian_check.hpp"
#include "support/random.hpp"
#include "support/time_differences.hpp"

namespace test_split_bspline {

namespace {

using namespace quat;
using ld = long double;
using quat::test::relative_error;

quat::test::worst_errors worst("split_bspline");

std::array<ld, 6> arr(const se3::twist<ld>& t) {
    return {t.linear.x, t.linear.y, t.linear.z, t.angular.x, t.angular.y, t.angular.z};
}

bool same(const vec3<double>& a, const vec3<double>& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

template <std::size_t K>
void check_split(double t0, double dt) {
    test::random_rotations random;
    const std::vector<quaternion<double>> rotations = test::random_walk<double>(random, 9, 1.0);
    std::vector<vec3<double>> positions;
    for (int i = 0; i < 9; ++i) positions.push_back(random.vector<double>(2.0));
    std::vector<quaternion<ld>> wide_rotations;
    std::vector<vec3<ld>> wide_positions;
    for (const quaternion<double>& q : rotations) wide_rotations.push_back(quaternion<ld>(q));
    for (const vec3<double>& p : positions) wide_positions.push_back(vec3<ld>(p));
    const split_bspline<double, K> spline(rotations, positions, t0, dt);
    const split_bspline<ld, K> wide(wide_rotations, wide_positions, static_cast<ld>(t0),
                                    static_cast<ld>(dt));
    const so3_bspline<double, K> rotation(rotations, t0, dt);
    const euclidean_bspline<double, K> position(positions, t0, dt);
    REQUIRE(spline.valid());
    const std::string order = "K=" + std::to_string(K) + " ";
    std::vector<double> times;
    for (std::size_t i = 0; i <= 9 - K + 1; ++i) times.push_back(t0 + static_cast<double>(i) * dt);
    for (int n = 0; n < 4; ++n)
        times.push_back(t0 + (std::floor(random.uniform<double>(0, 9.0 - K + 1)) +
                              random.uniform<double>(0.05, 0.95)) *
                                 dt);
    for (const double t : times) {
        INFO(order << "t = " << t);
        std::array<matrix3<double>, K> Jq{}, Jw{}, Jq2{}, Jw2{};
        std::array<double, K> Jp{}, Jp2{};
        const split_bspline_sample<double> s = spline.evaluate(t, &Jq, &Jw, nullptr, nullptr, &Jp);
        const so3_bspline_sample<double> r = rotation.evaluate(t, &Jq2, &Jw2);
        const euclidean_bspline_sample<double> p = position.evaluate(t, &Jp2);
        CHECK(s.first == r.first);
        CHECK(s.rotation == r.rotation);
        CHECK(same(s.angular_velocity, r.angular_velocity));
        CHECK(same(s.angular_jerk, r.angular_jerk));
        CHECK(same(s.position, p.position));
        CHECK(same(s.linear_acceleration, p.acceleration));
        CHECK(Jq == Jq2);
        CHECK(Jw == Jw2);
        CHECK(Jp == Jp2);
        // The body twist of the pose X = (R, p) and its derivative, from differences of X.
        const double u = (t - t0) / dt;
        const bool knot = u == std::floor(u);
        const int side = !knot ? 0 : (t == spline.end_time() ? -1 : 1);
        const ld tl = t, h = 1e-3L * dt;
        const dual_quaternion<ld> base = wide(tl);
        const auto twist = test::time_derivative<6>(
            [&](ld d) { return arr(se3::minus(wide(tl + d), base)); }, h, side);
        const auto twist_rate = test::time_derivative<6>(
            [&](ld d) { return arr(wide.evaluate(tl + d).body_velocity); }, h, side);
        // Measured worst: body twist 6.3e-14, its derivative 2.5e-14.
        worst.check(order + "body twist", relative_error(se3::to_vector(s.body_velocity), twist));
        worst.check(order + "body twist derivative",
                    relative_error(se3::to_vector(s.body_acceleration), twist_rate));
    }
}

}  // namespace

TEST_CASE(
    "split_bspline: the halves are so3_bspline and euclidean_bspline, the body twist and its "
    "derivative against long double differences of the pose") {
    check_split<4>(0.25, 0.5);
    check_split<5>(-1.0, 0.75);
    check_split<6>(2.0, 0.3125);
}

TEST_CASE(
    "split_bspline domain: NaN from evaluate and an empty optional from try_evaluate outside "
    "the range, for containers of different sizes and for non-finite control points") {
    test::random_rotations random;
    const std::vector<quaternion<double>> rotations = test::random_walk<double>(random, 6, 1.0);
    std::vector<vec3<double>> positions(6, vec3<double>{1, 2, 3});
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const split_bspline<double, 4> spline(rotations, positions, 0.0, 1.0);  // [0, 3]
    CHECK(spline.valid());
    CHECK(spline.end_time() == 3.0);
    CHECK(spline.try_evaluate(3.0).has_value());
    for (const double t : {-1.0, 3.0000001, nan}) {
        std::array<double, 4> Jp{};
        std::array<matrix3<double>, 4> Jq{};
        const split_bspline_sample<double> s =
            spline.evaluate(t, &Jq, nullptr, nullptr, nullptr, &Jp);
        CHECK(std::isnan(s.rotation.w));
        CHECK(std::isnan(s.position.x));
        CHECK(std::isnan(s.body_velocity.linear.y));
        CHECK(std::isnan(s.body_acceleration.angular.z));
        CHECK(std::isnan(Jq[1](1, 1)));
        CHECK(std::isnan(Jp[3]));
        CHECK(!spline.try_evaluate(t).has_value());
        CHECK(std::isnan(spline(t).dual.x));
    }
    const std::vector<vec3<double>> fewer(5, vec3<double>{1, 2, 3});
    const split_bspline<double, 4> mismatched(rotations, fewer, 0.0, 1.0);
    CHECK(!mismatched.valid());
    CHECK(std::isnan(mismatched.end_time()));
    CHECK(std::isnan(mismatched.evaluate(1.0).rotation.w));
    CHECK(!mismatched.try_evaluate(1.0).has_value());
    std::vector<vec3<double>> bad = positions;
    bad[0].x = nan;
    const split_bspline<double, 4> with_nan(rotations, bad, 0.0, 1.0);
    CHECK(!with_nan.try_evaluate(0.5).has_value());
    CHECK(with_nan.try_evaluate(1.5).has_value());
}

}  // namespace test_split_bspline
