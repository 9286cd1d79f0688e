// What tests/test_so3_bspline_derivatives.cpp and tests/test_se3_bspline.cpp share, templated on
// the control point (quaternion or dual quaternion) and the tangent's dimension N (3 or 6): named
// sets of control points, the times to check, the N x N Jacobian blocks joined into one N x NK
// matrix, tangents as arrays of components, and forward-mode scalars (ceres::Jet and
// tests/support/dual_number.hpp) with their partials.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <ceres/jet.h>
#include <quat/lie/se3.hpp>
#include <quat/matrix.hpp>
#include <quat/quaternion.hpp>
#include <quat/vec3.hpp>

#include "dual_number.hpp"
#include "random.hpp"

namespace quat::test {

/// Control points of one kind, with the name the checks report them by.
template <class Point>
struct control_points {
    std::string name;
    std::vector<Point> points;
};

/// The points in long double.
template <template <class> class Point>
std::vector<Point<long double>> widened(const std::vector<Point<double>>& points) {
    std::vector<Point<long double>> wide;
    for (const Point<double>& x : points) wide.push_back(Point<long double>(x));
    return wide;
}

/// Times to check: every knot from t0 to the end, and `inside` random times inside segments (at
/// least dt/20 from a knot, so that central differences stay inside one segment).
template <std::size_t K>
std::vector<double> check_times(std::size_t count, double t0, double dt, int inside) {
    random_rotations random(7);
    std::vector<double> times;
    const std::size_t segments = count - K + 1;
    for (std::size_t i = 0; i <= segments; ++i) times.push_back(t0 + static_cast<double>(i) * dt);
    for (int n = 0; n < inside; ++n) {
        const double i = std::floor(random.uniform<double>(0, static_cast<double>(segments)));
        times.push_back(t0 + (i + random.uniform<double>(0.05, 0.95)) * dt);
    }
    return times;
}

/// True when t is a knot of the spline (where one-sided differences are needed).
inline bool is_knot(double t, double t0, double dt) {
    const double s = (t - t0) / dt;
    return s == std::floor(s);
}

/// The K blocks of a Jacobian with respect to the K control points of a segment.
template <int N, std::size_t K>
using blocks = std::array<matrix<double, N, N>, K>;

/// The N x NK matrix of K blocks.
template <int N, std::size_t K>
matrix<double, N, N * K> joined(const blocks<N, K>& b) {
    matrix<double, N, N * K> m{};
    for (int k = 0; k < static_cast<int>(K); ++k)
        set_block(m, 0, N * k, b[static_cast<std::size_t>(k)]);
    return m;
}

/// A tangent's components: (x, y, z), or (linear, angular) for a twist.
template <class S>
std::array<S, 3> components(const vec3<S>& v) {
    return {v.x, v.y, v.z};
}
template <class S>
std::array<S, 6> components(const se3::twist<S>& t) {
    return {t.linear.x, t.linear.y, t.linear.z, t.angular.x, t.angular.y, t.angular.z};
}

// Forward-mode scalars at 0: variable i, the value and partial i.
template <int N>
using jet = ceres::Jet<double, N>;
template <int N>
jet<N> variable(int i, jet<N>*) {
    return jet<N>(0.0, i);
}
template <int N>
double value_of(const jet<N>& x) {
    return x.a;
}
template <int N>
double partial(const jet<N>& x, int i) {
    return x.v[i];
}
template <std::size_t N>
dual<double, N> variable(int i, dual<double, N>*) {
    return dual<double, N>::variable(0.0, static_cast<std::size_t>(i));
}
template <std::size_t N>
double value_of(const dual<double, N>& x) {
    return x.value;
}
template <std::size_t N>
double partial(const dual<double, N>& x, int i) {
    return x.d[static_cast<std::size_t>(i)];
}

/// The quaternion of the values alone, without partials.
template <class S>
quaternion<S> value_part(const quaternion<S>& q) {
    return {S(value_of(q.w)), S(value_of(q.x)), S(value_of(q.y)), S(value_of(q.z))};
}

/// max |a - b| / max |b| over the R x C entries.
template <int R, int C>
double max_relative(const matrix<double, R, C>& a, const matrix<double, R, C>& b) {
    double error = 0, largest = 0;
    for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) {
            if (!std::isfinite(a(r, c))) return std::numeric_limits<double>::infinity();
            error = std::max(error, std::abs(a(r, c) - b(r, c)));
            largest = std::max(largest, std::abs(b(r, c)));
        }
    return largest > 0 ? error / largest : error;
}

/// The R x C partials of a tangent of forward-mode scalars.
template <int C, class Tangent>
auto partials(const Tangent& v) {
    const auto e = components(v);
    constexpr int R = static_cast<int>(std::tuple_size<decltype(e)>::value);
    matrix<double, R, C> m{};
    for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) m(r, c) = partial(e[static_cast<std::size_t>(r)], c);
    return m;
}

}  // namespace quat::test
