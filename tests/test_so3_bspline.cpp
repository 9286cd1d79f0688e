// Cumulative B-splines on SO(3) (quat/trajectory/so3_bspline.hpp), for the orders K = 4, 5, 6:
// - the cumulative basis against its closed form (K = 4) and Cox-de Boor's recursion;
// - the angular velocity, acceleration and jerk against long double Richardson differences in time
//   of the library's own long double evaluation (central inside segments, one-sided at knots, where
//   the spline is only C^(K-2));
// - every Jacobian with respect to the K control points against long double central differences of
//   the same evaluation through the right plus and minus, at random times and at every knot, for
//   random control points, control points near the identity, and increments near a half turn;
// - ceres::Jet and tests/support/dual_number.hpp derivatives through the evaluation against the
//   analytic Jacobians;
// - the O(K) recurrences against the O(K^2) product rule (tests/support/bspline_reference.hpp);
// - the domain rules: NaN from evaluate, an empty optional from try_evaluate.
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

#include "support/bspline_reference.hpp"
#include "support/catch.hpp"
#include "support/dual_number.hpp"
#include "support/jacobian_check.hpp"
#include "support/random.hpp"
#include "support/time_differences.hpp"

namespace {

using namespace quat;
using ld = long double;
using quat::test::central_differences;
using quat::test::relative_error;

quat::test::worst_errors worst("so3_bspline");

constexpr double pi = 3.14159265358979323846;

std::array<ld, 3> arr(const vec3<ld>& v) { return {v.x, v.y, v.z}; }
vec3<ld> vec(const std::array<ld, 3>& a) { return {a[0], a[1], a[2]}; }
matrix<double, 3, 1> to_column(const vec3<double>& v) { return {{{v.x}, {v.y}, {v.z}}}; }

/// Control points of one kind, with the name the checks report them by.
struct control_points {
    std::string name;
    std::vector<quaternion<double>> points;
};

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

/// Times to check: every knot from t0 to the end, and random times inside segments (at least dt/20
/// from a knot, so that central differences stay inside one segment).
template <int K>
std::vector<double> check_times(std::size_t count, double t0, double dt) {
    test::random_rotations random(7);
    std::vector<double> times;
    const std::size_t segments = count - K + 1;
    for (std::size_t i = 0; i <= segments; ++i) times.push_back(t0 + static_cast<double>(i) * dt);
    for (int n = 0; n < 6; ++n) {
        const double i = std::floor(random.uniform<double>(0, static_cast<double>(segments)));
        times.push_back(t0 + (i + random.uniform<double>(0.05, 0.95)) * dt);
    }
    return times;
}

/// True when t is a knot of the spline (where one-sided differences are needed).
bool is_knot(double t, double t0, double dt) {
    const double s = (t - t0) / dt;
    return s == std::floor(s);
}

template <int K>
using blocks = std::array<matrix3<double>, K>;

/// The 3 x 3K matrix of K blocks.
template <int K>
matrix<double, 3, 3 * K> joined(const blocks<K>& b) {
    matrix<double, 3, 3 * K> m{};
    for (int k = 0; k < K; ++k) set_block(m, 0, 3 * k, b[static_cast<std::size_t>(k)]);
    return m;
}

template <int K>
void check_against_differences(const control_points& set, double t0, double dt) {
    const std::vector<quaternion<double>>& points = set.points;
    std::vector<quaternion<ld>> wide;
    for (const quaternion<double>& q : points) wide.push_back(quaternion<ld>(q));
    const so3_bspline<double, K> spline(points, t0, dt);
    const std::string order = "K=" + std::to_string(K) + " " + set.name + " ";
    for (const double t : check_times<K>(points.size(), t0, dt)) {
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
            [&](ld step) { return arr(so3::minus(at(wide_spline, tl + step).rotation, base.rotation)); },
            h, side);
        const auto acceleration = test::time_derivative<3>(
            [&](ld step) { return arr(at(wide_spline, tl + step).angular_velocity); }, h, side);
        const auto jerk = test::time_derivative<3>(
            [&](ld step) { return arr(at(wide_spline, tl + step).angular_acceleration); }, h, side);
        worst.check(order + "angular velocity", relative_error(to_column(s.angular_velocity), velocity));
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
                [&](const std::array<ld, 3>& d) { return arr(so3::minus(perturbed(d).rotation, base.rotation)); },
                step);
            const auto jw = central_differences<3, 3>(
                [&](const std::array<ld, 3>& d) { return arr(perturbed(d).angular_velocity); }, step);
            const auto ja = central_differences<3, 3>(
                [&](const std::array<ld, 3>& d) { return arr(perturbed(d).angular_acceleration); }, step);
            const auto jj = central_differences<3, 3>(
                [&](const std::array<ld, 3>& d) { return arr(perturbed(d).angular_jerk); }, step);
            const int c = 3 * static_cast<int>(m);
            set_block(rq, 0, c, jq);
            set_block(rw, 0, c, jw);
            set_block(ra, 0, c, ja);
            set_block(rj, 0, c, jj);
        }
        worst.check(order + "J rotation / points", relative_error(joined<K>(Jq), rq));
        worst.check(order + "J angular velocity / points", relative_error(joined<K>(Jw), rw));
        worst.check(order + "J angular acceleration / points", relative_error(joined<K>(Ja), ra));
        worst.check(order + "J angular jerk / points", relative_error(joined<K>(Jj), rj));
    }
}

}  // namespace

