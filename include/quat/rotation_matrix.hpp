// 3x3 rotation matrices acting on column vectors.
#ifndef QUAT_ROTATION_MATRIX_HPP_INCLUDED
#define QUAT_ROTATION_MATRIX_HPP_INCLUDED

#include "config.hpp"
#include "detail/math.hpp"
#include "vec3.hpp"

namespace quat {

/// 3x3 matrix stored row-major, acting on column vectors: v' = M v. Used for rotations (orthogonal,
/// determinant +1); nearest_rotation and try_to_quaternion also accept any 3x3 matrix in it.
template <class T>
struct rotation_matrix {
    /// Row-major: elements[row][col].
    /// @{
    T elements[3][3];
    /// @}

    /// Elements left uninitialized, as in a plain struct; rotation_matrix<T>{} is zero.
    rotation_matrix() = default;
    /// The matrix with the given rows: rotation_matrix<T>{{{m00, m01, m02}, {m10, ...}, {...}}}.
    [[gnu::always_inline]] constexpr rotation_matrix(const T (&rows)[3][3]) noexcept
        : elements{{rows[0][0], rows[0][1], rows[0][2]},
                   {rows[1][0], rows[1][1], rows[1][2]},
                   {rows[2][0], rows[2][1], rows[2][2]}} {}
    /// Conversion from another precision, element by element: rotation_matrix<float>{md}.
    template <class U>
    [[gnu::always_inline]] constexpr explicit rotation_matrix(const rotation_matrix<U>& m) noexcept
        : elements{{static_cast<T>(m.elements[0][0]), static_cast<T>(m.elements[0][1]),
                    static_cast<T>(m.elements[0][2])},
                   {static_cast<T>(m.elements[1][0]), static_cast<T>(m.elements[1][1]),
                    static_cast<T>(m.elements[1][2])},
                   {static_cast<T>(m.elements[2][0]), static_cast<T>(m.elements[2][1]),
                    static_cast<T>(m.elements[2][2])}} {}

    /// Element at (row, col), both in [0, 3).
    [[nodiscard]] [[gnu::always_inline]] constexpr T& operator()(int row, int col) noexcept {
        QUAT_ASSERT(row >= 0 && row < 3 && col >= 0 && col < 3, "matrix index out of range");
        return elements[row][col];
    }
    /// Element at (row, col), read-only.
    [[nodiscard]] [[gnu::always_inline]] constexpr const T& operator()(int row,
                                                                       int col) const noexcept {
        QUAT_ASSERT(row >= 0 && row < 3 && col >= 0 && col < 3, "matrix index out of range");
        return elements[row][col];
    }

    /// The rotation by zero angle.
    [[nodiscard]] [[gnu::always_inline]] static constexpr rotation_matrix identity() noexcept {
        return {{{T(1), T(0), T(0)}, {T(0), T(1), T(0)}, {T(0), T(0), T(1)}}};
    }
    /// The matrix whose rows are r0, r1, r2.
    [[nodiscard]] [[gnu::always_inline]] static constexpr rotation_matrix from_rows(
        const vec3<T>& r0, const vec3<T>& r1, const vec3<T>& r2) noexcept {
        return {{{r0.x, r0.y, r0.z}, {r1.x, r1.y, r1.z}, {r2.x, r2.y, r2.z}}};
    }
    /// The matrix whose columns are c0, c1, c2: for a rotation, the images of the x, y and z axes.
    [[nodiscard]] [[gnu::always_inline]] static constexpr rotation_matrix from_columns(
        const vec3<T>& c0, const vec3<T>& c1, const vec3<T>& c2) noexcept {
        return {{{c0.x, c1.x, c2.x}, {c0.y, c1.y, c2.y}, {c0.z, c1.z, c2.z}}};
    }
};

#include "detail/isa_namespace.inc"
/// Row i (0, 1 or 2) of m.
template <class T>
[[nodiscard]] constexpr vec3<T> row(const rotation_matrix<T>& m, int i) noexcept {
    return {m(i, 0), m(i, 1), m(i, 2)};
}

/// Column j (0, 1 or 2) of m: for a rotation, the image of axis j.
template <class T>
[[nodiscard]] constexpr vec3<T> column(const rotation_matrix<T>& m, int j) noexcept {
    return {m(0, j), m(1, j), m(2, j)};
}

/// Matrix product: as rotations, a * b applies b first, then a.
template <class T>
[[nodiscard]] constexpr rotation_matrix<T> operator*(const rotation_matrix<T>& a,
                                                     const rotation_matrix<T>& b) noexcept {
    const auto entry = [&a, &b](int i, int j) {
        return a(i, 0) * b(0, j) + a(i, 1) * b(1, j) + a(i, 2) * b(2, j);
    };
    return {{{entry(0, 0), entry(0, 1), entry(0, 2)},
             {entry(1, 0), entry(1, 1), entry(1, 2)},
             {entry(2, 0), entry(2, 1), entry(2, 2)}}};
}

/// a = a * b: as rotations, b is applied first, then the old a.
template <class T>
constexpr rotation_matrix<T>& operator*=(rotation_matrix<T>& a,
                                         const rotation_matrix<T>& b) noexcept {
    return a = a * b;
}

/// Exact element-wise equality.
template <class T>
[[nodiscard]] constexpr bool operator==(const rotation_matrix<T>& a,
                                        const rotation_matrix<T>& b) noexcept {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (!(a(i, j) == b(i, j))) return false;
    return true;
}
/// Negation of ==.
template <class T>
[[nodiscard]] constexpr bool operator!=(const rotation_matrix<T>& a,
                                        const rotation_matrix<T>& b) noexcept {
    return !(a == b);
}

/// M v: rotates v by the rotation matrix m.
template <class T>
[[nodiscard]] constexpr vec3<T> rotate(const rotation_matrix<T>& m, const vec3<T>& v) noexcept {
    return {m(0, 0) * v.x + m(0, 1) * v.y + m(0, 2) * v.z,
            m(1, 0) * v.x + m(1, 1) * v.y + m(1, 2) * v.z,
            m(2, 0) * v.x + m(2, 1) * v.y + m(2, 2) * v.z};
}

/// M v as the math writes it (GLM, Eigen, Sophus): the same as rotate(m, v).
template <class T>
[[nodiscard]] constexpr vec3<T> operator*(const rotation_matrix<T>& m, const vec3<T>& v) noexcept {
    return rotate(m, v);
}

/// Transpose; for a rotation, its inverse.
template <class T>
[[nodiscard]] constexpr rotation_matrix<T> transpose(const rotation_matrix<T>& m) noexcept {
    return rotation_matrix<T>::from_columns(row(m, 0), row(m, 1), row(m, 2));
}

/// Determinant: +1 for a rotation, -1 for a reflection.
template <class T>
[[nodiscard]] constexpr T determinant(const rotation_matrix<T>& m) noexcept {
    return dot(row(m, 0), cross(row(m, 1), row(m, 2)));
}

/// Largest |(M^T M - I)(i, j)|: zero for an exact rotation or reflection, NaN propagates.
template <class T>
[[nodiscard]] constexpr T orthogonality_error(const rotation_matrix<T>& m) noexcept {
    T worst = T(0);
    for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) {
            const T deviation =
                detail::abs(dot(column(m, i), column(m, j)) - (i == j ? T(1) : T(0)));
            if (deviation != deviation) return deviation;  // NaN in, NaN out
            if (worst < deviation) worst = deviation;
        }
    return worst;
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_ROTATION_MATRIX_HPP_INCLUDED
