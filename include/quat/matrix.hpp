// Small fixed-size matrices for Jacobians and covariances: matrix<T, Rows, Cols>. Not a linear
// algebra library: products, sums, transposes and blocks, enough to chain the Jacobians of the
// Lie-group functions (lie/so3.hpp, lie/se3.hpp) and to hand them to Eigen (interop/eigen.hpp) or
// Ceres.
#ifndef QUAT_MATRIX_HPP_INCLUDED
#define QUAT_MATRIX_HPP_INCLUDED

#include <cstddef>

#include "config.hpp"
#include "detail/math.hpp"
#include "rotation_matrix.hpp"
#include "vec3.hpp"

namespace quat {

/// A Rows x Cols matrix stored row-major; vectors multiply it as columns, v' = M v. Any scalar the
/// rest of quat accepts, automatic-differentiation scalars included.
template <class T, int Rows, int Cols>
struct matrix {
    static_assert(Rows > 0 && Cols > 0, "quat::matrix: empty matrices are not supported");
    /// Row-major: elements[row][col]. matrix<T, R, C>{} is zero; matrix<T, R, C> m; leaves the
    /// elements uninitialized, as in a plain struct.
    T elements[static_cast<std::size_t>(Rows)][static_cast<std::size_t>(Cols)];

    /// Element at (row, col), row in [0, Rows) and col in [0, Cols).
    [[nodiscard]] [[gnu::always_inline]] constexpr T& operator()(int row, int col) noexcept {
        QUAT_ASSERT(row >= 0 && row < Rows && col >= 0 && col < Cols, "matrix index out of range");
        return elements[row][col];
    }
    /// Element at (row, col), read-only.
    [[nodiscard]] [[gnu::always_inline]] constexpr const T& operator()(int row,
                                                                       int col) const noexcept {
        QUAT_ASSERT(row >= 0 && row < Rows && col >= 0 && col < Cols, "matrix index out of range");
        return elements[row][col];
    }

    /// The matrix of zeros.
    [[nodiscard]] [[gnu::always_inline]] static constexpr matrix zero() noexcept {
        matrix m{};
        for (int i = 0; i < Rows; ++i)
            for (int j = 0; j < Cols; ++j) m.elements[i][j] = T(0);
        return m;
    }
    /// The identity (ones on the diagonal, zeros elsewhere; square or not).
    [[nodiscard]] [[gnu::always_inline]] static constexpr matrix identity() noexcept {
        matrix m = zero();
        for (int i = 0; i < (Rows < Cols ? Rows : Cols); ++i) m.elements[i][i] = T(1);
        return m;
    }
};

/// A 3x3 matrix: Jacobians and covariances on SO(3)'s tangent space (rotation vectors). A rotation
/// is a rotation_matrix; to_matrix3 and to_rotation_matrix convert between the two.
template <class T>
using matrix3 = matrix<T, 3, 3>;
/// A 6x6 matrix: Jacobians and covariances on SE(3)'s tangent space (twists, linear part first).
template <class T>
using matrix6 = matrix<T, 6, 6>;

#include "detail/isa_namespace.inc"
/// The same 3x3 numbers as a general matrix: to chain a rotation with Jacobians. The inverse of
/// to_rotation_matrix; the two types do not convert implicitly.
template <class T>
[[nodiscard]] constexpr matrix3<T> to_matrix3(const rotation_matrix<T>& m) noexcept {
    matrix3<T> out{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out(i, j) = m(i, j);
    return out;
}

/// The same 3x3 numbers as a rotation_matrix, the inverse of to_matrix3: for a matrix the caller
/// knows to be a rotation (R(q) = so3::adjoint(q), say), or one to hand to nearest_rotation or
/// try_to_quaternion, which accept any 3x3 matrix. Nothing is checked: a rotation_matrix that is
/// not a rotation breaks the preconditions of the functions that expect one.
template <class T>
[[nodiscard]] constexpr rotation_matrix<T> to_rotation_matrix(const matrix3<T>& m) noexcept {
    return {
        {{m(0, 0), m(0, 1), m(0, 2)}, {m(1, 0), m(1, 1), m(1, 2)}, {m(2, 0), m(2, 1), m(2, 2)}}};
}

/// Element-wise sum.
template <class T, int R, int C>
[[nodiscard]] constexpr matrix<T, R, C> operator+(const matrix<T, R, C>& a,
                                                  const matrix<T, R, C>& b) noexcept {
    matrix<T, R, C> out{};
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j) out(i, j) = a(i, j) + b(i, j);
    return out;
}

/// Element-wise difference.
template <class T, int R, int C>
[[nodiscard]] constexpr matrix<T, R, C> operator-(const matrix<T, R, C>& a,
                                                  const matrix<T, R, C>& b) noexcept {
    matrix<T, R, C> out{};
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j) out(i, j) = a(i, j) - b(i, j);
    return out;
}

