// The references of `quat_accuracy --trajectory`: long double central differences of a function
// of a tangent step (Richardson-extrapolated twice, as tests/support/jacobian_check.hpp does for
// the tests, which cannot be included here: it brings Catch), time differences from
// tests/support/time_differences.hpp, and the error of a result relative to the largest entry of
// its reference.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "support/time_differences.hpp"

namespace accuracy {
namespace trajectory {

using ld = long double;

/// The Jacobian of g: R^In -> R^Out at 0 (g takes a std::array<ld, In> and returns a
/// std::array<ld, Out>), column by column, from steps h, h/2 and h/4 (error O(h^6)):
/// result[r][i] = d g_r / d x_i.
template <std::size_t Out, std::size_t In, class G>
std::array<std::array<ld, In>, Out> step_differences(G g, ld h) {
    std::array<std::array<ld, In>, Out> result{};
    for (std::size_t i = 0; i < In; ++i) {
        std::array<std::array<ld, 3>, Out> estimate{};
        for (std::size_t k = 0; k < 3; ++k) {
            const ld step = h / static_cast<ld>(1 << k);
            std::array<ld, In> plus{}, minus{};
            plus[i] = step;
            minus[i] = -step;
            const std::array<ld, Out> up = g(plus), down = g(minus);
            for (std::size_t r = 0; r < Out; ++r) estimate[r][k] = (up[r] - down[r]) / (2 * step);
        }
        for (std::size_t r = 0; r < Out; ++r) {
            const auto& e = estimate[r];
            const ld first = (4 * e[1] - e[0]) / 3, second = (4 * e[2] - e[1]) / 3;
            result[r][i] = (16 * second - first) / 15;
        }
    }
    return result;
}

/// d f(s) / ds at s = 0 for f: ld -> std::array<ld, N>, central (side 0) or one-sided (side +-1,
/// reading f on that side only), Richardson-extrapolated to O(h^6) (tests/support).
template <std::size_t N, class F>
std::array<ld, N> time_rate(F f, ld h, int side) {
    const auto column = quat::test::time_derivative<static_cast<int>(N)>(f, h, side);
    std::array<ld, N> out{};
    for (std::size_t r = 0; r < N; ++r) out[r] = column(static_cast<int>(r), 0);
    return out;
}

/// max |got - reference| / max |reference| over the entries (absolute where the reference is
/// zero); infinite for a non-finite entry.
template <class Got>
double relative_error(const Got& got, const std::vector<ld>& reference) {
    ld largest = 0, error = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        const auto value = static_cast<ld>(got[i]);
        if (!std::isfinite(value)) return std::numeric_limits<double>::infinity();
        largest = std::max(largest, std::abs(reference[i]));
        error = std::max(error, std::abs(value - reference[i]));
    }
    return static_cast<double>(largest > 0 ? error / largest : error);
}

/// relative_error of two fixed-size arrays.
template <class T, std::size_t N>
double relative_error(const std::array<T, N>& got, const std::array<ld, N>& reference) {
    return relative_error(got, std::vector<ld>(reference.begin(), reference.end()));
}

/// The largest |entry| of a rate.
template <std::size_t N>
ld largest_entry(const std::array<ld, N>& v) {
    ld largest = 0;
    for (const ld x : v) largest = std::max(largest, std::abs(x));
    return largest;
}

/// max |got - reference| / scale, scale the largest entry of the same rate over all the set's
/// sample times: a rate's error relative to its size along the path. At one time a rate can pass
/// near zero (an acceleration between a speed-up and a slow-down) while its terms do not, and
/// relative to its own entries there any rounding of theirs looks large.
template <class T, std::size_t N>
double scaled_error(const std::array<T, N>& got, const std::array<ld, N>& reference, ld scale) {
    ld error = 0;
    for (std::size_t i = 0; i < N; ++i) {
        const auto value = static_cast<ld>(got[i]);
        if (!std::isfinite(value)) return std::numeric_limits<double>::infinity();
        error = std::max(error, std::abs(value - reference[i]));
    }
    return static_cast<double>(scale > 0 ? error / scale : error);
}

/// The largest error seen, and where.
struct worst_error {
    double max = 0;
    long count = 0;
    std::string where;

    void add(double e, const std::string& at) {
        if (std::isnan(e)) e = std::numeric_limits<double>::infinity();
        if (count++ == 0 || e > max) {
            max = e;
            where = at;
        }
    }
};

/// The sample classes, the columns of a row's breakdown: random times and knots (of random
/// control points or keyframes), then both kinds of time for points near the identity and for
/// increments near a half turn.
constexpr int class_count = 4;
constexpr const char* class_names[class_count] = {"random t", "knots", "near identity", "near π"};
/// The kinds of control points (or keyframes), as the worst cases name them.
constexpr const char* set_names[3] = {"random points", "near identity", "near π"};

/// One quantity: its worst error in each column (an order K, or a path) and sample class, and the
/// bound it is held to.
struct measured_row {
    std::string group;     // the spline or path family
    std::string quantity;  // what is compared with what
    std::string unit;      // "relative" or "eps"
    double bound;          // NaN: a diagnostic row, held to nothing
    std::vector<std::array<worst_error, class_count>> columns;

    /// The worst over the classes of column c, and the class it occurred in.
    [[nodiscard]] const worst_error* worst(std::size_t c, int* which) const {
        const worst_error* w = nullptr;
        for (int k = 0; k < class_count; ++k) {
            const worst_error& e = columns[c][static_cast<std::size_t>(k)];
            if (e.count > 0 && (w == nullptr || e.max > w->max)) {
                w = &e;
                *which = k;
            }
        }
        return w;
    }
    [[nodiscard]] bool exceeded() const {
        for (const auto& column : columns)
            for (const worst_error& e : column)
                if (e.count > 0 && !std::isnan(bound) && !(e.max <= bound)) return true;
        return false;
    }
};

}  // namespace trajectory
}  // namespace accuracy
