// The reference Jacobians of tests/test_so3.cpp and tests/test_se3.cpp: long double central
// differences of a function of a tangent step, Richardson-extrapolated twice, the relative error
// of a Jacobian against them, and a check that remembers each Jacobian's worst error
// (QUAT_LIE_REPORT=1 in the environment prints them when the tests end).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <string>

// lie/so3.hpp for matrix<T, R, C>: the single-header layout has no matrix.hpp of its own.
#include <quat/lie/so3.hpp>

#include "catch.hpp"

namespace quat::test {

/// The Jacobian of g: R^In -> R^Out at 0 (g takes and returns long double arrays), from steps h,
/// h/2 and h/4 (error O(h^6)).
template <int Out, int In, class G>
matrix<long double, Out, In> central_differences(G g, long double h) {
    using ld = long double;
    matrix<ld, Out, In> result{};
    for (int i = 0; i < In; ++i) {
        std::array<std::array<ld, 3>, Out> estimate{};
        for (int k = 0; k < 3; ++k) {
            const ld step = h / static_cast<ld>(1 << k);
            std::array<ld, In> plus{}, minus{};
            plus[static_cast<std::size_t>(i)] = step;
            minus[static_cast<std::size_t>(i)] = -step;
            const std::array<ld, Out> up = g(plus), down = g(minus);
            for (std::size_t r = 0; r < Out; ++r)
                estimate[r][static_cast<std::size_t>(k)] = (up[r] - down[r]) / (2 * step);
        }
        for (int r = 0; r < Out; ++r) {
            const auto& e = estimate[static_cast<std::size_t>(r)];
            const ld first = (4 * e[1] - e[0]) / 3, second = (4 * e[2] - e[1]) / 3;
            result(r, i) = (16 * second - first) / 15;
        }
    }
    return result;
}

/// max |got - reference| / max |reference| (absolute where the reference is zero); Inf for a NaN
/// or infinite entry.
template <class T, int R, int C>
double relative_error(const matrix<T, R, C>& got, const matrix<long double, R, C>& reference) {
    long double largest = 0, error = 0;
    for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) {
            const auto value = static_cast<long double>(got(r, c));
            if (!std::isfinite(value)) return std::numeric_limits<double>::infinity();
            largest = std::max(largest, std::abs(reference(r, c)));
            error = std::max(error, std::abs(value - reference(r, c)));
        }
    return static_cast<double>(largest > 0 ? error / largest : error);
}

/// The worst error seen for each named Jacobian, printed at exit under QUAT_LIE_REPORT.
class worst_errors {
public:
    explicit worst_errors(const char* group) : group_(group) {}
    worst_errors(const worst_errors&) = delete;
    worst_errors& operator=(const worst_errors&) = delete;
    ~worst_errors() {
        if (std::getenv("QUAT_LIE_REPORT") == nullptr) return;
        for (const auto& [name, error] : table_)
            std::printf("%s %-40s %.2e\n", group_, name.c_str(), error);
    }

    /// Records the error and checks it against the tolerance.
    void check(const std::string& name, double error, double tolerance = 1e-12) {
        double& worst = table_[name];
        worst = std::max(worst, error);
        INFO(name << ": error " << error);
        CHECK(error <= tolerance);
    }

private:
    const char* group_;
    std::map<std::string, double> table_;
};

}  // namespace quat::test
