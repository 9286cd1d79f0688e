// 3x3 matrices and the block tridiagonal solve behind rotation_spline's rates.
#ifndef QUAT_PATHS_DETAIL_BLOCK_TRIDIAGONAL_HPP_INCLUDED
#define QUAT_PATHS_DETAIL_BLOCK_TRIDIAGONAL_HPP_INCLUDED

#include <cstddef>

#include "../../vec3.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

template <class T>
struct matrix3 {
    T m[3][3];
};

/// a I + b [r]x + c [r]x^2, with [r]x v = r x v and [r]x^2 = r r^T - |r|^2 I.
template <class T>
[[nodiscard]] constexpr matrix3<T> skew_polynomial(const vec3<T>& r, T a, T b, T c) noexcept {
    const T v[3] = {r.x, r.y, r.z};
    const T n2 = squared_norm(r);
    matrix3<T> result{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) result.m[i][j] = c * v[i] * v[j];
    for (int i = 0; i < 3; ++i) result.m[i][i] += a - c * n2;
    result.m[0][1] -= b * v[2];
    result.m[0][2] += b * v[1];
    result.m[1][0] += b * v[2];
    result.m[1][2] -= b * v[0];
    result.m[2][0] -= b * v[1];
    result.m[2][1] += b * v[0];
    return result;
}

/// u v^T
template <class T>
[[nodiscard]] constexpr matrix3<T> outer(const vec3<T>& u, const vec3<T>& v) noexcept {
    return {{{u.x * v.x, u.x * v.y, u.x * v.z},
             {u.y * v.x, u.y * v.y, u.y * v.z},
             {u.z * v.x, u.z * v.y, u.z * v.z}}};
}

template <class T>
[[nodiscard]] constexpr matrix3<T> operator+(const matrix3<T>& a, const matrix3<T>& b) noexcept {
    matrix3<T> result{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) result.m[i][j] = a.m[i][j] + b.m[i][j];
    return result;
}

template <class T>
[[nodiscard]] constexpr matrix3<T> operator-(const matrix3<T>& a, const matrix3<T>& b) noexcept {
    matrix3<T> result{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) result.m[i][j] = a.m[i][j] - b.m[i][j];
    return result;
}

template <class T>
[[nodiscard]] constexpr matrix3<T> operator*(const matrix3<T>& a, T s) noexcept {
    matrix3<T> result{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) result.m[i][j] = a.m[i][j] * s;
    return result;
}

template <class T>
[[nodiscard]] constexpr matrix3<T> operator*(const matrix3<T>& a, const matrix3<T>& b) noexcept {
    matrix3<T> result{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            result.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
    return result;
}

template <class T>
[[nodiscard]] constexpr vec3<T> operator*(const matrix3<T>& a, const vec3<T>& v) noexcept {
    return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
            a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
            a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
}

/// The inverse by cofactors; the blocks it is used on are diagonally dominant.
template <class T>
[[nodiscard]] constexpr matrix3<T> inverse(const matrix3<T>& a) noexcept {
    const auto& m = a.m;
    matrix3<T> c{{{m[1][1] * m[2][2] - m[1][2] * m[2][1], m[0][2] * m[2][1] - m[0][1] * m[2][2],
                   m[0][1] * m[1][2] - m[0][2] * m[1][1]},
                  {m[1][2] * m[2][0] - m[1][0] * m[2][2], m[0][0] * m[2][2] - m[0][2] * m[2][0],
                   m[0][2] * m[1][0] - m[0][0] * m[1][2]},
                  {m[1][0] * m[2][1] - m[1][1] * m[2][0], m[0][1] * m[2][0] - m[0][0] * m[2][1],
                   m[0][0] * m[1][1] - m[0][1] * m[1][0]}}};
    const T determinant = m[0][0] * c.m[0][0] + m[0][1] * c.m[1][0] + m[0][2] * c.m[2][0];
    return c * (T(1) / determinant);
}

/// Solves the block tridiagonal system lower(k) x(k-1) + diagonal(k) x(k) + upper(k) x(k+1) = b(k)
/// for k in [0, count), with b coming in x(k) and the solution going out there, by block Gaussian
/// elimination without pivoting (the block Thomas algorithm), stable for block diagonally dominant
/// systems. lower and upper return blocks by value, diagonal and x references to storage that is
/// overwritten; lower(0) and upper(count - 1) are not called. count >= 1.
template <class Lower, class Diagonal, class Upper, class X>
constexpr void solve_block_tridiagonal(std::size_t count, Lower lower, Diagonal diagonal,
                                       Upper upper, X x) noexcept {
    for (std::size_t k = 0; k < count; ++k) {
        if (k > 0) {
            const auto factor = lower(k) * diagonal(k - 1);  // diagonal(k - 1) is inverted
            diagonal(k) = diagonal(k) - factor * upper(k - 1);
            x(k) -= factor * x(k - 1);
        }
        diagonal(k) = inverse(diagonal(k));
    }
    x(count - 1) = diagonal(count - 1) * x(count - 1);
    for (std::size_t k = count - 1; k-- > 0;) x(k) = diagonal(k) * (x(k) - upper(k) * x(k + 1));
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_PATHS_DETAIL_BLOCK_TRIDIAGONAL_HPP_INCLUDED
