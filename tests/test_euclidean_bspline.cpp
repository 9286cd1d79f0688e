// Cumulative B-splines in R^3 (quat/trajectory/euclidean_bspline.hpp), K = 4, 5, 6: velocity,
// acceleration and jerk against long double Richardson differences in time of the library's own long
// double evaluation (one-sided at knots); the Jacobian weights against moving one point, against
// ceres::Jet derivatives, and as a partition of unity; the domain rules.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <ceres/jet.h>
#include <quat/quat.hpp>
#include <quat/trajectory/euclidean_bspline.hpp>

#include "support/catch.hpp"
#include "support/jacobian_check.hpp"
#include "support/random.hpp"
#include "support/time_differences.hpp"

namespace test_euclidean_bspline {

namespace {

using namespace quat;
using ld = long double;
using quat::test::relative_error;

quat::test::worst_errors worst("euclidean_bspline");

std::array<ld, 3> arr(const vec3<ld>& v) { return {v.x, v.y, v.z}; }
matrix<double, 3, 1> column(const vec3<double>& v) { return {{{v.x}, {v.y}, {v.z}}}; }

std::vector<vec3<double>> random_points(std::size_t count) {
    test::random_rotations random;
    std::vector<vec3<double>> points;
    for (std::size_t i = 0; i < count; ++i) points.push_back(random.vector<double>(3.0));
    return points;
}

template <std::size_t K>
void check_path(double t0, double dt) {
    const std::vector<vec3<double>> points = random_points(9);
    std::vector<vec3<ld>> wide;
    for (const vec3<double>& p : points) wide.push_back(vec3<ld>(p));
    const euclidean_bspline<double, K> spline(points, t0, dt);
    const euclidean_bspline<ld, K> wide_spline(wide, static_cast<ld>(t0), static_cast<ld>(dt));
    const std::string order = "K=" + std::to_string(K) + " ";
    test::random_rotations random(3);
    std::vector<double> times;
    for (std::size_t i = 0; i <= points.size() - K + 1; ++i)
        times.push_back(t0 + static_cast<double>(i) * dt);
    for (int n = 0; n < 6; ++n)
        times.push_back(t0 + (std::floor(random.uniform<double>(0, 9.0 - K + 1)) +
                              random.uniform<double>(0.05, 0.95)) *
                                 dt);
    for (const double t : times) {
        INFO(order << "t = " << t);
        std::array<double, K> Jp{}, Jv{}, Ja{}, Jj{};
        const euclidean_bspline_sample<double> s = spline.evaluate(t, &Jp, &Jv, &Ja, &Jj);
        const double u = (t - t0) / dt;
        const bool knot = u == std::floor(u);
        const int side = !knot ? 0 : (t == spline.end_time() ? -1 : 1);
        const ld tl = t, h = 1e-3L * dt;
        const auto at = [&](ld step) { return wide_spline.evaluate(tl + step); };
        // Measured worst: velocity 2.3e-14, acceleration 1.2e-14, jerk 6.4e-15.
        worst.check(order + "velocity",
                    relative_error(column(s.velocity),
                                   test::time_derivative<3>(
                                       [&](ld d) { return arr(at(d).position); }, h, side)));
        worst.check(order + "acceleration",
                    relative_error(column(s.acceleration),
                                   test::time_derivative<3>(
                                       [&](ld d) { return arr(at(d).velocity); }, h, side)));
        if (K >= 5 || !knot)
            worst.check(
                order + "jerk",
                relative_error(column(s.jerk),
                               test::time_derivative<3>(
                                   [&](ld d) { return arr(at(d).acceleration); }, h, side)));
        // The weights: moving point first + m by e moves each output by weight m times e.
        double sum[4] = {0, 0, 0, 0};
        for (std::size_t m = 0; m < K; ++m) {
            std::vector<vec3<ld>> moved = wide;
            moved[s.first + m] = moved[s.first + m] + vec3<ld>{1, 0, 0};
            const euclidean_bspline<ld, K> sp(moved, static_cast<ld>(t0), static_cast<ld>(dt));
            const euclidean_bspline_sample<ld> a = sp.evaluate(tl), b = wide_spline.evaluate(tl);
            const std::array<ld, 4> change = {
                a.position.x - b.position.x, a.velocity.x - b.velocity.x,
                a.acceleration.x - b.acceleration.x, a.jerk.x - b.jerk.x};
            const std::array<double, 4> weight = {Jp[m], Jv[m], Ja[m], Jj[m]};
            for (std::size_t d = 0; d < 4; ++d) {
                const ld scale = std::pow(1.0L / dt, static_cast<ld>(d));
                // The path is linear in its points: the change is the weight up to rounding.
                CHECK(std::abs(change[d] - weight[d]) <= 1e-14L * scale);
                sum[d] += weight[d];
            }
        }
        CHECK(std::abs(sum[0] - 1) <= 4e-16);  // a partition of unity; derivatives sum to 0
        for (int d = 1; d < 4; ++d) CHECK(std::abs(sum[d]) <= 1e-13 / std::pow(dt, d));
        // Jet derivatives with respect to the x components of the K points.
        using jet = ceres::Jet<double, K>;
        std::vector<vec3<jet>> jets;
        for (const vec3<double>& p : points) jets.push_back(vec3<jet>(p));
        for (int m = 0; m < static_cast<int>(K); ++m)
            jets[s.first + static_cast<std::size_t>(m)].x =
                jet(points[s.first + static_cast<std::size_t>(m)].x, m);
        const euclidean_bspline<jet, K> through(jets, jet(t0), jet(dt));
        const euclidean_bspline_sample<jet> d = through.evaluate(jet(t));
        for (int m = 0; m < static_cast<int>(K); ++m) {
            const auto i = static_cast<std::size_t>(m);
            CHECK(d.position.x.v[m] == Approx(Jp[i]).margin(1e-15));
            CHECK(d.velocity.x.v[m] == Approx(Jv[i]).margin(1e-15));
            CHECK(d.acceleration.x.v[m] == Approx(Ja[i]).margin(1e-14));
            CHECK(d.jerk.x.v[m] == Approx(Jj[i]).margin(1e-13));
        }
    }
}

}  // namespace

TEST_CASE(
    "euclidean_bspline: derivatives against long double differences, weights against moved "
    "points and Jet derivatives") {
    check_path<4>(0.25, 0.5);
    check_path<5>(-1.0, 0.75);
    check_path<6>(2.0, 0.3125);
}

TEST_CASE("euclidean_bspline domain: NaN from evaluate, an empty optional from try_evaluate") {
    const std::vector<vec3<double>> points = random_points(6);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const euclidean_bspline<double, 4> spline(points, 0.0, 1.0);  // [0, 3]
    CHECK(spline.end_time() == 3.0);
    CHECK(spline.try_evaluate(3.0).has_value());
    for (const double t : {-0.5, 3.5, nan}) {
        std::array<double, 4> J{};
        CHECK(std::isnan(spline.evaluate(t, &J).position.x));
        CHECK(std::isnan(J[2]));
        CHECK(!spline.try_evaluate(t).has_value());
    }
    CHECK(!euclidean_bspline<double, 4>(points.data(), 3, 0.0, 1.0).valid());
    CHECK(!euclidean_bspline<double, 4>(points, 0.0, 0.0).try_evaluate(0.0).has_value());
    CHECK(std::isnan(euclidean_bspline<double, 4>(points, 0.0, nan)(0.0).y));
    std::vector<vec3<double>> bad = points;
    bad[5].z = nan;
    CHECK(euclidean_bspline<double, 4>(bad, 0.0, 1.0).try_evaluate(1.0).has_value());
    CHECK(!euclidean_bspline<double, 4>(bad, 0.0, 1.0).try_evaluate(2.0).has_value());
}

}  // namespace test_euclidean_bspline