TEST_CASE("so3_bspline's cumulative basis: the closed form for K = 4 and Cox-de Boor for K = 4, 5, 6") {
    constexpr auto table = detail::cumulative_basis_table<4>();
    static_assert(table[0][0][0] == 6 && table[0][0][1] == 0 && table[0][0][3] == 0);
    static_assert(table[0][1][0] == 5 && table[0][1][1] == 3 && table[0][1][2] == -3 &&
                  table[0][1][3] == 1);
    static_assert(table[0][2][0] == 1 && table[0][2][1] == 3 && table[0][2][2] == 3 &&
                  table[0][2][3] == -2);
    static_assert(table[0][3][3] == 1 && table[1][3][2] == 3 && table[3][3][0] == 6);
    const auto cox_de_boor = [](int k, int s, ld x) {  // B-spline s of order k, knots 0, 1, 2, ...
        std::vector<ld> b(static_cast<std::size_t>(s + k), 0);
        for (int i = 0; i < s + k; ++i) b[static_cast<std::size_t>(i)] = (i <= x && x < i + 1) ? 1 : 0;
        for (int o = 2; o <= k; ++o)
            for (int i = 0; i + o <= s + k; ++i) {
                const auto u = static_cast<std::size_t>(i);
                b[u] = (x - i) / (o - 1) * b[u] + (i + o - x) / (o - 1) * b[u + 1];
            }
        return b[static_cast<std::size_t>(s)];
    };
    const auto check = [&](auto order) {
        constexpr int K = decltype(order)::value;
        for (const ld u : {0.0L, 0.125L, 0.5L, 0.75L, 0.999L}) {
            const auto w = detail::cumulative_weights_at<ld, K>(u, 1.0L);
            for (int j = 0; j < K; ++j) {
                // b~_j(u) = sum of the B-splines s >= j over the segment [K-1, K) of control points 0..K-1.
                ld expected = 0;
                for (int s = j; s < K; ++s) expected += cox_de_boor(K, s, K - 1 + u);
                CHECK(std::abs(w.b[0][static_cast<std::size_t>(j)] - expected) <= 1e-18L);
            }
        }
    };
    check(std::integral_constant<int, 4>{});
    check(std::integral_constant<int, 5>{});
    check(std::integral_constant<int, 6>{});
}

TEST_CASE("so3_bspline: angular velocity, acceleration, jerk and every Jacobian against long double "
          "differences, at random times and knots, near the identity and near half turns") {
    for (const control_points& set : point_sets(9)) {
        check_against_differences<4>(set, 0.25, 0.5);
        check_against_differences<5>(set, -1.0, 0.75);
        check_against_differences<6>(set, 2.0, 0.3125);  // knots exact in binary
    }
}
