// The cumulative basis of uniform B-splines of order K (degree K - 1) and the segment of a uniform
// knot sequence that holds a time. With knots t0 + m dt, the spline on [t0 + i dt, t0 + (i + 1) dt]
// blends control points i .. i + K - 1 with weights b_s(u), u = (t - t0) / dt - i in [0, 1]; the
// cumulative weights are b~_j(u) = sum over s >= j of b_s(u), so b~_0 = 1 (K. Qin, "General matrix
// representations for B-splines", 2000; C. Sommer, V. Usenko, D. Schubert, N. Demmel, D. Cremers,
// "Efficient Derivative Computation for Cumulative B-Splines on Lie Groups", CVPR 2020).
#ifndef QUAT_TRAJECTORY_DETAIL_UNIFORM_BASIS_HPP_INCLUDED
#define QUAT_TRAJECTORY_DETAIL_UNIFORM_BASIS_HPP_INCLUDED

#include <array>
#include <cstddef>
#include <type_traits>

#include "../../detail/math.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

/// n!, for the small n of spline orders.
[[nodiscard]] constexpr long long factorial_of(int n) noexcept {
    long long f = 1;
    for (int i = 2; i <= n; ++i) f *= i;
    return f;
}

/// The binomial coefficient C(n, r), 0 outside 0 <= r <= n.
[[nodiscard]] constexpr long long binomial_of(int n, int r) noexcept {
    if (r < 0 || r > n) return 0;
    return factorial_of(n) / (factorial_of(r) * factorial_of(n - r));
}

/// (K - 1)! times the coefficients of the cumulative basis, table[d][j][n]: the coefficient of u^n
/// in (K - 1)! d^d/du^d b~_j(u). Qin's blending matrix of the uniform B-spline of order K is
///     (K - 1)! m(s, n) = C(K - 1, n) sum_(l = s .. K - 1) (-1)^(l - s) C(K, l - s) (K - 1 - l)^(K - 1 - n)
/// (all integers); b~_j sums its rows s >= j, and each derivative multiplies the coefficient of
/// u^n by n and moves it to u^(n - 1).
template <std::size_t K>
[[nodiscard]] constexpr std::array<std::array<std::array<long long, K>, K>, 4>
cumulative_basis_table() noexcept {
    std::array<std::array<std::array<long long, K>, K>, 4> table{};
    const int k = static_cast<int>(K);  // signed: the sums below alternate in sign
    for (int s = 0; s < k; ++s)
        for (int n = 0; n < k; ++n) {
            long long sum = 0;
            for (int l = s; l < k; ++l) {
                long long power = 1;
                for (int e = 0; e < k - 1 - n; ++e) power *= (k - 1 - l);
                sum += ((l - s) % 2 == 0 ? 1 : -1) * binomial_of(k, l - s) * power;
            }
            const long long entry = binomial_of(k - 1, n) * sum;
            for (int j = 0; j <= s; ++j)
                table[0][static_cast<std::size_t>(j)][static_cast<std::size_t>(n)] += entry;
        }
    for (std::size_t d = 1; d < 4; ++d)
        for (std::size_t j = 0; j < K; ++j)
            for (std::size_t n = 0; n + 1 < K; ++n)
                table[d][j][n] = static_cast<long long>(n + 1) * table[d - 1][j][n + 1];
    return table;
}

/// The cumulative weights and their first three time derivatives at one time: b[d][j] is
/// d^d/dt^d b~_j (j = 0 .. K - 1; b[0][0] = 1, b[d][0] = 0 for d > 0).
template <class T, std::size_t K>
struct cumulative_weights {
    std::array<std::array<T, K>, 4> b;
};

/// The cumulative weights at u in [0, 1] of a segment of duration dt: Horner's scheme on the
/// integer coefficients, one division by (K - 1)! dt^d each (exact coefficients in any T).
template <class T, std::size_t K>
[[nodiscard]] constexpr cumulative_weights<T, K> cumulative_weights_at(const T& u,
                                                                       const T& dt) noexcept {
    constexpr auto table = cumulative_basis_table<K>();
    cumulative_weights<T, K> w{};
    T scale = T(static_cast<double>(factorial_of(static_cast<int>(K) - 1)));
    for (std::size_t d = 0; d < 4; ++d) {
        for (std::size_t j = 0; j < K; ++j) {
            if (d + 1 > K) {
                w.b[d][j] = T(0);
                continue;
            }
            const std::size_t top = K - 1 - d;  // the degree after d derivatives
            T sum = T(static_cast<double>(table[d][j][top]));
            for (std::size_t n = top; n-- > 0;)
                sum = sum * u + T(static_cast<double>(table[d][j][n]));
            w.b[d][j] = sum / scale;
        }
        scale = scale * dt;
    }
    return w;
}

/// Where a time falls on a uniform knot sequence: the segment (its first control point) and u in
/// [0, 1]; valid is false outside the spline's domain (see spline_position).
template <class T>
struct knot_position {
    std::size_t segment;
    T u;
    bool valid;
};

/// The segment of the uniform spline of order K over `count` control points, with knots t0 + m dt,
/// that holds t: for t0 <= t <= t0 + (count - K + 1) dt (computed so in T), s = (t - t0) / dt
/// (at most count - K + 1), segment = min(floor(s), count - K), u = s - segment (the last segment
/// includes its end, u = 1). Invalid (segment 0, u NaN) for count < K, dt not positive or not
/// finite, t0 not finite, t NaN or outside that range.
template <std::size_t K, class T>
[[nodiscard]] constexpr knot_position<T> spline_position(const T& t, const T& t0, const T& dt,
                                                         std::size_t count) noexcept {
    const knot_position<T> invalid{0, quiet_nan<T>(), false};
    if (count < K || !(dt > T(0)) || !is_finite(dt) || !is_finite(t0)) return invalid;
    const std::size_t last = count - K;
    const T segments = T(static_cast<double>(last + 1));
    // The range as times, t0 <= t <= t0 + segments dt (the end as end_time() rounds it), then s
    // clamped to it: (t - t0) / dt may round past the last knot at the end itself.
    if (!(t >= t0) || !(t <= t0 + segments * dt)) return invalid;
    T s = (t - t0) / dt;
    if (s > segments) s = segments;
    std::size_t segment = last;
    if constexpr (std::is_floating_point_v<T>) {
        // s < last fits std::size_t, and its truncation is its floor (s >= 0).
        if (s < T(static_cast<double>(last))) segment = static_cast<std::size_t>(s);
        if (segment > last) segment = last;
    } else {
        // A user scalar need not convert to an integer: the last i <= last with i <= s.
        std::size_t low = 0, high = last;
        while (low < high) {
            const std::size_t middle = low + (high - low + 1) / 2;
            if (s < T(static_cast<double>(middle))) high = middle - 1;
            else low = middle;
        }
        segment = low;
    }
    return {segment, s - T(static_cast<double>(segment)), true};
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_DETAIL_UNIFORM_BASIS_HPP_INCLUDED
