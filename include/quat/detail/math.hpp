// Scalar functions that work at compile time and at run time, and for user-defined scalars.
//
// For float, double and long double: the C library's functions at run time, called through the
// compiler's builtins (std::sqrt(float) and the like are the standard library's inline functions,
// which quat cannot key by instruction set, see below), and during constant evaluation our own long
// double implementations (correct to a few ulp of double for the argument ranges rotations use:
// |x| < 1e6 for sin and cos). For any other scalar the call is unqualified, so ADL finds the user's
// sqrt, sin, cos, atan2, asin and abs. No <cmath>: the builtins need no declaration, and g++ 12
// parsed bench/compile_time.sh's unit in 1300 million instructions with it, 938 without
// (callgrind); with it that unit compiled at -O2 in 1.18x the instructions of the one including
// GLM's quaternion headers.
//
// One definition across instruction sets. An inline function compiled with -mavx (even plain scalar
// code: at -O0 every load is VEX-encoded) and the same function compiled without it have one name,
// and the linker keeps one copy for the whole program; a translation unit built for CPUs without
// AVX may then run the AVX one. So every quat function lives in an inline namespace named after the
// instruction set it is compiled for: the widest of AVX-512F, AVX2, AVX, SSE4.1 and SSE, and
// whether FMA is on (which changes every multiply-add the compiler contracts, and fast_fma below).
// Units built with different flags then call different functions. Every header opens the key by
// including detail/isa_namespace.inc, the one place its #if chain is spelled out (quat's only
// macros
// are its version and QUAT_ASSERT); detail, nested in it, is keyed with everything in it.
// What it covers: every function quat defines, free or in detail; rotation_spline, a class whose
// member functions do real work, is keyed whole (so it cannot cross between such units). The value
// types (vec3, quaternion, the matrices, euler, dual_quaternion, ...) are not keyed, so that they
// mean the same type in every unit and can cross between units built with different flags; their
// few member functions (constructors, identity, element access) are [[gnu::always_inline]], so no
// copy of them is ever emitted (unless a user takes their address). What it cannot cover: the
// standard library's inline functions (those of std::vector, std::optional, std::numeric_limits,
// ...) have one name whatever the flags; quat calls none of them on its computing paths (numeric
// limits are read at compile time, below), but the try_... functions return std::optional, and user
// code has its own. Nor does the key name every -m flag (-mbmi2, -mf16c, the AVX-512 subsets beyond
// F): units that differ only in those share quat's functions. tests/contracts/isa_mix_*.cpp is the
// proof: units built for x86-64, x86-64-v3 and AVX-512 in one program, whose baseline unit runs
// under an emulated CPU without AVX; tests/contracts/isa_key_lint.cmake checks the habits above in
// every header.
#ifndef QUAT_DETAIL_MATH_HPP_INCLUDED
#define QUAT_DETAIL_MATH_HPP_INCLUDED

#include <limits>
#include <type_traits>

