// e^x and ln x for quat's scalars: in long double by series in constant evaluation (as
// detail/math.hpp's sqrt and sin), the compiler's builtins at run time, and ADL exp and log for a
// user scalar. Only exp(quaternion) and log(quaternion) use them.
#ifndef QUAT_DETAIL_EXP_LOG_HPP_INCLUDED
#define QUAT_DETAIL_EXP_LOG_HPP_INCLUDED

#include <type_traits>

#include "math.hpp"

namespace quat {

#include "isa_namespace.inc"
namespace detail {
namespace compile_time {

// e^x and ln x in long double for constant evaluation, as detail/math.hpp's sqrt and sin: within a
// few ulp of long double over the whole range. ln 2 is split into a head with 32 significant bits
// (fdlibm's ln2_hi), so k * head is exact for |k| < 2^32, and the rest.
inline constexpr real ln2 = 0.693147180559945309417232121458176568L;
inline constexpr real ln2_head = 0.693147180369123816490L;
inline constexpr real ln2_tail = ln2 - ln2_head;

[[nodiscard]] constexpr real exp(real x) noexcept {
    if (is_nan(x)) return x;
    if (x > 11357) return infinity<real>();
    if (x < -11400) return 0;
    // x = k ln 2 + r with |r| <= ln 2 / 2; e^r by its Taylor series, then times 2^k exactly.
    const real quotient = x / ln2;
    long long k = static_cast<long long>(quotient + (quotient < 0 ? -0.5L : 0.5L));
    const real r = (x - static_cast<real>(k) * ln2_head) - static_cast<real>(k) * ln2_tail;
    real term = 1, sum = 1;
    for (int n = 1; n < 40; ++n) {
        term *= r / static_cast<real>(n);
        if (sum + term == sum) break;
        sum += term;
    }
    for (; k > 0; --k) sum *= 2;
    for (; k < 0; ++k) sum /= 2;
    return sum;
}

[[nodiscard]] constexpr real log(real x) noexcept {
    if (is_nan(x) || x < 0) return quiet_nan<real>();
    if (x == 0) return -infinity<real>();
    if (x == infinity<real>()) return x;
    // x = m 2^e with m in [sqrt(1/2), sqrt(2)) (exact scalings), then ln m = 2 atanh(f),
    // f = (m - 1) / (m + 1), |f| < 0.172, by its series.
    long long e = 0;
    constexpr real big = 18446744073709551616.0L;  // 2^64
    while (x >= big) {
        x /= big;
        e += 64;
    }
    while (x < 1 / big) {
        x *= big;
        e -= 64;
    }
    while (x >= 2) {
        x /= 2;
        ++e;
    }
    while (x < 1) {
        x *= 2;
        --e;
    }
    if (x > 1.41421356237309504880L) {
        x /= 2;
        ++e;
    }
    const real f = (x - 1) / (x + 1), f2 = f * f;
    real power = f, sum = f;
    for (int n = 1; n < 40; ++n) {
        power *= f2;
        const real term = power / static_cast<real>(2 * n + 1);
        if (sum + term == sum) break;
        sum += term;
    }
    const auto k = static_cast<real>(e);
    return k * ln2_head + (k * ln2_tail + 2 * sum);
}

}  // namespace compile_time

/// e^x; for a user scalar, exp found by argument-dependent lookup (only exp(quaternion) needs it).
template <class T>
[[nodiscard]] constexpr T scalar_exp(T x) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        if (constant_evaluated())
            return static_cast<T>(compile_time::exp(static_cast<compile_time::real>(x)));
        if constexpr (std::is_same_v<T, float>) {
            return __builtin_expf(x);
        } else if constexpr (std::is_same_v<T, double>) {
            return __builtin_exp(x);
        } else {
            return __builtin_expl(x);
        }
    } else {
        using adl_only::exp;
        return exp(x);
    }
}

/// ln x (NaN for negative x, -Inf for 0); for a user scalar, log found by argument-dependent
/// lookup (only log(quaternion) needs it).
template <class T>
[[nodiscard]] constexpr T scalar_log(T x) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        if (constant_evaluated())
            return static_cast<T>(compile_time::log(static_cast<compile_time::real>(x)));
        if constexpr (std::is_same_v<T, float>) {
            return __builtin_logf(x);
        } else if constexpr (std::is_same_v<T, double>) {
            return __builtin_log(x);
        } else {
            return __builtin_logl(x);
        }
    } else {
        using adl_only::log;
        return log(x);
    }
}

}  // namespace detail
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_DETAIL_EXP_LOG_HPP_INCLUDED
