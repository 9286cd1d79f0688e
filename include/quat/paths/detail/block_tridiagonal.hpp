// The block tridiagonal solve behind rotation_spline's rates, on 3x3 blocks (matrix3).
#ifndef QUAT_PATHS_DETAIL_BLOCK_TRIDIAGONAL_HPP_INCLUDED
#define QUAT_PATHS_DETAIL_BLOCK_TRIDIAGONAL_HPP_INCLUDED

#include <cstddef>

#include "../../matrix.hpp"
#include "../../vec3.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

/// u v^T
template <class T>
[[nodiscard]] constexpr matrix3<T> outer(const vec3<T>& u, const vec3<T>& v) noexcept {
    return {{{u.x * v.x, u.x * v.y, u.x * v.z},
             {u.y * v.x, u.y * v.y, u.y * v.z},
             {u.z * v.x, u.z * v.y, u.z * v.z}}};
}

/// The inverse by cofactors; the blocks it is used on are diagonally dominant.
template <class T>
[[nodiscard]] constexpr matrix3<T> inverse(const matrix3<T>& a) noexcept {
    const auto& m = a.elements;
    const matrix3<T> c{
        {{m[1][1] * m[2][2] - m[1][2] * m[2][1], m[0][2] * m[2][1] - m[0][1] * m[2][2],
          m[0][1] * m[1][2] - m[0][2] * m[1][1]},
         {m[1][2] * m[2][0] - m[1][0] * m[2][2], m[0][0] * m[2][2] - m[0][2] * m[2][0],
          m[0][2] * m[1][0] - m[0][0] * m[1][2]},
         {m[1][0] * m[2][1] - m[1][1] * m[2][0], m[0][1] * m[2][0] - m[0][0] * m[2][1],
          m[0][0] * m[1][1] - m[0][1] * m[1][0]}}};
    const T determinant = m[0][0] * c(0, 0) + m[0][1] * c(1, 0) + m[0][2] * c(2, 0);
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
