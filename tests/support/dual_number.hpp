// A minimal forward-mode dual number: a value and N partial derivatives, each operation applying
// the chain rule. It offers exactly what quat asks of a user scalar (README, docs/api.md "Generic
// scalars"): explicit construction from numbers, the arithmetic and comparison operators,
// std::numeric_limits, and sqrt, sin, cos, atan2, asin, abs, exp and log found by
// argument-dependent lookup. Comparisons look at the value only, as ceres::Jet's do.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

namespace quat::test {

template <class T, std::size_t N>
struct dual {
    T value{};
    std::array<T, N> d{};  ///< d[i] = d value / d input i

    constexpr dual() noexcept = default;
    template <class A, std::enable_if_t<std::is_arithmetic_v<A>, int> = 0>
    constexpr explicit dual(A v) noexcept : value(static_cast<T>(v)) {}

    /// Input number i of N, with value v: its only partial is d[i] = 1.
    static constexpr dual variable(T v, std::size_t i) noexcept {
        dual x(v);
        x.d[i] = T(1);
        return x;
    }
};

/// value and partials (f(x), f'(x) x.d): the chain rule for a function of one argument.
template <class T, std::size_t N>
constexpr dual<T, N> chain(const dual<T, N>& x, T value, T derivative) noexcept {
    dual<T, N> r(value);
    for (std::size_t i = 0; i < N; ++i) r.d[i] = derivative * x.d[i];
    return r;
}

template <class T, std::size_t N>
constexpr dual<T, N> operator-(const dual<T, N>& a) noexcept {
    return chain(a, -a.value, T(-1));
}
template <class T, std::size_t N>
constexpr dual<T, N> operator+(const dual<T, N>& a, const dual<T, N>& b) noexcept {
    dual<T, N> r(a.value + b.value);
    for (std::size_t i = 0; i < N; ++i) r.d[i] = a.d[i] + b.d[i];
    return r;
}
template <class T, std::size_t N>
constexpr dual<T, N> operator-(const dual<T, N>& a, const dual<T, N>& b) noexcept {
    dual<T, N> r(a.value - b.value);
    for (std::size_t i = 0; i < N; ++i) r.d[i] = a.d[i] - b.d[i];
    return r;
}
template <class T, std::size_t N>
constexpr dual<T, N> operator*(const dual<T, N>& a, const dual<T, N>& b) noexcept {
    dual<T, N> r(a.value * b.value);
    for (std::size_t i = 0; i < N; ++i) r.d[i] = a.d[i] * b.value + a.value * b.d[i];
    return r;
}
template <class T, std::size_t N>
constexpr dual<T, N> operator/(const dual<T, N>& a, const dual<T, N>& b) noexcept {
    const T q = a.value / b.value;
    dual<T, N> r(q);
    for (std::size_t i = 0; i < N; ++i) r.d[i] = (a.d[i] - q * b.d[i]) / b.value;
    return r;
}
template <class T, std::size_t N>
constexpr dual<T, N>& operator+=(dual<T, N>& a, const dual<T, N>& b) noexcept {
    return a = a + b;
}
template <class T, std::size_t N>
constexpr dual<T, N>& operator-=(dual<T, N>& a, const dual<T, N>& b) noexcept {
    return a = a - b;
}

template <class T, std::size_t N>
constexpr bool operator<(const dual<T, N>& a, const dual<T, N>& b) noexcept {
    return a.value < b.value;
}
template <class T, std::size_t N>
constexpr bool operator<=(const dual<T, N>& a, const dual<T, N>& b) noexcept {
    return a.value <= b.value;
}
template <class T, std::size_t N>
constexpr bool operator>(const dual<T, N>& a, const dual<T, N>& b) noexcept {
    return a.value > b.value;
}
template <class T, std::size_t N>
constexpr bool operator>=(const dual<T, N>& a, const dual<T, N>& b) noexcept {
    return a.value >= b.value;
}
template <class T, std::size_t N>
constexpr bool operator==(const dual<T, N>& a, const dual<T, N>& b) noexcept {
    return a.value == b.value;
}
template <class T, std::size_t N>
constexpr bool operator!=(const dual<T, N>& a, const dual<T, N>& b) noexcept {
    return a.value != b.value;
}

// The elementary functions: at a point where the function is not differentiable (sqrt(0), asin(1),
// abs(0)) the partials are what the formula gives (Inf or NaN for sqrt and asin), as ceres::Jet's.
template <class T, std::size_t N>
dual<T, N> sqrt(const dual<T, N>& x) noexcept {
    const T r = std::sqrt(x.value);
    return chain(x, r, T(0.5) / r);
}
template <class T, std::size_t N>
dual<T, N> sin(const dual<T, N>& x) noexcept {
    return chain(x, std::sin(x.value), std::cos(x.value));
}
template <class T, std::size_t N>
dual<T, N> cos(const dual<T, N>& x) noexcept {
    return chain(x, std::cos(x.value), -std::sin(x.value));
}
template <class T, std::size_t N>
dual<T, N> asin(const dual<T, N>& x) noexcept {
    return chain(x, std::asin(x.value), T(1) / std::sqrt((T(1) - x.value) * (T(1) + x.value)));
}
template <class T, std::size_t N>
dual<T, N> abs(const dual<T, N>& x) noexcept {
    return chain(x, std::abs(x.value), x.value < T(0) ? T(-1) : T(1));
}
template <class T, std::size_t N>
dual<T, N> exp(const dual<T, N>& x) noexcept {
    const T e = std::exp(x.value);
    return chain(x, e, e);
}
template <class T, std::size_t N>
dual<T, N> log(const dual<T, N>& x) noexcept {
    return chain(x, std::log(x.value), T(1) / x.value);
}
/// d atan2(y, x) = (x dy - y dx) / (x^2 + y^2).
template <class T, std::size_t N>
dual<T, N> atan2(const dual<T, N>& y, const dual<T, N>& x) noexcept {
    const T r2 = x.value * x.value + y.value * y.value;
    dual<T, N> r(std::atan2(y.value, x.value));
    for (std::size_t i = 0; i < N; ++i) r.d[i] = (x.value * y.d[i] - y.value * x.d[i]) / r2;
    return r;
}

}  // namespace quat::test

/// The limits of the value type, with zero partials.
template <class T, std::size_t N>
struct std::numeric_limits<quat::test::dual<T, N>> {
    using D = quat::test::dual<T, N>;
    static constexpr bool is_specialized = true;
    static constexpr D epsilon() noexcept { return D(std::numeric_limits<T>::epsilon()); }
    static constexpr D min() noexcept { return D(std::numeric_limits<T>::min()); }
    static constexpr D max() noexcept { return D(std::numeric_limits<T>::max()); }
    static constexpr D infinity() noexcept { return D(std::numeric_limits<T>::infinity()); }
    static constexpr D quiet_NaN() noexcept { return D(std::numeric_limits<T>::quiet_NaN()); }
};
