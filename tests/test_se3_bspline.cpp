// Cumulative B-splines on SE(3) (quat/trajectory/se3_bspline.hpp), for the orders K = 4, 5, 6, as
// tests/test_so3_bspline.cpp and tests/test_so3_bspline_derivatives.cpp check SO(3): the body
// twist and its two derivatives against long double Richardson differences in time of the
// library's own long double evaluation (one-sided at knots), every Jacobian with respect to the K
// control motions against long double central differences through se3's right plus and minus, at
// random times and every knot, for random motions, motions near the identity and rotation
// increments near a half turn; ceres::Jet and dual-number derivatives through the evaluation; the
// O(K) recurrences against the O(K^2) product rule in dual quaternions; the domain rules.
// QUAT_LIE_REPORT=1 prints the worst error of every check.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <ceres/jet.h>
#include <quat/lie/se3.hpp>
#include <quat/quat.hpp>
#include <quat/trajectory/se3_bspline.hpp>

#include "support/bspline_checks.hpp"
#include "support/bspline_reference.hpp"
#include "support/catch.hpp"
#include "support/jacobian_check.hpp"
#include "support/random.hpp"
#include "support/time_differences.hpp"

namespace test_se3_bspline {

namespace {

using namespace quat;
using ld = long double;
template <class T>
using dq = dual_quaternion<T>;
template <class T>
using twist = se3::twist<T>;
using quat::test::central_differences;
using quat::test::check_times;
using quat::test::is_knot;
using quat::test::joined;
using quat::test::relative_error;
using control_points = quat::test::control_points<dq<double>>;
template <std::size_t K>
using blocks = quat::test::blocks<6, K>;

quat::test::worst_errors worst("se3_bspline");

constexpr double pi = 3.14159265358979323846;

using arr6 = std::array<ld, 6>;
twist<ld> tw(const arr6& a) { return {{a[0], a[1], a[2]}, {a[3], a[4], a[5]}}; }
matrix<double, 6, 1> column(const twist<double>& t) { return se3::to_vector(t); }

/// X_(i+1) = X_i exp(step): rotation steps up to 1 rad and translation steps of about 1 with random
/// signs; steps below 1e-7 from the identity; rotation steps of pi - 1e-2 rad.
std::vector<control_points> point_sets(std::size_t count) {
    test::random_rotations random;
    std::vector<control_points> sets;
    const auto walk = [&](double low, double high, double reach, bool from_identity = false) {
        std::vector<dq<double>> points{from_identity ? dq<double>::identity()
                                                     : random.rigid_motion<double>()};
        while (points.size() < count) {
            const vec3<double> axis = random.unit_vector<double>();
            const double angle = random.uniform<double>(low, high);
            const vec3<double> linear = random.vector<double>(reach);
            points.push_back(
                normalize(points.back() * se3::exp(twist<double>{linear, axis * angle})));
        }
        for (dq<double>& x : points)
            if (random.uniform<double>(0, 1) < 0.5) x = -x;
        return points;
    };
    sets.push_back({"random", walk(0.0, 1.0, 1.0)});
    sets.push_back({"near identity", walk(0.0, 1e-7, 1e-7, true)});
    sets.push_back({"near half turn", walk(pi - 1e-2, pi - 1e-2, 1.0)});
    return sets;
}

template <std::size_t K>
void check_against_differences(const control_points& set, double t0, double dt) {
    const std::vector<dq<double>>& points = set.points;
    const std::vector<dq<ld>> wide = test::widened(points);
    const se3_bspline<double, K> spline(points, t0, dt);
    const se3_bspline<ld, K> wide_spline(wide, static_cast<ld>(t0), static_cast<ld>(dt));
    const std::string order = "K=" + std::to_string(K) + " " + set.name + " ";
    for (const double t : check_times<K>(points.size(), t0, dt, 4)) {
        INFO(order << "t = " << t);
        blocks<K> Jx{}, Jv{}, Ja{}, Jj{};
        const se3_bspline_sample<double> s = spline.evaluate(t, &Jx, &Jv, &Ja, &Jj);
        REQUIRE(s.first + K <= points.size());
        const ld tl = t;
        const se3_bspline_sample<ld> base = wide_spline.evaluate(tl);
        const bool knot = is_knot(t, t0, dt);
        const int side = !knot ? 0 : (t == spline.end_time() ? -1 : 1);
        const ld h = 1e-3L * dt;
        const auto at = [&](ld step) { return wide_spline.evaluate(tl + step); };
        const auto velocity = test::time_derivative<6>(
            [&](ld step) { return test::components(se3::minus(at(step).motion, base.motion)); }, h,
            side);
        const auto acceleration = test::time_derivative<6>(
            [&](ld step) { return test::components(at(step).velocity); }, h, side);
        const auto jerk = test::time_derivative<6>(
            [&](ld step) { return test::components(at(step).acceleration); }, h, side);
        // Measured worst over the orders and point sets: twist 2.0e-13, derivative 4.0e-14, second
        // derivative 9.3e-15.
        worst.check(order + "twist", relative_error(column(s.velocity), velocity));
        worst.check(order + "twist derivative",
                    relative_error(column(s.acceleration), acceleration));
        if (K >= 5 || !knot)
            worst.check(order + "twist second derivative", relative_error(column(s.jerk), jerk));

        matrix<ld, 6, 6 * K> rx{}, rv{}, ra{}, rj{};
        for (std::size_t m = 0; m < K; ++m) {
            const auto perturbed = [&](const arr6& delta) {
                std::vector<dq<ld>> moved = wide;
                moved[s.first + m] = moved[s.first + m] * se3::exp(tw(delta));
                const se3_bspline<ld, K> sp(moved, static_cast<ld>(t0), static_cast<ld>(dt));
                return sp.evaluate(tl);
            };
            const ld step = 1e-3L;
            const int c = 6 * static_cast<int>(m);
            set_block(rx, 0, c,
                      central_differences<6, 6>(
                          [&](const arr6& d) {
                              return test::components(se3::minus(perturbed(d).motion, base.motion));
                          },
                          step));
            set_block(
                rv, 0, c,
                central_differences<6, 6>(
                    [&](const arr6& d) { return test::components(perturbed(d).velocity); }, step));
            set_block(
                ra, 0, c,
                central_differences<6, 6>(
                    [&](const arr6& d) { return test::components(perturbed(d).acceleration); },
                    step));
            set_block(
                rj, 0, c,
                central_differences<6, 6>(
                    [&](const arr6& d) { return test::components(perturbed(d).jerk); }, step));
        }
        // Measured worst: motion 1.2e-14, twist 4.2e-15, derivative 3.2e-15, second 4.2e-15.
        worst.check(order + "J motion / points", relative_error(joined(Jx), rx));
        worst.check(order + "J twist / points", relative_error(joined(Jv), rv));
        worst.check(order + "J twist derivative / points", relative_error(joined(Ja), ra));
        worst.check(order + "J twist second derivative / points", relative_error(joined(Jj), rj));
    }
}

}  // namespace

TEST_CASE(
    "se3_bspline: the body twist, its derivatives and every Jacobian against long double "
    "differences, at random times and knots, near the identity and near half turns",
    "[sweep]") {
    for (const control_points& set : point_sets(8)) {
        check_against_differences<4>(set, 0.25, 0.5);
        check_against_differences<5>(set, -1.0, 0.75);
        check_against_differences<6>(set, 2.0, 0.3125);
    }
}

namespace {

using quat::test::jet;
using quat::test::max_relative;
using quat::test::partials;
template <std::size_t N>
using dual = test::dual<double, N>;

/// Forward-mode derivatives (6K partials) through evaluate, point first + m moved by the first-order
/// right plus X ((1, omega / 2) + eps (0, rho / 2)), against the analytic Jacobians.
template <std::size_t K, class S>
void check_autodiff(const control_points& set, double t0, double dt, const std::string& scalar) {
    const std::vector<dq<double>>& points = set.points;
    const se3_bspline<double, K> spline(points, t0, dt);
    const std::string order = scalar + " K=" + std::to_string(K) + " " + set.name + " ";
    for (const double t : check_times<K>(points.size(), t0, dt, 4)) {
        INFO(order << "t = " << t);
        blocks<K> Jx{}, Jv{}, Ja{}, Jj{};
        const se3_bspline_sample<double> s = spline.evaluate(t, &Jx, &Jv, &Ja, &Jj);
        std::vector<dq<S>> moved;
        for (const dq<double>& x : points) moved.push_back(dq<S>(x));
        for (int m = 0; m < static_cast<int>(K); ++m) {
            dq<S>& x = moved[s.first + static_cast<std::size_t>(m)];
            const S half(0.5), zero(0), one(1);
            S v[6];
            for (int i = 0; i < 6; ++i) v[i] = test::variable(6 * m + i, (S*)nullptr) * half;
            x = x * dq<S>{{one, v[3], v[4], v[5]}, {zero, v[0], v[1], v[2]}};
        }
        const se3_bspline<S, K> through(moved, S(t0), S(dt));
        const se3_bspline_sample<S> d = through.evaluate(S(t));
        const dq<S> value{test::value_part(d.motion.real), test::value_part(d.motion.dual)};
        const dq<S> local = dq<S>{conjugate(value.real), conjugate(value.dual)} * d.motion;
        const S two(2);
        const twist<S> tangent{{local.dual.x * two, local.dual.y * two, local.dual.z * two},
                               {local.real.x * two, local.real.y * two, local.real.z * two}};
        // Measured worst over both scalars: motion 3.6e-15, twist 3.0e-15, derivative 1.2e-15,
        // second derivative 3.0e-15.
        worst.check(order + "autodiff J motion", max_relative(joined(Jx), partials<6 * K>(tangent)),
                    1e-13);
        worst.check(order + "autodiff J twist",
                    max_relative(joined(Jv), partials<6 * K>(d.velocity)), 1e-13);
        worst.check(order + "autodiff J twist derivative",
                    max_relative(joined(Ja), partials<6 * K>(d.acceleration)), 1e-13);
        worst.check(order + "autodiff J twist second derivative",
                    max_relative(joined(Jj), partials<6 * K>(d.jerk)), 1e-13);
    }
}

template <std::size_t K>
void check_against_textbook(const control_points& set, double t0, double dt) {
    const std::vector<dq<double>>& points = set.points;
    const std::vector<dq<ld>> wide = test::widened(points);
    const se3_bspline<double, K> spline(points, t0, dt);
    const std::string order = "K=" + std::to_string(K) + " " + set.name + " ";
    constexpr double eps = std::numeric_limits<double>::epsilon();
    for (const double t : check_times<K>(points.size(), t0, dt, 4)) {
        INFO(order << "t = " << t);
        const se3_bspline_sample<double> s = spline.evaluate(t);
        const detail::knot_position<double> at =
            detail::spline_position<K>(t, t0, dt, points.size());
        const auto r = test::textbook_bspline<test::se3_reference<ld>, ld, K>(
            wide.data() + at.segment,
            detail::cumulative_weights_at<ld, K>(static_cast<ld>(at.u), static_cast<ld>(dt)));
        const auto relative = [](const twist<double>& got, const twist<ld>& want) {
            const arr6 g = test::components(twist<ld>{vec3<ld>(got.linear), vec3<ld>(got.angular)}),
                       w = test::components(want);
            ld error = 0, scale = 0;
            for (std::size_t i = 0; i < 6; ++i) {
                error = std::max(error, std::abs(g[i] - w[i]));
                scale = std::max(scale, std::abs(w[i]));
            }
            return static_cast<double>(scale > 0 ? error / scale : error);
        };
        const arr6 e = test::components(se3::minus(dq<ld>(s.motion), r.value));
        const ld reach = std::max<ld>(1, norm(translation_of(r.value)));
        ld motion_error = 0;
        for (const ld c : e) motion_error = std::max(motion_error, std::abs(c));
        // Measured worst, in double epsilons (the motion's translation relative to max(1, |p|)):
        // motion 1.9, twist 5.2, derivative 5.3, second derivative 5.9.
        worst.check(order + "textbook motion (eps)",
                    static_cast<double>(motion_error / reach) / eps, 8);
        worst.check(order + "textbook twist (eps)", relative(s.velocity, r.velocity) / eps, 8);
        worst.check(order + "textbook twist derivative (eps)",
                    relative(s.acceleration, r.acceleration) / eps, 8);
        worst.check(order + "textbook twist second derivative (eps)",
                    relative(s.jerk, r.jerk) / eps, 8);
    }
}

}  // namespace

TEST_CASE(
    "se3_bspline: ceres::Jet and dual-number derivatives through evaluate equal the analytic "
    "Jacobians") {
    for (const control_points& set : point_sets(8)) {
        check_autodiff<4, jet<24>>(set, 0.25, 0.5, "Jet");
        check_autodiff<5, jet<30>>(set, -1.0, 0.75, "Jet");
        check_autodiff<6, jet<36>>(set, 2.0, 0.3125, "Jet");
        check_autodiff<4, dual<24>>(set, 0.25, 0.5, "dual");
    }
}

TEST_CASE("se3_bspline: the O(K) recurrences agree with the O(K^2) product rule within 8 epsilon") {
    for (const control_points& set : point_sets(8)) {
        check_against_textbook<4>(set, 0.25, 0.5);
        check_against_textbook<5>(set, -1.0, 0.75);
        check_against_textbook<6>(set, 2.0, 0.3125);
    }
}

TEST_CASE(
    "se3_bspline domain: NaN from evaluate and an empty optional from try_evaluate outside "
    "[t0, t0 + (count - K + 1) dt] and for views that cannot be evaluated") {
    const std::vector<dq<double>> points = point_sets(6)[0].points;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const auto is_nan_sample = [](const se3_bspline_sample<double>& s) {
        return s.first == 0 && std::isnan(s.motion.real.w) && std::isnan(s.motion.dual.z) &&
               std::isnan(s.velocity.linear.x) && std::isnan(s.acceleration.angular.y) &&
               std::isnan(s.jerk.angular.z);
    };
    const se3_bspline<double, 5> spline(points, 0.0, 0.25);  // 6 points: 2 segments, [0, 0.5]
    CHECK(spline.end_time() == 0.5);
    for (const double t : {0.0, 0.25, 0.5}) CHECK(spline.try_evaluate(t).has_value());
    for (const double t : {-1e-300, std::nextafter(0.5, 1.0), inf, nan}) {
        blocks<5> J{};
        CHECK(is_nan_sample(spline.evaluate(t, nullptr, &J)));
        CHECK(std::isnan(J[4](5, 5)));
        CHECK(!spline.try_evaluate(t).has_value());
        CHECK(std::isnan(spline(t).real.w));
    }
    for (const se3_bspline<double, 5>& s :
         {se3_bspline<double, 5>(points.data(), 4, 0.0, 0.25),
          se3_bspline<double, 5>(points, 0.0, 0.0), se3_bspline<double, 5>(points, 0.0, -1.0),
          se3_bspline<double, 5>(points, inf, 0.25), se3_bspline<double, 5>(points, 0.0, nan),
          se3_bspline<double, 5>(nullptr, 6, 0.0, 0.25)}) {
        CHECK(!s.valid());
        CHECK(is_nan_sample(s.evaluate(0.1)));
        CHECK(!s.try_evaluate(0.1).has_value());
    }
    static_assert(noexcept(spline.evaluate(0.0))&& noexcept(spline.try_evaluate(0.0)));
    static_assert(std::is_trivially_copyable_v<se3_bspline<double, 5>>);
}

}  // namespace test_se3_bspline