/// Element-wise negation.
template <class T, int R, int C>
[[nodiscard]] constexpr matrix<T, R, C> operator-(const matrix<T, R, C>& a) noexcept {
    matrix<T, R, C> out{};
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j) out(i, j) = -a(i, j);
    return out;
}

/// Every element times s.
template <class T, int R, int C>
[[nodiscard]] constexpr matrix<T, R, C> operator*(const matrix<T, R, C>& a,
                                                  detail::type_identity_t<T> s) noexcept {
    matrix<T, R, C> out{};
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j) out(i, j) = a(i, j) * s;
    return out;
}

/// Every element times s.
template <class T, int R, int C>
[[nodiscard]] constexpr matrix<T, R, C> operator*(detail::type_identity_t<T> s,
                                                  const matrix<T, R, C>& a) noexcept {
    return a * s;
}

/// Matrix product: (a b) v = a (b v).
template <class T, int R, int K, int C>
[[nodiscard]] constexpr matrix<T, R, C> operator*(const matrix<T, R, K>& a,
                                                  const matrix<T, K, C>& b) noexcept {
    matrix<T, R, C> out{};
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j) {
            T sum = a(i, 0) * b(0, j);
            for (int k = 1; k < K; ++k) sum = sum + a(i, k) * b(k, j);
            out(i, j) = sum;
        }
    return out;
}

/// M v for a 3x3 matrix.
template <class T>
[[nodiscard]] constexpr vec3<T> operator*(const matrix3<T>& m, const vec3<T>& v) noexcept {
    return {m(0, 0) * v.x + m(0, 1) * v.y + m(0, 2) * v.z,
            m(1, 0) * v.x + m(1, 1) * v.y + m(1, 2) * v.z,
            m(2, 0) * v.x + m(2, 1) * v.y + m(2, 2) * v.z};
}

/// a = a + b.
template <class T, int R, int C>
constexpr matrix<T, R, C>& operator+=(matrix<T, R, C>& a, const matrix<T, R, C>& b) noexcept {
    return a = a + b;
}

/// a = a - b.
template <class T, int R, int C>
constexpr matrix<T, R, C>& operator-=(matrix<T, R, C>& a, const matrix<T, R, C>& b) noexcept {
    return a = a - b;
}

/// Exact element-wise equality.
template <class T, int R, int C>
[[nodiscard]] constexpr bool operator==(const matrix<T, R, C>& a,
                                        const matrix<T, R, C>& b) noexcept {
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j)
            if (!(a(i, j) == b(i, j))) return false;
    return true;
}

/// Negation of ==.
template <class T, int R, int C>
[[nodiscard]] constexpr bool operator!=(const matrix<T, R, C>& a,
                                        const matrix<T, R, C>& b) noexcept {
    return !(a == b);
}

/// The transpose: element (i, j) moves to (j, i).
template <class T, int R, int C>
[[nodiscard]] constexpr matrix<T, C, R> transpose(const matrix<T, R, C>& m) noexcept {
    matrix<T, C, R> out{};
    for (int i = 0; i < R; ++i)
        for (int j = 0; j < C; ++j) out(j, i) = m(i, j);
    return out;
}

/// The BR x BC block of m whose top-left element is m(row, col). Precondition: the block lies
/// inside m (checked when both are constants, otherwise debug-checked).
template <int BR, int BC, class T, int R, int C>
[[nodiscard]] constexpr matrix<T, BR, BC> block(const matrix<T, R, C>& m, int row,
                                                int col) noexcept {
    static_assert(BR <= R && BC <= C, "quat::block: the block is larger than the matrix");
    QUAT_ASSERT(row >= 0 && col >= 0 && row + BR <= R && col + BC <= C,
                "quat::block: the block does not lie inside the matrix");
    matrix<T, BR, BC> out{};
    for (int i = 0; i < BR; ++i)
        for (int j = 0; j < BC; ++j) out(i, j) = m(row + i, col + j);
    return out;
}

/// Writes b into m with b's top-left element at m(row, col). Precondition: as for block.
template <class T, int R, int C, int BR, int BC>
constexpr void set_block(matrix<T, R, C>& m, int row, int col,
                         const matrix<T, BR, BC>& b) noexcept {
    static_assert(BR <= R && BC <= C, "quat::set_block: the block is larger than the matrix");
    QUAT_ASSERT(row >= 0 && col >= 0 && row + BR <= R && col + BC <= C,
                "quat::set_block: the block does not lie inside the matrix");
    for (int i = 0; i < BR; ++i)
        for (int j = 0; j < BC; ++j) m(row + i, col + j) = b(i, j);
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_MATRIX_HPP_INCLUDED
