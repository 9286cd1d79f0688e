// Long double reference for rigid motions: 4x4 matrices built from a dual quaternion's components
// by the textbook formulas, their products, and the matrix exponential and logarithm by series, so
// sclerp and friends are checked against the matrix form a exp(t log(a^-1 b)) with no quat code
// in the path.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

#include <quat/rigid/dual_quaternion.hpp>
#include <quat/rigid/homogeneous_matrix.hpp>
#include <quat/rigid/sclerp.hpp>

namespace quat::test {

struct matrix4 {
    long double entries[4][4];
    long double* operator[](int row) { return entries[row]; }
    const long double* operator[](int row) const { return entries[row]; }
};

inline matrix4 identity4() {
    matrix4 m{};
    for (int i = 0; i < 4; ++i) m[i][i] = 1;
    return m;
}

inline matrix4 operator*(const matrix4& a, const matrix4& b) {
    matrix4 p{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) p[i][j] += a[i][k] * b[k][j];
    return p;
}

inline matrix4 operator+(matrix4 a, const matrix4& b) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) a[i][j] += b[i][j];
    return a;
}

inline matrix4 operator*(long double s, matrix4 a) {
    for (auto& row : a.entries)
        for (long double& x : row) x *= s;
    return a;
}

/// Largest absolute entry.
inline long double max_abs(const matrix4& a) {
    long double m = 0;
    for (const auto& row : a.entries)
        for (long double x : row) m = std::max(m, std::fabs(x));
    return m;
}

inline long double max_difference(const matrix4& a, const matrix4& b) {
    return max_abs(a + (-1.0L) * b);
}

/// The rigid motion of dq, whose real part is only approximately unit: R from the normalized real
/// part (q v q* / |q|^2 written out), t = 2 dual real* / |real|^2.
template <class T>
matrix4 reference_matrix(const dual_quaternion<T>& dq) {
    const long double w = dq.real.w, x = dq.real.x, y = dq.real.y, z = dq.real.z;
    const long double dw = dq.dual.w, dx = dq.dual.x, dy = dq.dual.y, dz = dq.dual.z;
    const long double n = w * w + x * x + y * y + z * z;
    matrix4 m{};
    m[0][0] = (w * w + x * x - y * y - z * z) / n;
    m[0][1] = 2 * (x * y - w * z) / n;
    m[0][2] = 2 * (x * z + w * y) / n;
    m[1][0] = 2 * (x * y + w * z) / n;
    m[1][1] = (w * w - x * x + y * y - z * z) / n;
    m[1][2] = 2 * (y * z - w * x) / n;
    m[2][0] = 2 * (x * z - w * y) / n;
    m[2][1] = 2 * (y * z + w * x) / n;
    m[2][2] = (w * w - x * x - y * y + z * z) / n;
    // Vector part of dual * conjugate(real), doubled.
    m[0][3] = 2 * (-dw * x + dx * w - dy * z + dz * y) / n;
    m[1][3] = 2 * (-dw * y + dx * z + dy * w - dz * x) / n;
    m[2][3] = 2 * (-dw * z - dx * y + dy * x + dz * w) / n;
    m[3][3] = 1;
    return m;
}

template <class T>
matrix4 reference_matrix(const homogeneous_matrix<T>& h) {
    matrix4 m{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) m[i][j] = h(i, j);
    return m;
}

/// Inverse by Gauss-Jordan elimination with partial pivoting.
inline matrix4 inverse4(matrix4 a) {
    matrix4 inv = identity4();
    for (int c = 0; c < 4; ++c) {
        int pivot = c;
        for (int r = c + 1; r < 4; ++r)
            if (std::fabs(a[r][c]) > std::fabs(a[pivot][c])) pivot = r;
        std::swap(a.entries[c], a.entries[pivot]);
        std::swap(inv.entries[c], inv.entries[pivot]);
        const long double p = a[c][c];
        for (int j = 0; j < 4; ++j) {
            a[c][j] /= p;
            inv[c][j] /= p;
        }
        for (int r = 0; r < 4; ++r) {
            if (r == c) continue;
            const long double f = a[r][c];
            for (int j = 0; j < 4; ++j) {
                a[r][j] -= f * a[c][j];
                inv[r][j] -= f * inv[c][j];
            }
        }
    }
    return inv;
}

/// exp(X) by scaling and squaring: Taylor series of X / 2^s with |X / 2^s| <= 1/4, squared s times.
inline matrix4 expm(const matrix4& x) {
    int s = 0;
    long double scale = 1;
    while (max_abs(x) * scale * 4 > 0.25L) {
        scale /= 2;
        ++s;
    }
    const matrix4 y = scale * x;
    matrix4 sum = identity4(), term = identity4();
    for (int k = 1; k < 40; ++k) {
        term = (1.0L / k) * (term * y);
        sum = sum + term;
    }
    for (int i = 0; i < s; ++i) sum = sum * sum;
    return sum;
}

/// Principal square root by the Denman-Beavers iteration.
inline matrix4 sqrtm(const matrix4& a) {
    matrix4 y = a, z = identity4();
    for (int k = 0; k < 100; ++k) {
        const matrix4 y_next = 0.5L * (y + inverse4(z)), z_next = 0.5L * (z + inverse4(y));
        const long double change = max_difference(y_next, y);
        y = y_next;
        z = z_next;
        if (change < 1e-30L) break;
    }
    return y;
}

/// Principal logarithm by inverse scaling and squaring: square roots until |A - I| <= 1/8, then
/// the series of log(I + X), times 2^k.
inline matrix4 logm(matrix4 a) {
    long double factor = 1;
    while (max_difference(a, identity4()) > 0.125L) {
        a = sqrtm(a);
        factor *= 2;
    }
    const matrix4 x = a + (-1.0L) * identity4();
    matrix4 sum{}, power = identity4();
    for (int n = 1; n < 60; ++n) {
        power = power * x;
        sum = sum + ((n % 2 == 1 ? 1.0L : -1.0L) / n) * power;
    }
    return factor * sum;
}

/// a exp(t log(a^-1 b)): the screw motion from a to b, in long double.
inline matrix4 reference_sclerp(const matrix4& a, const matrix4& b, long double t) {
    return a * expm(t * logm(inverse4(a) * b));
}

/// A difference and the size it is measured against.
struct scaled_difference {
    long double difference, scale;
    [[nodiscard]] long double relative() const { return difference / scale; }
};

/// The largest entry difference of quat::sclerp(a, b, t) from the matrix form, and the sizes
/// involved: the largest entry of a, b and the result, at least 1. (The computation passes through
/// a's and b's translations even where the path comes near the origin.)
template <class T>
scaled_difference sclerp_difference(const dual_quaternion<T>& a, const dual_quaternion<T>& b, T t) {
    const matrix4 ma = reference_matrix(a), mb = reference_matrix(b);
    const matrix4 reference = reference_sclerp(ma, mb, t);
    return {max_difference(reference_matrix(sclerp(a, b, t)), reference),
            std::max({1.0L, max_abs(reference), max_abs(ma), max_abs(mb)})};
}

}  // namespace quat::test
