// The rotation nearest to an arbitrary 3x3 matrix (orthonormalization).
#ifndef QUAT_NEAREST_ROTATION_HPP_INCLUDED
#define QUAT_NEAREST_ROTATION_HPP_INCLUDED

#include <optional>

#include "conversions.hpp"
#include "detail/math.hpp"
#include "quaternion.hpp"
#include "rotation_matrix.hpp"

namespace quat {

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
// eigenvalue. Found with cyclic Jacobi rotations (Golub & Van Loan, Matrix Computations, 8.5):
// unconditionally convergent, quadratically at the end, a handful of sweeps for a 4x4.
template <class T>
[[nodiscard]] constexpr horn_solution<T> solve_horn(const rotation_matrix<T>& input) noexcept {
    const T nan = std::numeric_limits<T>::quiet_NaN();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (!detail::is_finite(input(i, j))) return {{nan, nan, nan, nan}, nan};
    T scale = T(0);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) scale = detail::max(scale, detail::abs(input(i, j)));
    if (!(scale > T(0))) scale = T(1);  // zero matrix: every rotation is equally near
    rotation_matrix<T> m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = input(i, j) / scale;

    T k[4][4] = {
        {m(0, 0) + m(1, 1) + m(2, 2), m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1)},
        {m(2, 1) - m(1, 2), m(0, 0) - m(1, 1) - m(2, 2), m(0, 1) + m(1, 0), m(0, 2) + m(2, 0)},
        {m(0, 2) - m(2, 0), m(0, 1) + m(1, 0), m(1, 1) - m(0, 0) - m(2, 2), m(1, 2) + m(2, 1)},
        {m(1, 0) - m(0, 1), m(0, 2) + m(2, 0), m(1, 2) + m(2, 1), m(2, 2) - m(0, 0) - m(1, 1)}};
    T v[4][4] = {{T(1), T(0), T(0), T(0)},
                 {T(0), T(1), T(0), T(0)},
                 {T(0), T(0), T(1), T(0)},
                 {T(0), T(0), T(0), T(1)}};
    for (int sweep = 0; sweep < 32; ++sweep) {
        T off = T(0), total = T(0);
        for (int p = 0; p < 4; ++p)
            for (int q = 0; q < 4; ++q) (p == q ? total : off) += k[p][q] * k[p][q];
        if (!(off > std::numeric_limits<T>::epsilon() * std::numeric_limits<T>::epsilon() * total))
            break;
        for (int p = 0; p < 3; ++p)
            for (int q = p + 1; q < 4; ++q) {
                if (k[p][q] == T(0)) continue;
                // Rotation in the (p, q) plane that zeroes k[p][q]: t = tan of its angle, the smaller root.
                const T theta = (k[q][q] - k[p][p]) / (T(2) * k[p][q]);
                const T t = (theta < T(0) ? T(-1) : T(1)) /
                            (detail::abs(theta) + detail::sqrt(theta * theta + T(1)));
                const T c = T(1) / detail::sqrt(t * t + T(1)), s = t * c;
                for (int r = 0; r < 4; ++r) {  // k <- k J
                    const T kp = k[r][p], kq = k[r][q];
                    k[r][p] = c * kp - s * kq;
                    k[r][q] = s * kp + c * kq;
                }
                for (int r = 0; r < 4; ++r) {  // k <- J^T k
                    const T kp = k[p][r], kq = k[q][r];
                    k[p][r] = c * kp - s * kq;
                    k[q][r] = s * kp + c * kq;
                }
                for (int r = 0; r < 4; ++r) {  // v <- v J: columns are the eigenvectors
                    const T vp = v[r][p], vq = v[r][q];
                    v[r][p] = c * vp - s * vq;
                    v[r][q] = s * vp + c * vq;
                }
            }
    }
    int best = 0;
    for (int n = 1; n < 4; ++n)
        if (k[n][n] > k[best][best]) best = n;
    T second = -std::numeric_limits<T>::infinity();
    for (int n = 0; n < 4; ++n)
        if (n != best && k[n][n] > second) second = k[n][n];
    const quaternion<T> q{v[0][best], v[1][best], v[2][best], v[3][best]};
    return {normalize(q.w < T(0) ? -q : q), k[best][best] - second};
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
    if (!(result.eigenvalue_gap > detail::sqrt(std::numeric_limits<T>::epsilon())))
        return std::nullopt;
    return to_matrix(result.rotation);
}

}  // namespace quat

#endif  // QUAT_NEAREST_ROTATION_HPP_INCLUDED
