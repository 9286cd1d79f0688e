// The rotation nearest to an arbitrary 3x3 matrix (orthonormalization).
#ifndef QUAT_NEAREST_ROTATION_HPP_INCLUDED
#define QUAT_NEAREST_ROTATION_HPP_INCLUDED

#include <limits>
#include <optional>

#include "conversions.hpp"
#include "detail/math.hpp"
#include "detail/symmetric_eigen.hpp"
#include "quaternion.hpp"
#include "rotation_matrix.hpp"

namespace quat {

#include "detail/isa_namespace.inc"
namespace detail {

// Unit quaternion (w >= 0) of the rotation R maximizing trace(R^T m), i.e. minimizing the Frobenius
// norm |R - m|, and the gap between the two largest eigenvalues of Horn's matrix (0: not unique).
template <class T>
struct horn_solution {
    quaternion<T> rotation;
    T eigenvalue_gap;
};

// trace(R(q)^T m) = q^T K q for the symmetric 4x4 K below (Horn, J. Opt. Soc. Am. A 4(4), 1987;
// Bar-Itzhack, J. Guidance 23(6), 2000), so the best q is the eigenvector of K's largest
// eigenvalue. K is built from m / max |m(i, j)|, so its eigenvalues are relative to that element;
// a non-finite element gives NaN.
template <class T>
[[nodiscard]] constexpr symmetric_eigen4<T> horn_eigen(const rotation_matrix<T>& input) noexcept {
    T scale = T(0);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) scale = detail::max(scale, detail::abs(input(i, j)));
    if (!(scale > T(0))) scale = T(1);  // zero matrix: every rotation is equally near
    rotation_matrix<T> m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = input(i, j) / scale;
    const T k[4][4] = {
        {m(0, 0) + m(1, 1) + m(2, 2), m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1)},
        {m(2, 1) - m(1, 2), m(0, 0) - m(1, 1) - m(2, 2), m(0, 1) + m(1, 0), m(0, 2) + m(2, 0)},
        {m(0, 2) - m(2, 0), m(0, 1) + m(1, 0), m(1, 1) - m(0, 0) - m(2, 2), m(1, 2) + m(2, 1)},
        {m(1, 0) - m(0, 1), m(0, 2) + m(2, 0), m(1, 2) + m(2, 1), m(2, 2) - m(0, 0) - m(1, 1)}};
    return detail::symmetric_eigen(k);
}

template <class T>
[[nodiscard]] constexpr horn_solution<T> solve_horn(const rotation_matrix<T>& input) noexcept {
    const symmetric_eigen4<T> eigen = detail::horn_eigen(input);
    const quaternion<T>& q = eigen.vectors[0];
    return {normalize(q.w < T(0) ? -q : q), eigen.values[0] - eigen.values[1]};
}

}  // namespace detail

/// The rotation matrix nearest to m in the Frobenius norm, for any finite 3x3 m. For det(m) > 0 it
/// is the orthogonal polar factor of m. For det(m) <= 0 the polar factor is a reflection; the result
/// is still the nearest proper rotation (trace(R^T m) maximal). When that rotation is not unique
/// (e.g. m = -I, or rank(m) < 2) one of the nearest rotations is returned; try_nearest_rotation
/// reports it. Non-finite m gives NaN elements.
template <class T>
[[nodiscard]] constexpr rotation_matrix<T> nearest_rotation(const rotation_matrix<T>& m) noexcept {
    return to_matrix(detail::solve_horn(m).rotation);
}

/// nearest_rotation(m), or std::nullopt when m has a non-finite element or the nearest rotation is
/// not unique (the top two eigenvalues of Horn's matrix agree to within sqrt(epsilon) of |m|).
template <class T>
[[nodiscard]] constexpr std::optional<rotation_matrix<T>> try_nearest_rotation(
    const rotation_matrix<T>& m) noexcept {
    const detail::horn_solution<T> result = detail::solve_horn(m);
    if (!(result.eigenvalue_gap > detail::sqrt(detail::epsilon<T>()))) return std::nullopt;
    return to_matrix(result.rotation);
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_NEAREST_ROTATION_HPP_INCLUDED