namespace quat {
#include "isa_namespace.inc"
namespace detail {

// What the using-declarations of the user-scalar branches below name: deleted functions that no
// call can choose, so that an unqualified sqrt(x) finds only the user's overloads (by ADL), never
// the quat::detail function it is called from.
namespace adl_only {
void sqrt() = delete;
void sin() = delete;
void cos() = delete;
void atan2() = delete;
void asin() = delete;
void abs() = delete;
void exp() = delete;
void log() = delete;
}  // namespace adl_only

/// True while the caller is being constant-evaluated. The builtin exists in GCC >= 9 and Clang >= 9
/// in every language mode, which lets C++17 code use <cmath> at run time. (MSVC is not supported:
/// quat also needs __builtin_copysignl and other GCC/Clang builtins.)
[[nodiscard]] constexpr bool constant_evaluated() noexcept {
    return __builtin_is_constant_evaluated();
}

// std::numeric_limits<T>'s constants, read during compilation: called at run time (as at -O0),
// std::numeric_limits<double>::epsilon() is an inline function of the standard library, which the
// linker may take from a unit compiled for another instruction set. Any other T asks
// numeric_limits.
/// The difference between 1 and the next larger T.
template <class T>
[[nodiscard]] constexpr T epsilon() noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        constexpr T value = std::numeric_limits<T>::epsilon();
        return value;
    } else {
        return std::numeric_limits<T>::epsilon();
    }
}
/// The smallest positive normal T.
template <class T>
[[nodiscard]] constexpr T smallest_normal() noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        constexpr T value = std::numeric_limits<T>::min();
        return value;
    } else {
        return std::numeric_limits<T>::min();
    }
}
/// The largest finite T.
template <class T>
[[nodiscard]] constexpr T largest() noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        constexpr T value = std::numeric_limits<T>::max();
        return value;
    } else {
        return std::numeric_limits<T>::max();
    }
}
/// True when a squared length neither overflows nor loses digits to underflow, so that formulas
/// built on it are accurate as written; always true for a user scalar, trusted with any length.
template <class T>
[[nodiscard]] constexpr bool in_normal_range(T squared_length) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        return squared_length >= smallest_normal<T>() && squared_length <= largest<T>();
    } else {
        return true;
    }
}
/// Positive infinity.
template <class T>
[[nodiscard]] constexpr T infinity() noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        constexpr T value = std::numeric_limits<T>::infinity();
        return value;
    } else {
        return std::numeric_limits<T>::infinity();
    }
}
/// A quiet NaN.
template <class T>
[[nodiscard]] constexpr T quiet_nan() noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        constexpr T value = std::numeric_limits<T>::quiet_NaN();
        return value;
    } else {
        return std::numeric_limits<T>::quiet_NaN();
    }
}

namespace compile_time {

using real = long double;
inline constexpr real pi = 3.14159265358979323846264338327950288L;
// pi/2 split in a 53-bit head (so k * head is exact for |k| < 2^11) and the remainder.
inline constexpr real half_pi_head = static_cast<real>(static_cast<double>(pi / 2));
inline constexpr real half_pi_tail = pi / 2 - half_pi_head;

[[nodiscard]] constexpr bool is_nan(real x) noexcept { return x != x; }
[[nodiscard]] constexpr bool sign_bit(real x) noexcept { return __builtin_copysignl(1.0L, x) < 0; }

[[nodiscard]] constexpr real sqrt(real x) noexcept {
    if (is_nan(x) || x < 0) return quiet_nan<real>();
    if (x == 0 || x == infinity<real>()) return x;
    // Scale by powers of 4 (exact) into [1, 4), then Newton from above, which decreases
    // monotonically.
    real scale = 1;
    constexpr real big = 18446744073709551616.0L;  // 2^64
    while (x >= big) {
        x /= big;
        scale *= 4294967296.0L;
    }
    while (x < 1 / big) {
        x *= big;
        scale /= 4294967296.0L;
    }
    while (x >= 4) {
        x /= 4;
        scale *= 2;
    }
    while (x < 1) {
        x *= 4;
        scale /= 2;
    }
    real y = (x + 1) / 2;
    for (int i = 0; i < 64; ++i) {
        const real next = (y + x / y) / 2;
        if (!(next < y)) break;
        y = next;
    }
    return y * scale;
}

// Taylor series of sin and cos on |r| <= pi/4, summed until the terms no longer change the result.
[[nodiscard]] constexpr real sin_kernel(real r) noexcept {
    real term = r, sum = r;
    for (int n = 1; n < 30; ++n) {
        term *= -r * r / static_cast<real>((2 * n) * (2 * n + 1));
        if (sum + term == sum) break;
        sum += term;
    }
    return sum;
}
[[nodiscard]] constexpr real cos_kernel(real r) noexcept {
    real term = 1, sum = 1;
    for (int n = 1; n < 30; ++n) {
        term *= -r * r / static_cast<real>((2 * n - 1) * (2 * n));
        if (sum + term == sum) break;
        sum += term;
    }
    return sum;
}

struct sine_cosine {
    real sin, cos;
};
[[nodiscard]] constexpr sine_cosine sin_cos(real x) noexcept {
    if (is_nan(x) || x - x != 0) return {quiet_nan<real>(), quiet_nan<real>()};
    const real quotient = x / (pi / 2);
    if (quotient > 9e15L || quotient < -9e15L) return {quiet_nan<real>(), quiet_nan<real>()};
    const long long k = static_cast<long long>(quotient + (quotient < 0 ? -0.5L : 0.5L));
    const real r = (x - static_cast<real>(k) * half_pi_head) - static_cast<real>(k) * half_pi_tail;
    const real s = sin_kernel(r), c = cos_kernel(r);
    switch (((k % 4) + 4) % 4) {
        case 0:
            return {s, c};
        case 1:
            return {c, -s};
        case 2:
            return {-s, -c};
        default:
            return {-c, s};
    }
}

// atan on [0, 1]: shift by pi/4 above tan(pi/8), then the alternating series on |z| <= 0.4143.
[[nodiscard]] constexpr real atan_unit(real z) noexcept {
    real offset = 0;
    if (z > 0.41421356237309504880L) {
        offset = pi / 4;
        z = (z - 1) / (z + 1);
    }
    real power = z, sum = z;
    for (int n = 1; n < 80; ++n) {
        power *= -z * z;
        const real term = power / static_cast<real>(2 * n + 1);
        if (sum + term == sum) break;
        sum += term;
    }
    return offset + sum;
}

[[nodiscard]] constexpr real atan2(real y, real x) noexcept {
    if (is_nan(x) || is_nan(y)) return quiet_nan<real>();
    constexpr real inf = infinity<real>();
    const real ax = x < 0 ? -x : x, ay = y < 0 ? -y : y;
    real angle = 0;
    if (ax == inf && ay == inf) angle = pi / 4;
    else if (ay == 0 || ax == inf) angle = 0;
    else if (ax == 0 || ay == inf) angle = pi / 2;
    else if (ay <= ax) angle = atan_unit(ay / ax);
    else angle = pi / 2 - atan_unit(ax / ay);
    if (sign_bit(x)) angle = pi - angle;
    return sign_bit(y) ? -angle : angle;
}

}  // namespace compile_time

