// The rotation nearest to an arbitrary 3x3 matrix (orthonormalization).
#ifndef QUAT_FITTING_NEAREST_ROTATION_HPP_INCLUDED
#define QUAT_FITTING_NEAREST_ROTATION_HPP_INCLUDED

#include <limits>
#include <optional>

#include "../conversions.hpp"
#include "../detail/math.hpp"
#include "../quaternion.hpp"
#include "../rotation_matrix.hpp"
#include "detail/symmetric_eigen.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
namespace detail {

// Unit quaternion (w >= 0) of the rotation R maximizing trace(R^T m), i.e. minimizing the Frobenius
// norm |R - m|, and the gap between the two largest eigenvalues of Horn's matrix (0: not unique),
// or a lower bound of that gap where it was not computed.
template <class T>
struct horn_solution {
    quaternion<T> rotation;
    T eigenvalue_gap;
};

// Above this relative eigen-gap the best rotation is well separated from the others: FOAM below
// finds it, and its eigenvector is accurate without a polish (align_vectors' Newton steps).
template <class T>
[[nodiscard]] constexpr T separated_gap() noexcept {
    return T(1) / T(4);
}

// m / max |m(i, j)| (m itself for the zero matrix): the matrices below are then of size about 1.
template <class T>
[[nodiscard]] constexpr rotation_matrix<T> unit_scaled(const rotation_matrix<T>& m) noexcept {
    T scale = T(0);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) scale = detail::max(scale, detail::abs(m(i, j)));
    if (!(scale > T(0))) return m;
    rotation_matrix<T> scaled{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) scaled(i, j) = m(i, j) / scale;
    return scaled;
}

// trace(R(q)^T m) = q^T K q for the symmetric 4x4 K below (Horn, J. Opt. Soc. Am. A 4(4), 1987;
// Bar-Itzhack, J. Guidance 23(6), 2000), so the best q is the eigenvector of K's largest
// eigenvalue. m is unit_scaled, so K's eigenvalues are relative to its largest element; a
// non-finite element gives NaN.
template <class T>
[[nodiscard]] constexpr symmetric_eigen4<T> horn_eigen(const rotation_matrix<T>& m) noexcept {
    const T k[4][4] = {
        {m(0, 0) + m(1, 1) + m(2, 2), m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1)},
        {m(2, 1) - m(1, 2), m(0, 0) - m(1, 1) - m(2, 2), m(0, 1) + m(1, 0), m(0, 2) + m(2, 0)},
        {m(0, 2) - m(2, 0), m(0, 1) + m(1, 0), m(1, 1) - m(0, 0) - m(2, 2), m(1, 2) + m(2, 1)},
        {m(1, 0) - m(0, 1), m(0, 2) + m(2, 0), m(1, 2) + m(2, 1), m(2, 2) - m(0, 0) - m(1, 1)}};
    return detail::symmetric_eigen(k);
}

