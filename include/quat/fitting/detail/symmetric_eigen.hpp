// Eigenvalues and eigenvectors of a symmetric N x N matrix: the one solver behind nearest_rotation,
// align_vectors and mean, whose answers are eigenvectors of a 4x4 read as quaternions, and
// hand_eye's 8x8; and the symmetric positive definite 3x3 solve of align_vectors' Newton steps.
#ifndef QUAT_FITTING_DETAIL_SYMMETRIC_EIGEN_HPP_INCLUDED
#define QUAT_FITTING_DETAIL_SYMMETRIC_EIGEN_HPP_INCLUDED

#include <cstddef>
#include <limits>

#include "../../detail/math.hpp"
#include "../../detail/summation.hpp"
#include "../../quaternion.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

// Eigenvalues in descending order (equal ones in the order of their diagonal positions after the
// sweeps), each with its unit eigenvector: vectors[n] belongs to values[n].
template <std::size_t N, class T>
struct symmetric_eigen_n {
    T values[N];
    T vectors[N][N];
};

// Cyclic Jacobi rotations (Golub & Van Loan, Matrix Computations, 8.5): unconditionally
// convergent, quadratically at the end, a handful of sweeps for N up to 8; each eigenvalue comes
// out within a few eps of the matrix's norm. Expects finite elements of moderate size (callers
// scale so the largest is about 1: the sums of squares below would overflow near sqrt(max)); a
// non-finite element gives NaN values and vectors.
template <std::size_t N, class T>
[[nodiscard]] constexpr symmetric_eigen_n<N, T> jacobi_eigen(const T (&matrix)[N][N]) noexcept {
    symmetric_eigen_n<N, T> result{};
    T k[N][N] = {}, v[N][N] = {};
    for (std::size_t p = 0; p < N; ++p)
        for (std::size_t q = 0; q < N; ++q) {
            if (!detail::is_finite(matrix[p][q])) {
                const T nan = detail::quiet_nan<T>();
                for (std::size_t i = 0; i < N; ++i) {
                    result.values[i] = nan;
                    for (std::size_t j = 0; j < N; ++j) result.vectors[i][j] = nan;
                }
                return result;
            }
            k[p][q] = matrix[p][q];
            v[p][q] = p == q ? T(1) : T(0);
        }
    for (std::size_t sweep = 0; sweep < 32; ++sweep) {
        T off = T(0), total = T(0);
        for (std::size_t p = 0; p < N; ++p)
            for (std::size_t q = 0; q < N; ++q) (p == q ? total : off) += k[p][q] * k[p][q];
        if (!(off > detail::epsilon<T>() * detail::epsilon<T>() * total)) break;
        for (std::size_t p = 0; p < N - 1; ++p)
            for (std::size_t q = p + 1; q < N; ++q) {
                if (k[p][q] == T(0)) continue;
                // Rotation in the (p, q) plane that zeroes k[p][q]: t = tan of its angle, the
                // smaller root.
                const T theta = (k[q][q] - k[p][p]) / (T(2) * k[p][q]);
                const T t = (theta < T(0) ? T(-1) : T(1)) /
                            (detail::abs(theta) + detail::sqrt(theta * theta + T(1)));
                const T c = T(1) / detail::sqrt(t * t + T(1)), s = t * c;
                for (std::size_t r = 0; r < N; ++r) {  // k <- k J
                    const T kp = k[r][p], kq = k[r][q];
                    k[r][p] = c * kp - s * kq;
                    k[r][q] = s * kp + c * kq;
                }
                for (std::size_t r = 0; r < N; ++r) {  // k <- J^T k
                    const T kp = k[p][r], kq = k[q][r];
                    k[p][r] = c * kp - s * kq;
                    k[q][r] = s * kp + c * kq;
                }
                for (std::size_t r = 0; r < N; ++r) {  // v <- v J: columns are the eigenvectors
                    const T vp = v[r][p], vq = v[r][q];
                    v[r][p] = c * vp - s * vq;
                    v[r][q] = s * vp + c * vq;
                }
            }
    }
    // Insertion sort, descending; a strict comparison keeps equal eigenvalues in diagonal order.
    std::size_t order[N] = {};
    for (std::size_t i = 0; i < N; ++i) order[i] = i;
    for (std::size_t i = 1; i < N; ++i)
        for (std::size_t j = i; j > 0 && k[order[j]][order[j]] > k[order[j - 1]][order[j - 1]];
             --j) {
            const std::size_t swapped = order[j];
            order[j] = order[j - 1];
            order[j - 1] = swapped;
        }
    for (std::size_t n = 0; n < N; ++n) {
        const std::size_t column = order[n];
        result.values[n] = k[column][column];
        for (std::size_t r = 0; r < N; ++r) result.vectors[n][r] = v[r][column];
    }
    return result;
}