/// sqrt(x); NaN for negative x.
template <class T>
[[nodiscard]] constexpr T sqrt(T x) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        if (constant_evaluated())
            return static_cast<T>(compile_time::sqrt(static_cast<compile_time::real>(x)));
        if constexpr (std::is_same_v<T, float>) {
            return __builtin_sqrtf(x);
        } else if constexpr (std::is_same_v<T, double>) {
            return __builtin_sqrt(x);
        } else {
            return __builtin_sqrtl(x);
        }
    } else {
        using adl_only::sqrt;
        return sqrt(x);
    }
}

/// sin(x) in radians.
template <class T>
[[nodiscard]] constexpr T sin(T x) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        if (constant_evaluated())
            return static_cast<T>(compile_time::sin_cos(static_cast<compile_time::real>(x)).sin);
        if constexpr (std::is_same_v<T, float>) {
            return __builtin_sinf(x);
        } else if constexpr (std::is_same_v<T, double>) {
            return __builtin_sin(x);
        } else {
            return __builtin_sinl(x);
        }
    } else {
        using adl_only::sin;
        return sin(x);
    }
}

/// cos(x) in radians.
template <class T>
[[nodiscard]] constexpr T cos(T x) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        if (constant_evaluated())
            return static_cast<T>(compile_time::sin_cos(static_cast<compile_time::real>(x)).cos);
        if constexpr (std::is_same_v<T, float>) {
            return __builtin_cosf(x);
        } else if constexpr (std::is_same_v<T, double>) {
            return __builtin_cos(x);
        } else {
            return __builtin_cosl(x);
        }
    } else {
        using adl_only::cos;
        return cos(x);
    }
}

/// atan2(y, x) in [-pi, pi], with IEEE signed-zero and infinity rules.
template <class T>
[[nodiscard]] constexpr T atan2(T y, T x) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        if (constant_evaluated())
            return static_cast<T>(compile_time::atan2(static_cast<compile_time::real>(y),
                                                      static_cast<compile_time::real>(x)));
        if constexpr (std::is_same_v<T, float>) {
            return __builtin_atan2f(y, x);
        } else if constexpr (std::is_same_v<T, double>) {
            return __builtin_atan2(y, x);
        } else {
            return __builtin_atan2l(y, x);
        }
    } else {
        using adl_only::atan2;
        return atan2(y, x);
    }
}

