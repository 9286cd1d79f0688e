// The B-spline rows of `quat_accuracy --trajectory`: so3_bspline and se3_bspline of orders K = 4, 5,
// 6 in double, as tests/test_so3_bspline_derivatives.cpp and tests/test_se3_bspline.cpp check them,
// with the worst error recorded instead of checked:
// - the body velocity and its two derivatives against long double Richardson differences in time
//   of the library's own long double evaluation (one-sided at knots, where the spline is only
//   C^(K-2); the jerk of K = 4 jumps there and is not compared);
// - the Jacobians of the value and of the three rates with respect to the K control points against
//   long double central differences over right perturbations x_m exp(delta);
// - forward-mode derivatives (tests/support/dual_number.hpp) through the double evaluation against
//   the same analytic Jacobians;
// - the O(K) recurrences against the O(K^2) product rule in long double
//   (tests/support/bspline_reference.hpp), in double epsilons.
// Sample classes: random control points at random times inside segments and at every knot, control
// points near the identity and increments near a half turn (pi - 1e-2 rad) at both kinds of time.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include <quat/lie/se3.hpp>
#include <quat/lie/so3.hpp>
#include <quat/trajectory/se3_bspline.hpp>
#include <quat/trajectory/so3_bspline.hpp>

#include "support/bspline_reference.hpp"
#include "support/dual_number.hpp"
#include "support/random.hpp"
#include "trajectory_differences.hpp"
#include "trajectory_kinds.hpp"