// The best rotation without an eigen-solve, after Markley's FOAM ("Attitude determination using
// vector observations: a fast optimal matrix algorithm", J. Astronaut. Sci. 41(2), 1993). For m's
// singular values s0 >= s1 >= |s2| (s2 < 0 when det m < 0) K's largest eigenvalue is
// lambda = s0 + s1 + s2, the largest root of (l^2 - |m|^2)^2 - 8 l det m - 4 |adj m|^2; Newton's
// method from sqrt(3) |m| >= lambda descends to it monotonically (all four roots are real). Then
// R = ((kappa + |m|^2) m + lambda cof(m) - m m^T m) / zeta, kappa = (lambda^2 - |m|^2) / 2,
// zeta = lambda kappa - det m = (s0 + s1)(s1 + s2)(s2 + s0). The eigen-gap 2 (s1 + s2) is at least
// zeta / (2 |m|^2), the returned bound: only where that is separated_gap() or more is the rotation
// used as it is (K's eigenvector would be as accurate: FOAM measures 3.6 eps at worst, Jacobi's
// 10.7, over 18,000 noisy point sets); below, zeta's cancellation spoils R by about eps / bound^2,
// which Newton steps can still remove down to `floor` (registration's small sets). Below `floor`:
// the identity and bound 0. m is unit_scaled.
template <class T>
[[nodiscard]] constexpr horn_solution<T> foam(const rotation_matrix<T>& m,
                                              T floor = separated_gap<T>()) noexcept {
    // cof(m), row by row: the cross products of the other two rows.
    const rotation_matrix<T> cofactor = rotation_matrix<T>::from_rows(
        cross(row(m, 1), row(m, 2)), cross(row(m, 2), row(m, 0)), cross(row(m, 0), row(m, 1)));
    T square = T(0), adjugate_square = T(0);  // |m|^2 and |adj m|^2
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            square += m(i, j) * m(i, j);
            adjugate_square += cofactor(i, j) * cofactor(i, j);
        }
    const T det = determinant(m);
    T lambda = detail::sqrt(T(3) * square);
    for (int step = 0; step < 32; ++step) {
        const T u = lambda * lambda - square;
        const T value = u * u - T(8) * lambda * det - T(4) * adjugate_square;
        if (!(value > T(0))) break;  // at the root to rounding (or NaN)
        const T change = value / (T(4) * lambda * u - T(8) * det);
        if (!(change > T(0))) break;  // a slope rounded to 0 or below, near a double root
        lambda -= change;
        if (!(change > T(4) * detail::epsilon<T>() * lambda)) break;
    }
    const T kappa = (lambda * lambda - square) / T(2);
    const T zeta = lambda * kappa - det;
    const T bound = zeta / (T(2) * square);
    if (!(bound >= floor)) return {quaternion<T>::identity(), T(0)};
    const rotation_matrix<T> cubic = m * transpose(m) * m;
    rotation_matrix<T> r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r(i, j) = ((kappa + square) * m(i, j) + lambda * cofactor(i, j) - cubic(i, j)) / zeta;
    return {to_quaternion(r), bound};
}

// FOAM where the answer is well separated, Horn's eigenvector otherwise. m is unit_scaled.
template <class T>
[[nodiscard]] constexpr horn_solution<T> solve_horn(const rotation_matrix<T>& m) noexcept {
    const horn_solution<T> separated = detail::foam(m);
    if (separated.eigenvalue_gap >= separated_gap<T>()) return separated;
    const symmetric_eigen4<T> eigen = detail::horn_eigen(m);
    const quaternion<T>& q = eigen.vectors[0];
    return {normalize(q.w < T(0) ? -q : q), eigen.values[0] - eigen.values[1]};
}

}  // namespace detail

/// The rotation matrix nearest to m in the Frobenius norm, for any finite 3x3 m. For det(m) > 0 it
/// is the orthogonal polar factor of m. For det(m) <= 0 the polar factor is a reflection; the
/// result is still the nearest proper rotation (trace(R^T m) maximal). When that rotation is not
/// unique (e.g. m = -I, or rank(m) < 2) one of the nearest rotations is returned;
/// try_nearest_rotation reports it. Non-finite m gives NaN elements.
template <class T>
[[nodiscard]] constexpr rotation_matrix<T> nearest_rotation(const rotation_matrix<T>& m) noexcept {
    return to_matrix(detail::solve_horn(detail::unit_scaled(m)).rotation);
}

/// nearest_rotation(m), or std::nullopt when m has a non-finite element or the nearest rotation is
/// not unique (the top two eigenvalues of Horn's matrix agree to within sqrt(epsilon) of |m|).
template <class T>
[[nodiscard]] constexpr std::optional<rotation_matrix<T>> try_nearest_rotation(
    const rotation_matrix<T>& m) noexcept {
    const detail::horn_solution<T> result = detail::solve_horn(detail::unit_scaled(m));
    if (!(result.eigenvalue_gap > detail::sqrt(detail::epsilon<T>()))) return std::nullopt;
    return to_matrix(result.rotation);
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_FITTING_NEAREST_ROTATION_HPP_INCLUDED