/// asin(x) in [-pi/2, pi/2]; NaN outside [-1, 1].
template <class T>
[[nodiscard]] constexpr T asin(T x) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        if (constant_evaluated()) {
            const auto r = static_cast<compile_time::real>(x);
            if (!(r >= -1 && r <= 1)) return quiet_nan<T>();
            return static_cast<T>(compile_time::atan2(r, compile_time::sqrt((1 - r) * (1 + r))));
        }
        if constexpr (std::is_same_v<T, float>) {
            return __builtin_asinf(x);
        } else if constexpr (std::is_same_v<T, double>) {
            return __builtin_asin(x);
        } else {
            return __builtin_asinl(x);
        }
    } else {
        using adl_only::asin;
        return asin(x);
    }
}

/// |x|.
template <class T>
[[nodiscard]] constexpr T abs(T x) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        if (constant_evaluated()) return x < 0 ? -x : (x == 0 ? T(0) : x);
        if constexpr (std::is_same_v<T, float>) {
            return __builtin_fabsf(x);
        } else if constexpr (std::is_same_v<T, double>) {
            return __builtin_fabs(x);
        } else {
            return __builtin_fabsl(x);
        }
    } else {
        using adl_only::abs;
        return abs(x);
    }
}

/// True unless x is NaN or infinite.
template <class T>
[[nodiscard]] constexpr bool is_finite(T x) noexcept {
    return x == x && abs(x) <= largest<T>();
}

/// pi in the scalar type T; a function, not a variable template, so that a scalar type without
/// constexpr constructors works too (the public constants are quat::pi and quat::pi_v<T>).
template <class T>
[[nodiscard]] constexpr T pi() noexcept {
    return T(3.14159265358979323846264338327950288L);
}

/// T itself, in a context where it is not deduced (std::type_identity_t in C++20): a scalar beside
/// a quat type converts to that type's T instead of deducing a second, conflicting T.
template <class T>
struct type_identity {
    using type = T;
};
template <class T>
using type_identity_t = typename type_identity<T>::type;

/// The scalar type of a factory called with an angle of type T: double for integers (as std::sin
/// does), T otherwise.
template <class T>
using real_t = std::conditional_t<std::is_integral_v<T>, double, T>;

/// The larger of two values (NaN-propagation is not needed where it is used).
template <class T>
[[nodiscard]] constexpr T max(T a, T b) noexcept {
    return a < b ? b : a;
}

// Small angles. Near zero the closed forms below divide a zero by a zero, and a dual-number scalar
// (forward-mode differentiation) takes the derivative of x = sqrt(x^2) at 0 as 0/0 = NaN even where
// the function is smooth. So below x^4 < epsilon each is a series in x^2, which a dual number
// differentiates exactly, and x itself is not read there; two terms leave the first omitted one
// below epsilon^1.5 relative, and its derivative below epsilon relative to the function's.

/// cos x and sin(x) / x.
template <class T>
struct cos_and_sinc {
    T cos, sinc;
};

/// True where the two-term series below are exact to rounding: x2^2 < epsilon.
template <class T>
[[nodiscard]] constexpr bool series_suffices(T x2) noexcept {
    return x2 * x2 < epsilon<T>();
}

/// cos x and sin(x) / x for x = sqrt(x2) >= 0, given both x2 and x; x is read only where
/// series_suffices(x2) is false (a NaN or infinite x2 gives NaN, through cos and sin).
template <class T>
[[nodiscard]] constexpr cos_and_sinc<T> cos_sinc(T x2, T x) noexcept {
    if (series_suffices(x2))
        return {T(1) - x2 / T(2) + x2 * x2 / T(24), T(1) - x2 / T(6) + x2 * x2 / T(120)};
    return {cos(x), sin(x) / x};
}

/// True where w > 0 and r = sqrt(s2) / w has r^4 < epsilon, so that atan_ratio_series(s2 / w^2)
/// is exact to rounding: series_suffices(s2 / w^2) without the division where it is false.
template <class T>
[[nodiscard]] constexpr bool atan_series_suffices(T s2, T w) noexcept {
    const T w2 = w * w;
    return w > T(0) && s2 * s2 < epsilon<T>() * (w2 * w2);
}

