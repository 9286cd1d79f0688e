// 4x4 homogeneous matrices of rigid motions, acting on column vectors (x, y, z, 1), and their
// conversions to and from dual quaternions.
#ifndef QUAT_RIGID_HOMOGENEOUS_MATRIX_HPP_INCLUDED
#define QUAT_RIGID_HOMOGENEOUS_MATRIX_HPP_INCLUDED

#include <optional>
#include <type_traits>

#include "../config.hpp"
#include "../conversions.hpp"
#include "../detail/math.hpp"
#include "../quaternion.hpp"
#include "../rotation_matrix.hpp"
#include "../vec3.hpp"
#include "dual_quaternion.hpp"

namespace quat {

/// 4x4 matrix stored row-major, acting on column vectors (x, y, z, 1): for a rigid motion the upper
/// left 3x3 block is the rotation, the last column's first three entries the translation, and the
/// last row (0, 0, 0, 1). The thesis (its section 2.2) puts the homogeneous coordinate first
/// instead; docs/thesis-notes.md maps one layout to the other.
template <class T>
struct homogeneous_matrix {
    /// Row-major: elements[row][col].
    /// @{
    T elements[4][4];
    /// @}

    /// Elements left uninitialized, as in a plain struct; homogeneous_matrix<T>{} is zero.
    homogeneous_matrix() = default;
    /// The matrix with the given rows: homogeneous_matrix<T>{{{m00, m01, m02, m03}, {...}, ...}}.
    [[gnu::always_inline]] constexpr homogeneous_matrix(const T (&rows)[4][4]) noexcept
        : elements{{rows[0][0], rows[0][1], rows[0][2], rows[0][3]},
                   {rows[1][0], rows[1][1], rows[1][2], rows[1][3]},
                   {rows[2][0], rows[2][1], rows[2][2], rows[2][3]},
                   {rows[3][0], rows[3][1], rows[3][2], rows[3][3]}} {}
    /// Conversion from another precision, element by element.
    template <class U>
    [[gnu::always_inline]] constexpr explicit homogeneous_matrix(
        const homogeneous_matrix<U>& m) noexcept
        : elements{} {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) elements[i][j] = static_cast<T>(m.elements[i][j]);
    }

    /// Element at (row, col), both in [0, 4).
    [[nodiscard]] [[gnu::always_inline]] constexpr T& operator()(int row, int col) noexcept {
        QUAT_ASSERT(row >= 0 && row < 4 && col >= 0 && col < 4, "matrix index out of range");
        return elements[row][col];
    }
    /// Element at (row, col), read-only.
    [[nodiscard]] [[gnu::always_inline]] constexpr const T& operator()(int row,
                                                                       int col) const noexcept {
        QUAT_ASSERT(row >= 0 && row < 4 && col >= 0 && col < 4, "matrix index out of range");
        return elements[row][col];
    }

    /// The motion that moves nothing.
    [[nodiscard]] [[gnu::always_inline]] static constexpr homogeneous_matrix identity() noexcept {
        return {{{T(1), T(0), T(0), T(0)},
                 {T(0), T(1), T(0), T(0)},
                 {T(0), T(0), T(1), T(0)},
                 {T(0), T(0), T(0), T(1)}}};
    }
    /// The pure translation x -> x + t: to_homogeneous(rotation_matrix<T>::identity(), t).
    [[nodiscard]] [[gnu::always_inline]] static constexpr homogeneous_matrix from_translation(
        const vec3<T>& t) noexcept {
        return to_homogeneous(rotation_matrix<T>::identity(), t);
    }
};

#include "../detail/isa_namespace.inc"
/// Matrix product: as motions, a * b applies b first, then a. 64 multiplications, 48 additions.
template <class T>
[[nodiscard]] constexpr homogeneous_matrix<T> operator*(const homogeneous_matrix<T>& a,
                                                        const homogeneous_matrix<T>& b) noexcept {
    // Row i of the product is a(i, 0) b's row 0 + ... + a(i, 3) b's row 3: written over whole rows,
    // the four columns are independent lanes that compilers vectorize: a chain of 1024 products
    // took 5.1 ns per product against 10.1 one entry at a time (rigid_chain/quat/matrix, g++ 12,
    // -O3, x86-64).
    homogeneous_matrix<T> product{};
    for (int i = 0; i < 4; ++i) {
        T* row = product.elements[i];
        for (int j = 0; j < 4; ++j) row[j] = a.elements[i][0] * b.elements[0][j];
        for (int k = 1; k < 4; ++k)
            for (int j = 0; j < 4; ++j) row[j] += a.elements[i][k] * b.elements[k][j];
    }
    return product;
}

