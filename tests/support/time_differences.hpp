// Richardson-extrapolated differences in time for the spline tests: central inside a segment, one-
// sided at a knot (where a spline of order K is only C^(K-2)), each in long double.
#pragma once

#include <array>
#include <cstddef>

#include <quat/matrix.hpp>

namespace quat::test {

/// d f(s) / ds at s = 0 for f: long double -> std::array<long double, N>: central differences with
/// steps h, h/2, h/4 extrapolated twice (error O(h^6)) for side = 0; for side = +1 (-1) forward
/// (backward) differences with steps h .. h/32 extrapolated five times (error O(h^6)), reading f
/// only on that side of 0.
template <int N, class F>
matrix<long double, N, 1> time_derivative(F f, long double h, int side) {
    using ld = long double;
    constexpr int levels = 6;
    std::array<std::array<ld, levels>, N> table{};
    const int used = side == 0 ? 3 : levels;
    const std::array<ld, N> at_zero = side == 0 ? std::array<ld, N>{} : f(0.0L);
    for (int k = 0; k < used; ++k) {
        const ld step = h / static_cast<ld>(1 << k);
        if (side == 0) {
            const std::array<ld, N> up = f(step), down = f(-step);
            for (std::size_t r = 0; r < N; ++r)
                table[r][static_cast<std::size_t>(k)] = (up[r] - down[r]) / (2 * step);
        } else {
            const std::array<ld, N> there = f(side * step);
            for (std::size_t r = 0; r < N; ++r)
                table[r][static_cast<std::size_t>(k)] = (there[r] - at_zero[r]) / (side * step);
        }
    }
    matrix<ld, N, 1> out{};
    for (std::size_t r = 0; r < N; ++r) {
        auto e = table[r];
        // Errors in h^2, h^4, ... (central) or h, h^2, ... (one-sided): eliminate one power a pass.
        for (int pass = 1; pass < used; ++pass) {
            const ld factor =
                side == 0 ? static_cast<ld>(1 << (2 * pass)) : static_cast<ld>(1 << pass);
            for (int k = used - 1; k >= pass; --k) {
                const auto i = static_cast<std::size_t>(k);
                e[i] = (factor * e[i] - e[i - 1]) / (factor - 1);
            }
        }
        out(static_cast<int>(r), 0) = e[static_cast<std::size_t>(used - 1)];
    }
    return out;
}

}  // namespace quat::test