// Eigenvalues in descending order, each with its unit eigenvector read as a quaternion
// (components w, x, y, z are rows 0 to 3 of the matrix).
template <class T>
struct symmetric_eigen4 {
    T values[4];
    quaternion<T> vectors[4];
};

// jacobi_eigen of a 4x4, the eigenvectors as quaternions.
template <class T>
[[nodiscard]] constexpr symmetric_eigen4<T> symmetric_eigen(const T (&matrix)[4][4]) noexcept {
    const symmetric_eigen_n<4, T> e = jacobi_eigen<4>(matrix);
    symmetric_eigen4<T> result{};
    for (std::size_t n = 0; n < 4; ++n) {
        result.values[n] = e.values[n];
        result.vectors[n] = {e.vectors[n][0], e.vectors[n][1], e.vectors[n][2], e.vectors[n][3]};
    }
    return result;
}

// Solves h x = g for a symmetric positive definite 3x3 h: LDL^T elimination, each step on the
// largest remaining diagonal element (symmetric complete pivoting, stable for positive definite
// matrices however graded: Higham, Accuracy and Stability of Numerical Algorithms, 2002, 10.3).
// False, x untouched, when a pivot is not positive (h not positive definite, or NaN).
template <class T>
[[nodiscard]] constexpr bool solve_positive_definite3(const T (&h)[3][3], const T (&g)[3],
                                                      T (&x)[3]) noexcept {
    T m[3][3] = {}, r[3] = {};
    int order[3] = {0, 1, 2};
    for (int i = 0; i < 3; ++i) {
        r[i] = g[i];
        for (int j = 0; j < 3; ++j) m[i][j] = h[i][j];
    }
    for (int k = 0; k < 3; ++k) {
        int p = k;
        for (int i = k + 1; i < 3; ++i)
            if (m[i][i] > m[p][p]) p = i;
        if (p != k) {  // swap row and column k with p
            for (int j = 0; j < 3; ++j) {
                const T row = m[k][j];
                m[k][j] = m[p][j];
                m[p][j] = row;
            }
            for (int i = 0; i < 3; ++i) {
                const T column = m[i][k];
                m[i][k] = m[i][p];
                m[i][p] = column;
            }
            const T value = r[k];
            r[k] = r[p];
            r[p] = value;
            const int index = order[k];
            order[k] = order[p];
            order[p] = index;
        }
        if (!(m[k][k] > T(0)) || !detail::is_finite(m[k][k])) return false;
        for (int i = k + 1; i < 3; ++i) {
            const T l = m[i][k] / m[k][k];
            for (int j = k + 1; j < 3; ++j) m[i][j] -= l * m[k][j];
            r[i] -= l * r[k];
        }
    }
    T y[3] = {};
    for (int k = 2; k >= 0; --k) {
        T value = r[k];
        for (int j = k + 1; j < 3; ++j) value -= m[k][j] * y[j];
        y[k] = value / m[k][k];
    }
    for (int k = 0; k < 3; ++k) x[order[k]] = y[k];
    return true;
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_FITTING_DETAIL_SYMMETRIC_EIGEN_HPP_INCLUDED