/// a = a * b: as motions, b is applied first, then the old a.
template <class T>
constexpr homogeneous_matrix<T>& operator*=(homogeneous_matrix<T>& a,
                                            const homogeneous_matrix<T>& b) noexcept {
    return a = a * b;
}

/// Exact element-wise equality.
template <class T>
[[nodiscard]] constexpr bool operator==(const homogeneous_matrix<T>& a,
                                        const homogeneous_matrix<T>& b) noexcept {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!(a(i, j) == b(i, j))) return false;
    return true;
}
/// Negation of ==.
template <class T>
[[nodiscard]] constexpr bool operator!=(const homogeneous_matrix<T>& a,
                                        const homogeneous_matrix<T>& b) noexcept {
    return !(a == b);
}

/// The upper left 3x3 block: the rotation of a rigid motion.
template <class T>
[[nodiscard]] constexpr rotation_matrix<T> rotation_block(const homogeneous_matrix<T>& m) noexcept {
    return {
        {{m(0, 0), m(0, 1), m(0, 2)}, {m(1, 0), m(1, 1), m(1, 2)}, {m(2, 0), m(2, 1), m(2, 2)}}};
}

/// The first three entries of the last column: the translation of a rigid motion.
template <class T>
[[nodiscard]] constexpr vec3<T> translation_of(const homogeneous_matrix<T>& m) noexcept {
    return {m(0, 3), m(1, 3), m(2, 3)};
}

/// M (p, 1) without its last coordinate: R p + t. Precondition: last row (0, 0, 0, 1), which is
/// not read.
template <class T>
[[nodiscard]] constexpr vec3<T> transform(const homogeneous_matrix<T>& m,
                                          const vec3<T>& p) noexcept {
    return rotate(rotation_block(m), p) + translation_of(m);
}

/// M (v, 0) without its last coordinate: R v, a direction turned and not translated.
template <class T>
[[nodiscard]] constexpr vec3<T> transform_vector(const homogeneous_matrix<T>& m,
                                                 const vec3<T>& v) noexcept {
    return rotate(rotation_block(m), v);
}

/// h * p, as GLM's mat4 * vec4(p, 1) and Eigen's Isometry3 * Vector3 read: the same as
/// transform(h, p). A point transform: p is rotated, then translated (transform_vector turns a
/// direction without translating).
template <class T>
[[nodiscard]] constexpr vec3<T> operator*(const homogeneous_matrix<T>& h,
                                          const vec3<T>& p) noexcept {
    return transform(h, p);
}

/// The rigid motion x -> R x + t as a 4x4 matrix: rotation block r, last column translation,
/// last row (0, 0, 0, 1), each copied exactly. Precondition: r is a rotation (not checked; any
/// 3x3 matrix is copied as given).
template <class T>
[[nodiscard]] constexpr homogeneous_matrix<T> to_homogeneous(const rotation_matrix<T>& rotation,
                                                             const vec3<T>& translation) noexcept {
    const rotation_matrix<T>& r = rotation;
    const vec3<T>& t = translation;
    return {{{r(0, 0), r(0, 1), r(0, 2), t.x},
             {r(1, 0), r(1, 1), r(1, 2), t.y},
             {r(2, 0), r(2, 1), r(2, 2), t.z},
             {T(0), T(0), T(0), T(1)}}};
}

/// The pure rotation r as a 4x4 matrix: to_homogeneous(r, {0, 0, 0}).
template <class T>
[[nodiscard]] constexpr homogeneous_matrix<T> to_homogeneous(
    const rotation_matrix<T>& rotation) noexcept {
    return to_homogeneous(rotation, vec3<T>{T(0), T(0), T(0)});
}

/// The rigid motion x -> R x + t, R the rotation of unit q: to_homogeneous(to_matrix(q), t), with
/// the translation exact (to_homogeneous(to_dual_quaternion(q, t)) rounds it). Precondition: unit
/// q (checked in debug builds by to_matrix).
template <class T>
[[nodiscard]] constexpr homogeneous_matrix<T> to_homogeneous(const quaternion<T>& rotation,
                                                             const vec3<T>& translation) noexcept {
    return to_homogeneous(to_matrix(rotation), translation);
}

