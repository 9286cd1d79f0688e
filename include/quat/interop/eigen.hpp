// Opt-in conversions between quat and Eigen (not included by quat.hpp; needs Eigen's headers):
// quaternions, 3x3 and 4x4 matrices (Eigen::Transform in), vectors, and matrix<T, R, C> (Jacobians,
// covariances).
// Eigen::Quaternion is Hamilton with q v q* like quat, so values carry over unchanged; only the
// layout differs (coeffs() is x, y, z, w; the constructor takes w, x, y, z).
#ifndef QUAT_INTEROP_EIGEN_HPP_INCLUDED
#define QUAT_INTEROP_EIGEN_HPP_INCLUDED

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "../matrix.hpp"
#include "../quaternion.hpp"
#include "../rigid/homogeneous_matrix.hpp"
#include "../rotation_matrix.hpp"
#include "../vec3.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
/// The same quaternion as Eigen::Quaternion (Eigen's constructor order is w, x, y, z).
template <class T>
[[nodiscard]] Eigen::Quaternion<T> to_eigen(const quaternion<T>& q) {
    return Eigen::Quaternion<T>(q.w, q.x, q.y, q.z);
}

/// The same quaternion from an Eigen::Quaternion, read through w(), x(), y(), z().
template <class T, int Options>
[[nodiscard]] quaternion<T> from_eigen(const Eigen::Quaternion<T, Options>& q) {
    return {q.w(), q.x(), q.y(), q.z()};
}

/// The same matrix as Eigen::Matrix3: element (row, col) to (row, col), whatever Eigen's storage
/// order.
template <class T>
[[nodiscard]] Eigen::Matrix<T, 3, 3> to_eigen(const rotation_matrix<T>& m) {
    Eigen::Matrix<T, 3, 3> out;
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) out(row, col) = m(row, col);
    return out;
}

/// The same matrix from a 3x3 Eigen matrix (row- or column-major).
template <class T, int Options, int MaxRows, int MaxCols>
[[nodiscard]] rotation_matrix<T> from_eigen(
    const Eigen::Matrix<T, 3, 3, Options, MaxRows, MaxCols>& m) {
    rotation_matrix<T> out{};
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) out(row, col) = m(row, col);
    return out;
}

/// The same matrix as Eigen::Matrix4: element (row, col) to (row, col). A rigid motion becomes an
/// Eigen::Isometry3 by Eigen::Transform<T, 3, Eigen::Isometry>(to_eigen(m)).
template <class T>
[[nodiscard]] Eigen::Matrix<T, 4, 4> to_eigen(const homogeneous_matrix<T>& m) {
    Eigen::Matrix<T, 4, 4> out;
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) out(row, col) = m(row, col);
    return out;
}

/// The same matrix from a 4x4 Eigen matrix (row- or column-major).
template <class T, int Options, int MaxRows, int MaxCols>
[[nodiscard]] homogeneous_matrix<T> from_eigen(
    const Eigen::Matrix<T, 4, 4, Options, MaxRows, MaxCols>& m) {
    homogeneous_matrix<T> out{};
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) out(row, col) = m(row, col);
    return out;
}

/// The same motion from an Eigen::Transform in 3D (Isometry3, Affine3, Projective3, or an
/// AffineCompact3, whose implicit last row (0, 0, 0, 1) is written out).
template <class T, int Mode, int Options>
[[nodiscard]] homogeneous_matrix<T> from_eigen(const Eigen::Transform<T, 3, Mode, Options>& t) {
    homogeneous_matrix<T> out = homogeneous_matrix<T>::identity();
    const auto& m = t.matrix();
    for (int row = 0; row < static_cast<int>(m.rows()); ++row)
        for (int col = 0; col < 4; ++col) out(row, col) = m(row, col);
    return out;
}

/// The same matrix as Eigen::Matrix<T, R, C>: element (row, col) to (row, col).
template <class T, int R, int C>
[[nodiscard]] Eigen::Matrix<T, R, C> to_eigen(const matrix<T, R, C>& m) {
    Eigen::Matrix<T, R, C> out;
    for (int row = 0; row < R; ++row)
        for (int col = 0; col < C; ++col) out(row, col) = m(row, col);
    return out;
}

/// The same matrix from a fixed-size Eigen matrix (row- or column-major) as matrix<T, R, C>. The
/// 3x3, 4x4 and 3x1 shapes have their own overloads above and below (rotation_matrix,
/// homogeneous_matrix, vec3); a 3x3 Jacobian becomes a matrix3 by to_matrix3(from_eigen(m)).
template <class T, int R, int C, int Options, int MaxRows, int MaxCols>
[[nodiscard]] matrix<T, R, C> from_eigen(
    const Eigen::Matrix<T, R, C, Options, MaxRows, MaxCols>& m) {
    static_assert(R > 0 && C > 0, "quat::from_eigen: a matrix<T, R, C> needs a fixed size");
    matrix<T, R, C> out{};
    for (int row = 0; row < R; ++row)
        for (int col = 0; col < C; ++col) out(row, col) = m(row, col);
    return out;
}

/// The same vector as Eigen::Vector3.
template <class T>
[[nodiscard]] Eigen::Matrix<T, 3, 1> to_eigen(const vec3<T>& v) {
    return Eigen::Matrix<T, 3, 1>(v.x, v.y, v.z);
}

/// The same vector from an Eigen 3-vector.
template <class T, int Options, int MaxRows, int MaxCols>
[[nodiscard]] vec3<T> from_eigen(const Eigen::Matrix<T, 3, 1, Options, MaxRows, MaxCols>& v) {
    return {v.x(), v.y(), v.z()};
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_INTEROP_EIGEN_HPP_INCLUDED
