// Cumulative B-splines on SO(3) (quat/trajectory/so3_bspline.hpp): the rates and the Jacobians,
// for the orders K = 4, 5, 6:
// - the angular velocity, acceleration and jerk against long double Richardson differences in time
//   of the library's own long double evaluation (central inside segments, one-sided at knots, where
//   the spline is only C^(K-2));
// - every Jacobian with respect to the K control points against long double central differences of
//   the same evaluation through the right plus and minus, at random times and at every knot, for
//   random control points, control points near the identity, and increments near a half turn;
// - ceres::Jet and tests/support/dual_number.hpp derivatives through the evaluation against the
//   analytic Jacobians, and a Jet time against the rates;
// - the O(K) recurrences against the O(K^2) product rule (tests/support/bspline_reference.hpp).
// The basis, the domain rules and the interface are in tests/test_so3_bspline.cpp.
// QUAT_LIE_REPORT=1 in the environment prints the worst error of every check.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <ceres/jet.h>
#include <quat/lie/so3.hpp>
#include <quat/quat.hpp>
#include <quat/trajectory/so3_bspline.hpp>

#include "support/bspline_checks.hpp"
#include "support/bspline_reference.hpp"
#include "support/catch.hpp"
#include "support/jacobian_check.hpp"
#include "support/random.hpp"
#include "support/time_differences.hpp"