/// atan(r) / r = 1 - r^2/3 + r^4/5 - ..., given r2 = r^2 with series_suffices(r2).
template <class T>
[[nodiscard]] constexpr T atan_ratio_series(T r2) noexcept {
    return T(1) - r2 / T(3) + r2 * r2 / T(5);
}

/// asin(x) / x = 1 + x^2/6 + 3 x^4/40 + ..., given x2 = x^2 with series_suffices(x2).
template <class T>
[[nodiscard]] constexpr T asin_ratio_series(T x2) noexcept {
    return T(1) + x2 / T(6) + x2 * x2 * T(3) / T(40);
}

namespace compile_time {

/// a b as high + low exactly (Dekker's product with Veltkamp's split, no fma), usable in constant
/// evaluation. Precondition: |a| and |b| far enough below max() that the split does not overflow.
template <class T>
struct exact_product {
    T high, low;
};
template <class T>
[[nodiscard]] constexpr T split_high(T a) noexcept {
    constexpr T factor = T((1ULL << ((std::numeric_limits<T>::digits + 1) / 2)) + 1);
    const T scaled = factor * a;
    return scaled - (scaled - a);
}
template <class T>
[[nodiscard]] constexpr exact_product<T> two_product(T a, T b) noexcept {
    const T p = a * b;
    const T a_high = split_high(a), a_low = a - a_high;
    const T b_high = split_high(b), b_low = b - b_high;
    return {p, ((a_high * b_high - p) + a_high * b_low + a_low * b_high) + a_low * b_low};
}

}  // namespace compile_time

/// True where fma is a fused instruction rather than a library call (FP_FAST_FMA and FP_FAST_FMAL
/// from <cmath>, defined by compilers that target FMA hardware, e.g. -march=haswell). It differs
/// between -m flags, as the code of difference_of_products does: keyed, as is all of this file.
template <class T>
inline constexpr bool fast_fma =
#if defined(FP_FAST_FMA)
    std::is_same_v<T, double> ||
#endif
#if defined(FP_FAST_FMAL)
    std::is_same_v<T, long double> ||
#endif
    false;

/// a b - c d without the cancellation of the naive formula, within 2 units of roundoff of the exact
/// value however much the products cancel. float: the products are exact in double, which rounds
/// once, then float once more. Others, where fma is an instruction: Kahan's algorithm, w = c d
/// rounded, e = w - c d exactly, result fma(a, b, -w) + e (Jeannerod, Louvet and Muller, "Further
/// analysis of Kahan's algorithm for the accurate computation of 2x2 determinants", Math. Comp. 82,
/// 2013). Elsewhere, and during constant evaluation (std::fma is not constexpr), the products are
/// split exactly (Dekker) and the high and low parts subtracted separately. Preconditions: no
/// product overflows or underflows, |a|, |b|, |c|, |d| below max() / 2^33. A user scalar gets the
/// plain a b - c d.
template <class T>
[[nodiscard]] constexpr T difference_of_products(T a, T b, T c, T d) noexcept {
    if constexpr (std::is_same_v<T, float>) {
        return static_cast<float>(static_cast<double>(a) * static_cast<double>(b) -
                                  static_cast<double>(c) * static_cast<double>(d));
    } else if constexpr (std::is_floating_point_v<T>) {
        if constexpr (fast_fma<T>) {
            if (!constant_evaluated()) {
                const T w = c * d;
                if constexpr (std::is_same_v<T, double>) {
                    const T e = __builtin_fma(-c, d, w);
                    return __builtin_fma(a, b, -w) + e;
                } else {
                    const T e = __builtin_fmal(-c, d, w);
                    return __builtin_fmal(a, b, -w) + e;
                }
            }
        }
        const compile_time::exact_product<T> ab = compile_time::two_product(a, b);
        const compile_time::exact_product<T> cd = compile_time::two_product(c, d);
        return (ab.high - cd.high) + (ab.low - cd.low);
    } else {
        return a * b - c * d;
    }
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_DETAIL_MATH_HPP_INCLUDED