namespace accuracy {
namespace trajectory {

// The bounds: rates and Jacobians within 1e-12 of the largest entry of their long double
// differences, forward-mode derivatives within 1e-13 of the analytic Jacobians, the recurrences
// within 8 eps of the product rule.
constexpr double bound_differences = 1e-12;
constexpr double bound_autodiff = 1e-13;
constexpr double bound_textbook = 8;

/// The rows of one spline kind: 3 rates, 4 Jacobians, 4 forward-mode Jacobians, 4 recurrences in
/// double against the product rule in long double, and the same 4 with both in long double (at
/// the long double u of the time), without a bound: how far the two formulations part with
/// double's roundings out of the way, in long double's epsilon.
template <class Kind>
std::vector<measured_row> bspline_table() {
    const std::string value = Kind::value_name;
    std::vector<measured_row> rows;
    const auto add = [&](const std::string& quantity, const char* unit, double bound) {
        rows.push_back({Kind::name, quantity, unit, bound,
                        std::vector<std::array<worst_error, class_count>>(3)});
    };
    for (const char* r : Kind::rate_names)
        add(std::string(r) + " vs time differences", "relative", bound_differences);
    std::vector<std::string> outputs{value};
    for (const char* r : Kind::rate_names) outputs.emplace_back(r);
    for (const std::string& o : outputs)
        add("∂" + o + "/∂points vs differences", "relative", bound_differences);
    for (const std::string& o : outputs)
        add("∂" + o + "/∂points: dual numbers vs analytic", "relative", bound_autodiff);
    for (const std::string& o : outputs)
        add(o + ": O(K) vs O(K²) product rule", "eps", bound_textbook);
    for (const std::string& o : outputs)
        add(o + ": O(K) vs O(K²), both in long double (ε of long double)", "eps",
            std::numeric_limits<double>::quiet_NaN());
    return rows;
}

/// Times of one set: every knot (class 1) and `random` times inside segments, at least dt/20 from
/// a knot (class 0).
struct sample_time {
    double t;
    bool knot;
};
template <int K>
std::vector<sample_time> sample_times(quat::test::random_rotations& random, std::size_t count,
                                      double t0, double dt, int random_times) {
    std::vector<sample_time> times;
    const std::size_t segments = count - K + 1;
    for (std::size_t i = 0; i <= segments; ++i)
        times.push_back({t0 + static_cast<double>(i) * dt, true});
    for (int n = 0; n < random_times; ++n) {
        const double i = std::floor(random.uniform<double>(0, static_cast<double>(segments)));
        times.push_back({t0 + (i + random.uniform<double>(0.05, 0.95)) * dt, false});
    }
    return times;
}

/// Measures one control-point set of class `point_class` (0 random, 1 near identity, 2 near a half
/// turn) into column `column` of rows (bspline_table's order).
template <class Kind, int K>
void measure_set(const std::vector<typename Kind::template point<double>>& points, int point_class,
                 double t0, double dt, const std::vector<sample_time>& times,
                 std::vector<measured_row>& rows, std::size_t column, const std::string& set) {
    using P = typename Kind::template point<ld>;
    constexpr std::size_t D = Kind::dim, N = D * K;
    using blocks = typename Kind::template spline<double, K>::jacobian_blocks;
    using dual = quat::test::dual<double, N>;
    // wide: the points as given (the tests' reference); unit: normalized in long double, the
    // rotations or motions the double points stand for. The product rule's rates carry |X|^2
    // (Omega = X* X'), so it is evaluated on unit points: on the given ones, whose |q|^2 - 1 is up
    // to a few double eps, it would be off by as much.
    std::vector<P> wide, unit;
    for (const auto& x : points) {
        wide.emplace_back(x);
        unit.push_back(normalize(P(x)));
    }
    const typename Kind::template spline<ld, K> unit_spline(unit, ld(t0), ld(dt));
    const typename Kind::template spline<double, K> spline(points, t0, dt);
    const typename Kind::template spline<ld, K> wide_spline(wide, ld(t0), ld(dt));
    // Each rate's largest entry over the set's times, the scale its errors are measured in.
    std::array<ld, 3> rate_scale{};
    const ld reach = Kind::reach(unit);
    for (const sample_time& st : times) {
        const auto r = Kind::rates(unit_spline.evaluate(ld(st.t)));
        for (std::size_t k = 0; k < 3; ++k)
            rate_scale[k] = std::max(rate_scale[k], largest_entry(r[k]));
    }
    for (const sample_time& st : times) {
        const int cls = point_class == 0 ? (st.knot ? 1 : 0) : point_class + 1;
        const auto record = [&](std::size_t r, double e) {
            char at[96];
            std::snprintf(at, sizeof at, "%s, t = %.17g", set.c_str(), st.t);
            rows[r].columns[column][static_cast<std::size_t>(cls)].add(e, at);
        };
        const double t = st.t;
        std::array<blocks, 4> J{};
        const auto s = spline.evaluate(t, &J[0], &J[1], &J[2], &J[3]);
        const ld tl = t;
        const auto base = wide_spline.evaluate(tl);
        const auto rates = Kind::rates(s);

        // (a) Rates against differences in time: one-sided at knots (backwards at the end).
        const int side = !st.knot ? 0 : (t == spline.end_time() ? -1 : 1);
        const ld h = 1e-3L * dt;
        const auto at = [&](ld step) { return wide_spline.evaluate(tl + step); };
        std::array<std::array<ld, D>, 3> reference{};
        reference[0] = time_rate<D>(
            [&](ld step) { return Kind::minus(Kind::value(at(step)), Kind::value(base)); }, h,
            side);
        for (std::size_t k = 1; k < 3; ++k)
            reference[k] =
                time_rate<D>([&](ld step) { return Kind::rates(at(step))[k - 1]; }, h, side);
        for (std::size_t k = 0; k < 3; ++k)
            if (k < 2 || K >= 5 || !st.knot)
                record(k, scaled_error(rates[k], reference[k], rate_scale[k]));

        // (b) Jacobians: point first + m moved to x_m exp(delta); value's change as log(X^-1 X').
        std::array<std::vector<ld>, 4> wanted;
        for (auto& w : wanted) w.assign(D * N, 0);
        for (std::size_t m = 0; m < K; ++m) {
            const auto j = step_differences<4 * D, D>(
                [&](const std::array<ld, D>& delta) {
                    std::vector<P> moved = wide;
                    moved[s.first + m] = Kind::plus(moved[s.first + m], delta);
                    const typename Kind::template spline<ld, K> sp(moved, ld(t0), ld(dt));
                    const auto e = sp.evaluate(tl);
                    std::array<ld, 4 * D> out{};
                    const auto v = Kind::minus(Kind::value(e), Kind::value(base));
                    const auto r = Kind::rates(e);
                    for (std::size_t i = 0; i < D; ++i) {
                        out[i] = v[i];
                        for (std::size_t k = 0; k < 3; ++k) out[(k + 1) * D + i] = r[k][i];
                    }
                    return out;
                },
                1e-3L);
            for (std::size_t o = 0; o < 4; ++o)
                for (std::size_t r = 0; r < D; ++r)
                    for (std::size_t i = 0; i < D; ++i)
                        wanted[o][r * N + m * D + i] = j[o * D + r][i];
        }
        std::array<std::vector<double>, 4> got;
        for (std::size_t o = 0; o < 4; ++o) {
            got[o].assign(D * N, 0);
            for (std::size_t m = 0; m < K; ++m)
                for (std::size_t r = 0; r < D; ++r)
                    for (std::size_t i = 0; i < D; ++i)
                        got[o][r * N + m * D + i] =
                            J[o][m](static_cast<int>(r), static_cast<int>(i));
            record(3 + o, relative_error(got[o], wanted[o]));
        }

        // Forward-mode derivatives through the double evaluation, against the analytic Jacobians.
        std::vector<typename Kind::template point<dual>> moved;
        for (const auto& x : points) moved.push_back(Kind::template widen<dual>(x));
        for (std::size_t m = 0; m < K; ++m) {
            std::array<dual, D> v{};
            for (std::size_t i = 0; i < D; ++i) v[i] = dual::variable(0.0, m * D + i);
            moved[s.first + m] = Kind::first_order_plus(moved[s.first + m], v.data());
        }
        const typename Kind::template spline<dual, K> through(moved, dual(t0), dual(dt));
        const auto d = through.evaluate(dual(t));
        const auto d_rates = Kind::rates(d);
        const std::array<std::array<dual, D>, 4> d_outputs{Kind::local_tangent(Kind::value(d)),
                                                           d_rates[0], d_rates[1], d_rates[2]};
        for (std::size_t o = 0; o < 4; ++o) {
            std::vector<ld> partials(D * N);
            for (std::size_t r = 0; r < D; ++r)
                for (std::size_t c = 0; c < N; ++c) partials[r * N + c] = d_outputs[o][r].d[c];
            // Relative to the largest partial: the analytic Jacobian is `got`, the partials the
            // reference.
            record(7 + o, relative_error(got[o], partials));
        }

        // (c) The recurrences against the product rule in long double at the same u.
        const quat::detail::knot_position<double> pos =
            quat::detail::spline_position<K>(t, t0, dt, points.size());
        const auto textbook = quat::test::textbook_bspline<typename Kind::reference, ld, K>(
            unit.data() + pos.segment,
            quat::detail::cumulative_weights_at<ld, K>(ld(pos.u), ld(dt)));
        constexpr double eps = std::numeric_limits<double>::epsilon();
        record(11, Kind::value_error(Kind::value(s), textbook.value, reach) / eps);
        const auto textbook_rates =
            std::array{Kind::flat(textbook.velocity), Kind::flat(textbook.acceleration),
                       Kind::flat(textbook.jerk)};
        for (std::size_t k = 0; k < 3; ++k)
            record(12 + k, scaled_error(rates[k], textbook_rates[k], rate_scale[k]) / eps);
        const quat::detail::knot_position<ld> wide_pos =
            quat::detail::spline_position<K>(tl, ld(t0), ld(dt), points.size());
        const auto wide_textbook = quat::test::textbook_bspline<typename Kind::reference, ld, K>(
            unit.data() + wide_pos.segment,
            quat::detail::cumulative_weights_at<ld, K>(wide_pos.u, ld(dt)));
        constexpr double wide_eps = static_cast<double>(std::numeric_limits<ld>::epsilon());
        const auto unit_sample = unit_spline.evaluate(tl);
        record(15,
               Kind::value_error(Kind::value(unit_sample), wide_textbook.value, reach) / wide_eps);
        const auto base_rates = Kind::rates(unit_sample);
        const auto wide_textbook_rates =
            std::array{Kind::flat(wide_textbook.velocity), Kind::flat(wide_textbook.acceleration),
                       Kind::flat(wide_textbook.jerk)};
        for (std::size_t k = 0; k < 3; ++k)
            record(16 + k,
                   scaled_error(base_rates[k], wide_textbook_rates[k], rate_scale[k]) / wide_eps);
    }
}

/// The rows of one kind at K = 4, 5, 6 (columns 0, 1, 2): `sets` control-point sets of 12 points
/// per point class, every knot and `random_times` random times each.
template <class Kind>
std::vector<measured_row> measure_bspline(int sets, int random_times, std::uint64_t seed) {
    std::vector<measured_row> rows = bspline_table<Kind>();
    const auto order = [&](auto k, std::size_t column, double t0, double dt) {
        constexpr int K = decltype(k)::value;
        quat::test::random_rotations random(seed + 101 * column);
        for (int point_class = 0; point_class < 3; ++point_class)
            for (int n = 0; n < sets; ++n) {
                const auto points = Kind::points(random, point_class, 12);
                const auto times = sample_times<K>(random, points.size(), t0, dt, random_times);
                const std::string set = "K=" + std::to_string(K) + " " + set_names[point_class] +
                                        " set " + std::to_string(n);
                measure_set<Kind, K>(points, point_class, t0, dt, times, rows, column, set);
            }
    };
    // Knots exact in binary: t0 + i dt.
    order(std::integral_constant<int, 4>{}, 0, 0.25, 0.5);
    order(std::integral_constant<int, 5>{}, 1, -1.0, 0.75);
    order(std::integral_constant<int, 6>{}, 2, 2.0, 0.3125);
    return rows;
}

}  // namespace trajectory
}  // namespace accuracy