namespace test_so3_bspline_derivatives {

namespace {

using namespace quat;
using ld = long double;
using quat::test::central_differences;
using quat::test::check_times;
using quat::test::is_knot;
using quat::test::joined;
using quat::test::relative_error;
using control_points = quat::test::control_points<quaternion<double>>;
template <std::size_t K>
using blocks = quat::test::blocks<3, K>;

quat::test::worst_errors worst("so3_bspline");

constexpr double pi = 3.14159265358979323846;

vec3<ld> vec(const std::array<ld, 3>& a) { return {a[0], a[1], a[2]}; }
matrix<double, 3, 1> to_column(const vec3<double>& v) { return {{{v.x}, {v.y}, {v.z}}}; }

/// Random steps up to 1 rad with random signs; steps below 1e-7 rad; steps of pi - 1e-2 rad.
std::vector<control_points> point_sets(std::size_t count) {
    test::random_rotations random;
    std::vector<control_points> sets;
    sets.push_back({"random", test::random_walk<double>(random, count, 1.0)});
    std::vector<quaternion<double>> near_identity, near_half_turn;
    for (std::size_t i = 0; i < count; ++i) {
        const vec3<double> small = random.unit_vector<double>() * random.uniform<double>(0, 1e-7);
        near_identity.push_back(from_rotation_vector(small));
    }
    near_half_turn.push_back(random.unit_quaternion<double>());
    while (near_half_turn.size() < count) {
        const vec3<double> step = random.unit_vector<double>() * (pi - 1e-2);
        near_half_turn.push_back(normalize(near_half_turn.back() * from_rotation_vector(step)));
    }
    sets.push_back({"near identity", near_identity});
    sets.push_back({"near half turn", near_half_turn});
    return sets;
}

template <std::size_t K>
void check_against_differences(const control_points& set, double t0, double dt) {
    const std::vector<quaternion<double>>& points = set.points;
    const std::vector<quaternion<ld>> wide = test::widened(points);
    const so3_bspline<double, K> spline(points, t0, dt);
    const std::string order = "K=" + std::to_string(K) + " " + set.name + " ";
    for (const double t : check_times<K>(points.size(), t0, dt, 6)) {
        INFO(order << "t = " << t);
        blocks<K> Jq{}, Jw{}, Ja{}, Jj{};
        const so3_bspline_sample<double> s = spline.evaluate(t, &Jq, &Jw, &Ja, &Jj);
        REQUIRE(s.first + K <= points.size());
        const so3_bspline<ld, K> wide_spline(wide, static_cast<ld>(t0), static_cast<ld>(dt));
        const ld tl = t;
        const auto at = [&](const so3_bspline<ld, K>& sp, ld time) { return sp.evaluate(time); };
        const so3_bspline_sample<ld> base = at(wide_spline, tl);

        // Time derivatives: one-sided at knots (backwards at the end, forwards elsewhere).
        const bool knot = is_knot(t, t0, dt);
        const int side = !knot ? 0 : (t == spline.end_time() ? -1 : 1);
        const ld h = 1e-3L * dt;
        const auto velocity = test::time_derivative<3>(
            [&](ld step) {
                return test::components(
                    so3::minus(at(wide_spline, tl + step).rotation, base.rotation));
            },
            h, side);
        const auto acceleration = test::time_derivative<3>(
            [&](ld step) { return test::components(at(wide_spline, tl + step).angular_velocity); },
            h, side);
        const auto jerk = test::time_derivative<3>(
            [&](ld step) {
                return test::components(at(wide_spline, tl + step).angular_acceleration);
            },
            h, side);
        // Measured worst over the orders and point sets: velocity 1.9e-13, acceleration 4.3e-14,
        // jerk 3.1e-14 (the one-sided differences at knots are the least accurate references).
        worst.check(order + "angular velocity",
                    relative_error(to_column(s.angular_velocity), velocity));
        worst.check(order + "angular acceleration",
                    relative_error(to_column(s.angular_acceleration), acceleration));
        if (K >= 5 || !knot)  // K = 4: the jerk jumps at knots
            worst.check(order + "angular jerk", relative_error(to_column(s.angular_jerk), jerk));

        // Jacobians: perturb point first + m by exp(delta) on the right.
        matrix<ld, 3, 3 * K> rq{}, rw{}, ra{}, rj{};
        for (std::size_t m = 0; m < K; ++m) {
            const auto perturbed = [&](const std::array<ld, 3>& delta) {
                std::vector<quaternion<ld>> moved = wide;
                moved[s.first + m] = moved[s.first + m] * so3::exp(vec(delta));
                const so3_bspline<ld, K> sp(moved, static_cast<ld>(t0), static_cast<ld>(dt));
                return sp.evaluate(tl);
            };
            const ld step = 1e-3L;
            const auto jq = central_differences<3, 3>(
                [&](const std::array<ld, 3>& d) {
                    return test::components(so3::minus(perturbed(d).rotation, base.rotation));
                },
                step);
            const auto jw = central_differences<3, 3>(
                [&](const std::array<ld, 3>& d) {
                    return test::components(perturbed(d).angular_velocity);
                },
                step);
            const auto ja = central_differences<3, 3>(
                [&](const std::array<ld, 3>& d) {
                    return test::components(perturbed(d).angular_acceleration);
                },
                step);
            const auto jj = central_differences<3, 3>(
                [&](const std::array<ld, 3>& d) {
                    return test::components(perturbed(d).angular_jerk);
                },
                step);
            const int c = 3 * static_cast<int>(m);
            set_block(rq, 0, c, jq);
            set_block(rw, 0, c, jw);
            set_block(ra, 0, c, ja);
            set_block(rj, 0, c, jj);
        }
        // Measured worst: rotation 4.2e-15, velocity 2.3e-15, acceleration 2.5e-15, jerk 2.5e-15.
        worst.check(order + "J rotation / points", relative_error(joined(Jq), rq));
        worst.check(order + "J angular velocity / points", relative_error(joined(Jw), rw));
        worst.check(order + "J angular acceleration / points", relative_error(joined(Ja), ra));
        worst.check(order + "J angular jerk / points", relative_error(joined(Jj), rj));
    }
}

}  // namespace

TEST_CASE(
    "so3_bspline: angular velocity, acceleration, jerk and every Jacobian against long double "
    "differences, at random times and knots, near the identity and near half turns",
    "[sweep]") {
    for (const control_points& set : point_sets(9)) {
        check_against_differences<4>(set, 0.25, 0.5);
        check_against_differences<5>(set, -1.0, 0.75);
        check_against_differences<6>(set, 2.0, 0.3125);  // knots exact in binary
    }
}

namespace {

using quat::test::jet;
using quat::test::max_relative;
using quat::test::partials;
template <std::size_t N>
using dual = test::dual<double, N>;

/// Forward-mode derivatives (S with 3K partials) through evaluate, each point first + m moved by
/// q (1, delta_m / 2), the first-order right plus, against the analytic Jacobians.
template <std::size_t K, class S>
void check_autodiff(const control_points& set, double t0, double dt, const std::string& scalar) {
    const std::vector<quaternion<double>>& points = set.points;
    const so3_bspline<double, K> spline(points, t0, dt);
    const std::string order = scalar + " K=" + std::to_string(K) + " " + set.name + " ";
    for (const double t : check_times<K>(points.size(), t0, dt, 6)) {
        INFO(order << "t = " << t);
        blocks<K> Jq{}, Jw{}, Ja{}, Jj{};
        const so3_bspline_sample<double> s = spline.evaluate(t, &Jq, &Jw, &Ja, &Jj);
        std::vector<quaternion<S>> moved;
        for (const quaternion<double>& q : points) moved.push_back(quaternion<S>(q));
        for (int m = 0; m < static_cast<int>(K); ++m) {
            quaternion<S>& q = moved[s.first + static_cast<std::size_t>(m)];
            const S half(0.5), one(1);
            q = q * quaternion<S>{one, test::variable(3 * m, (S*)nullptr) * half,
                                  test::variable(3 * m + 1, (S*)nullptr) * half,
                                  test::variable(3 * m + 2, (S*)nullptr) * half};
        }
        const so3_bspline<S, K> through(moved, S(t0), S(dt));
        const so3_bspline_sample<S> d = through.evaluate(S(t));
        const quaternion<S> value = test::value_part(d.rotation);
        const quaternion<S> local =
            conjugate(value) * d.rotation;  // (1, tangent / 2) to first order
        const vec3<S> tangent{local.x * S(2), local.y * S(2), local.z * S(2)};
        // Measured worst over both scalars: rotation 1.5e-15, velocity 1.3e-15, acceleration 1.6e-15,
        // jerk 2.3e-15.
        worst.check(order + "autodiff J rotation",
                    max_relative(joined(Jq), partials<3 * K>(tangent)), 1e-13);
        worst.check(order + "autodiff J angular velocity",
                    max_relative(joined(Jw), partials<3 * K>(d.angular_velocity)), 1e-13);
        worst.check(order + "autodiff J angular acceleration",
                    max_relative(joined(Ja), partials<3 * K>(d.angular_acceleration)), 1e-13);
        worst.check(order + "autodiff J angular jerk",
                    max_relative(joined(Jj), partials<3 * K>(d.angular_jerk)), 1e-13);
    }
}

}  // namespace

TEST_CASE(
    "so3_bspline: ceres::Jet and dual-number derivatives through evaluate equal the analytic "
    "Jacobians") {
    for (const control_points& set : point_sets(9)) {
        check_autodiff<4, jet<12>>(set, 0.25, 0.5, "Jet");
        check_autodiff<5, jet<15>>(set, -1.0, 0.75, "Jet");
        check_autodiff<6, jet<18>>(set, 2.0, 0.3125, "Jet");
        check_autodiff<4, dual<12>>(set, 0.25, 0.5, "dual");
        check_autodiff<6, dual<18>>(set, 2.0, 0.3125, "dual");
    }
}

TEST_CASE(
    "so3_bspline: a Jet time gives the angular velocity, acceleration and jerk as derivatives") {
    const std::vector<quaternion<double>> points = point_sets(8)[0].points;
    const so3_bspline<double, 5> spline(points, 0.0, 0.5);
    std::vector<quaternion<jet<1>>> wide;
    for (const quaternion<double>& q : points) wide.push_back(quaternion<jet<1>>(q));
    const so3_bspline<jet<1>, 5> through(wide, jet<1>(0.0), jet<1>(0.5));
    for (const double t : {0.0, 0.3, 0.5, 1.1, 2.0}) {
        INFO("t = " << t);
        const so3_bspline_sample<double> s = spline.evaluate(t);
        const so3_bspline_sample<jet<1>> d = through.evaluate(jet<1>(t, 0));
        const quaternion<jet<1>> value = test::value_part(d.rotation);
        const quaternion<jet<1>> local = conjugate(value) * d.rotation;
        const vec3<jet<1>> w{local.x * 2.0, local.y * 2.0, local.z * 2.0};
        const auto column = [](const vec3<double>& v) { return to_column(v); };
        // Measured worst: velocity 6.0e-16, acceleration 3.6e-16, jerk 6.7e-16.
        worst.check("Jet time: angular velocity",
                    max_relative(partials<1>(w), column(s.angular_velocity)), 1e-14);
        worst.check("Jet time: angular acceleration",
                    max_relative(partials<1>(d.angular_velocity), column(s.angular_acceleration)),
                    1e-14);
        worst.check("Jet time: angular jerk",
                    max_relative(partials<1>(d.angular_acceleration), column(s.angular_jerk)),
                    1e-14);
    }
}

namespace {

/// The O(K) evaluation in double against the O(K^2) product rule in long double at the same u.
template <std::size_t K>
void check_against_textbook(const control_points& set, double t0, double dt) {
    const std::vector<quaternion<double>>& points = set.points;
    const std::vector<quaternion<ld>> wide = test::widened(points);
    const so3_bspline<double, K> spline(points, t0, dt);
    const std::string order = "K=" + std::to_string(K) + " " + set.name + " ";
    constexpr double eps = std::numeric_limits<double>::epsilon();
    for (const double t : check_times<K>(points.size(), t0, dt, 6)) {
        INFO(order << "t = " << t);
        const so3_bspline_sample<double> s = spline.evaluate(t);
        const detail::knot_position<double> at =
            detail::spline_position<K>(t, t0, dt, points.size());
        const auto r = test::textbook_bspline<test::so3_reference<ld>, ld, K>(
            wide.data() + at.segment,
            detail::cumulative_weights_at<ld, K>(static_cast<ld>(at.u), static_cast<ld>(dt)));
        const auto relative = [](const vec3<double>& got, const vec3<ld>& want) {
            const ld scale = std::max({std::abs(want.x), std::abs(want.y), std::abs(want.z)});
            const vec3<ld> e = vec3<ld>(got) - want;
            const ld error = std::max({std::abs(e.x), std::abs(e.y), std::abs(e.z)});
            return static_cast<double>(scale > 0 ? error / scale : error);
        };
        const double angle =
            static_cast<double>(norm(so3::minus(quaternion<ld>(s.rotation), r.value)));
        // Measured worst, in double epsilons: rotation 5.3, velocity 3.8, acceleration 4.7, jerk 4.3.
        worst.check(order + "textbook rotation (eps)", angle / eps, 8);
        worst.check(order + "textbook angular velocity (eps)",
                    relative(s.angular_velocity, r.velocity) / eps, 8);
        worst.check(order + "textbook angular acceleration (eps)",
                    relative(s.angular_acceleration, r.acceleration) / eps, 8);
        worst.check(order + "textbook angular jerk (eps)", relative(s.angular_jerk, r.jerk) / eps,
                    8);
    }
}

}  // namespace

TEST_CASE("so3_bspline: the O(K) recurrences agree with the O(K^2) product rule within 8 epsilon") {
    for (const control_points& set : point_sets(9)) {
        check_against_textbook<4>(set, 0.25, 0.5);
        check_against_textbook<5>(set, -1.0, 0.75);
        check_against_textbook<6>(set, 2.0, 0.3125);
    }
}

}  // namespace test_so3_bspline_derivatives