/// The pure rotation by unit q as a 4x4 matrix: to_homogeneous(to_matrix(q), {0, 0, 0}).
template <class T>
[[nodiscard]] constexpr homogeneous_matrix<T> to_homogeneous(
    const quaternion<T>& rotation) noexcept {
    return to_homogeneous(to_matrix(rotation), vec3<T>{T(0), T(0), T(0)});
}

/// The 4x4 matrix of the unit dual quaternion dq: rotation block to_matrix(dq.real), last column
/// translation_of(dq), last row (0, 0, 0, 1). Precondition: unit dq (normalize gives one).
template <class T>
[[nodiscard]] constexpr homogeneous_matrix<T> to_homogeneous(
    const dual_quaternion<T>& dq) noexcept {
    return to_homogeneous(to_matrix(dq.real), translation_of(dq));
}

namespace detail {

/// The debug check of a rigid motion: rotation block within 1/4096 of orthogonal with a positive
/// determinant, last row within 1/4096 of (0, 0, 0, 1). NaN and infinities pass and propagate; a
/// user scalar is not checked.
template <class T>
[[nodiscard]] constexpr bool is_near_rigid(const homogeneous_matrix<T>& m) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        const rotation_matrix<T> r = rotation_block(m);
        const T error = orthogonality_error(r);
        if (!is_finite(error)) return true;
        const T tolerance = T(1) / T(4096);
        return error <= tolerance && determinant(r) > T(0) && abs(m(3, 0)) <= tolerance &&
               abs(m(3, 1)) <= tolerance && abs(m(3, 2)) <= tolerance &&
               abs(m(3, 3) - T(1)) <= tolerance;
    } else {
        return true;
    }
}

}  // namespace detail

/// The inverse x -> R^T (x - t) of the rigid motion m = [R t; 0 1]: rotation block R^T, translation
/// -R^T t, exact transposition and 9 multiplications. Precondition: m is rigid (checked in debug
/// builds, as to_dual_quaternion checks it). For any other matrix the same formula is applied to
/// its
/// blocks, the last row read as (0, 0, 0, 1): scale, shear or a projective row give a matrix that
/// is
/// not m's inverse (invert those with a general 4x4 inverse). NaN propagates.
template <class T>
[[nodiscard]] constexpr homogeneous_matrix<T> inverse(const homogeneous_matrix<T>& m) noexcept {
    QUAT_ASSERT(detail::is_near_rigid(m), "quat::inverse: the matrix is not a rigid motion");
    const rotation_matrix<T> r_transposed = transpose(rotation_block(m));
    return to_homogeneous(r_transposed, -rotate(r_transposed, translation_of(m)));
}

/// The unit dual quaternion (real part w >= 0) of the rigid motion m, exact at half turns (through
/// to_quaternion). Precondition: m is rigid (checked in debug builds); try_to_dual_quaternion
/// checks untrusted matrices.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> to_dual_quaternion(
    const homogeneous_matrix<T>& m) noexcept {
    QUAT_ASSERT(detail::is_near_rigid(m),
                "quat::to_dual_quaternion: the matrix is not a rigid motion");
    return to_dual_quaternion(to_quaternion(rotation_block(m)), translation_of(m));
}

/// to_dual_quaternion(m), or std::nullopt when m is not a rigid motion: an element not finite, a
/// last row off (0, 0, 0, 1) by more than tolerance, or a rotation block that try_to_quaternion
/// rejects (a reflection, or orthogonality_error above tolerance).
template <class T>
[[nodiscard]] constexpr std::optional<dual_quaternion<T>> try_to_dual_quaternion(
    const homogeneous_matrix<T>& m,
    detail::type_identity_t<T> tolerance = default_orthogonality_tolerance<T>()) noexcept {
    for (int j = 0; j < 4; ++j) {
        if (!detail::is_finite(m(0, j)) || !detail::is_finite(m(1, j)) ||
            !detail::is_finite(m(2, j)))
            return std::nullopt;
        if (!(detail::abs(m(3, j) - (j == 3 ? T(1) : T(0))) <= tolerance)) return std::nullopt;
    }
    const std::optional<quaternion<T>> rotation = try_to_quaternion(rotation_block(m), tolerance);
    if (!rotation) return std::nullopt;
    return to_dual_quaternion(*rotation, translation_of(m));
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_RIGID_HOMOGENEOUS_MATRIX_HPP_INCLUDED
