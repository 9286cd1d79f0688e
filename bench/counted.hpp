// quat::counted<T>: a scalar that behaves like T and counts the floating-point operations done on
// it, so the thesis's operation-count tables (3.1) can be measured on the library's own templates.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace quat {

/// Operation tallies. A fused multiply-add counts as one addition and one multiplication;
/// negation, abs, copysign and comparisons are free (sign flips and tests, not arithmetic).
struct operation_counts {
    std::int64_t add = 0;   ///< additions and subtractions
    std::int64_t mul = 0;   ///< multiplications
    std::int64_t div = 0;   ///< divisions
    std::int64_t sqrt = 0;  ///< square roots
    std::int64_t trig = 0;  ///< sin, cos, atan2, asin, acos

    friend bool operator==(const operation_counts& a, const operation_counts& b) noexcept {
        return a.add == b.add && a.mul == b.mul && a.div == b.div && a.sqrt == b.sqrt &&
               a.trig == b.trig;
    }
};

namespace detail {
// One tally per thread, so counting in one thread never sees another's work.
inline thread_local operation_counts counted_tally{};
}  // namespace detail

/// The operations counted since the last reset_counts() on this thread.
[[nodiscard]] inline operation_counts counts() noexcept { return detail::counted_tally; }
/// Sets this thread's tallies to zero.
inline void reset_counts() noexcept { detail::counted_tally = {}; }

/// A T that counts its arithmetic. Construct explicitly from numbers; read the value with .value.
template <class T>
struct counted {
    T value;

    constexpr counted() noexcept : value() {}
    template <class U, class = std::enable_if_t<std::is_arithmetic_v<U>>>
    constexpr explicit counted(U v) noexcept : value(static_cast<T>(v)) {}

    friend counted operator-(counted a) noexcept { return counted(-a.value); }
    friend counted operator+(counted a, counted b) noexcept {
        return ++detail::counted_tally.add, counted(a.value + b.value);
    }
    friend counted operator-(counted a, counted b) noexcept {
        return ++detail::counted_tally.add, counted(a.value - b.value);
    }
    friend counted operator*(counted a, counted b) noexcept {
        return ++detail::counted_tally.mul, counted(a.value * b.value);
    }
    friend counted operator/(counted a, counted b) noexcept {
        return ++detail::counted_tally.div, counted(a.value / b.value);
    }
    friend counted& operator+=(counted& a, counted b) noexcept { return a = a + b; }
    friend counted& operator-=(counted& a, counted b) noexcept { return a = a - b; }
    friend counted& operator*=(counted& a, counted b) noexcept { return a = a * b; }
    friend counted& operator/=(counted& a, counted b) noexcept { return a = a / b; }
    friend bool operator<(counted a, counted b) noexcept { return a.value < b.value; }
    friend bool operator<=(counted a, counted b) noexcept { return a.value <= b.value; }
    friend bool operator>(counted a, counted b) noexcept { return a.value > b.value; }
    friend bool operator>=(counted a, counted b) noexcept { return a.value >= b.value; }
    friend bool operator==(counted a, counted b) noexcept { return a.value == b.value; }
    friend bool operator!=(counted a, counted b) noexcept { return a.value != b.value; }

    // Found by argument-dependent lookup from quat's templates (`using std::sqrt; sqrt(x)`).
    friend counted sqrt(counted a) noexcept {
        return ++detail::counted_tally.sqrt, counted(std::sqrt(a.value));
    }
    friend counted sin(counted a) noexcept {
        return ++detail::counted_tally.trig, counted(std::sin(a.value));
    }
    friend counted cos(counted a) noexcept {
        return ++detail::counted_tally.trig, counted(std::cos(a.value));
    }
    friend counted asin(counted a) noexcept {
        return ++detail::counted_tally.trig, counted(std::asin(a.value));
    }
    friend counted acos(counted a) noexcept {
        return ++detail::counted_tally.trig, counted(std::acos(a.value));
    }
    friend counted atan2(counted y, counted x) noexcept {
        return ++detail::counted_tally.trig, counted(std::atan2(y.value, x.value));
    }
    friend counted abs(counted a) noexcept { return counted(std::abs(a.value)); }
    friend counted copysign(counted a, counted b) noexcept {
        return counted(std::copysign(a.value, b.value));
    }
    friend counted fma(counted a, counted b, counted c) noexcept {
        ++detail::counted_tally.add;
        ++detail::counted_tally.mul;
        return counted(std::fma(a.value, b.value, c.value));
    }
};

}  // namespace quat

/// Limits of counted<T> are those of T.
template <class T>
struct std::numeric_limits<quat::counted<T>> {
    static constexpr bool is_specialized = true;
    static constexpr bool is_signed = true;
    static constexpr bool is_integer = false;
    static constexpr bool is_exact = false;
    static constexpr bool has_infinity = std::numeric_limits<T>::has_infinity;
    static constexpr bool has_quiet_NaN = std::numeric_limits<T>::has_quiet_NaN;
    static constexpr int digits = std::numeric_limits<T>::digits;
    static constexpr quat::counted<T> epsilon() noexcept {
        return quat::counted<T>(std::numeric_limits<T>::epsilon());
    }
    static constexpr quat::counted<T> min() noexcept {
        return quat::counted<T>(std::numeric_limits<T>::min());
    }
    static constexpr quat::counted<T> max() noexcept {
        return quat::counted<T>(std::numeric_limits<T>::max());
    }
    static constexpr quat::counted<T> lowest() noexcept {
        return quat::counted<T>(std::numeric_limits<T>::lowest());
    }
    static constexpr quat::counted<T> infinity() noexcept {
        return quat::counted<T>(std::numeric_limits<T>::infinity());
    }
    static constexpr quat::counted<T> quiet_NaN() noexcept {
        return quat::counted<T>(std::numeric_limits<T>::quiet_NaN());
    }
};
